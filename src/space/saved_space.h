#pragma once

// A built free space as plain data for Boost.Serialization (free_space_file.cpp):
// rationals as bytes (sign, numerator, denominator), algebraic angles as indices into a
// table of angles (each distinct angle once, by its double enclosure where that
// isolates it, a rational angle by its t where that is a double) whose functions are
// stored by the double enclosures of their exact coefficients and those coefficients.
// Each kind of part is a few lists of numbers (or a text) for all its items, not a
// record per item: the archive reads a list of numbers as one block, and the loader
// checks each list's length against the bytes left before it sets memory aside.

#include <cstdint>
#include <string>
#include <vector>

#include <boost/serialization/level.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/tracking.hpp>
#include <boost/serialization/vector.hpp>

// clang-format would read `archive & a & b` as declarations.
// clang-format off
namespace freespace::saved {

/// The functions, one after another: the double enclosures of their exact
/// coefficients and, decoded only when first needed, the exact coefficients
/// themselves.
struct Functions {
  std::vector<std::uint32_t> coefficientCounts;  // per function: chart 0's, chart 1's
  std::vector<double> enclosures;                // lower, upper per coefficient, in the same order
  std::vector<std::uint8_t> keyed;               // per function: 1 when it has a key
  std::vector<std::uint32_t> keys;               // nine per keyed function
  std::vector<std::uint64_t> exactEnds;          // per function: where its coefficients end in `exact`
  std::string exact;                             // the coefficients as rationals one after another

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & coefficientCounts & enclosures & keyed & keys & exactEnds & exact;
  }
};

/// The table of angles: each angle's function (-1: a rational angle), chart, place
/// among the function's roots and root's double enclosure, which isolates it; an
/// exact isolating interval only where that is narrower than the doubles can say. A
/// rational angle's t is its enclosure's two ends when it is a double, else its exact
/// interval's.
struct Angles {
  std::vector<std::int32_t> functions;
  std::vector<std::uint8_t> charts;
  std::vector<std::int32_t> indices;
  std::vector<double> enclosures;          // lower, upper per angle
  std::vector<std::uint32_t> exactAngles;  // the angles with an exact interval, increasing
  std::string exactIntervals;              // per such angle: its lower, then upper end, as rationals

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & functions & charts & indices & enclosures & exactAngles & exactIntervals;
  }
};

/// Sets of arcs of angles, one after another.
struct AngleSets {
  std::vector<std::uint8_t> fullCircle;  // per set
  std::vector<std::uint32_t> arcCounts;  // per set
  std::vector<std::uint32_t> arcs;       // from, to, wraps per arc

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & fullCircle & arcCounts & arcs;
  }
};

struct Mesh {
  std::vector<double> vertices;          // x, y, z per vertex
  std::vector<std::uint32_t> triangles;  // three per triangle

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & vertices & triangles;
  }
};

struct Patches {
  std::vector<std::int32_t> contacts;  // per patch: kind, robot, world, side
  AngleSets ranges;
  std::vector<std::uint32_t> segments;            // per patch and end: robotVertex, vertex, edge[0], edge[1]
  std::vector<std::int32_t> lineTags;             // per patch: kind, side, vertices[4]
  std::vector<double> linePoints;                 // per patch: points[4], xyz
  std::vector<std::uint8_t> spiralRobotVertices;  // per patch: one per end
  std::vector<double> spiralPoints;               // per patch and end: points[3], xyz

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & contacts & ranges & segments & lineTags & linePoints & spiralRobotVertices & spiralPoints;
  }
};

struct Curves {
  std::vector<std::uint32_t> patches;  // per curve: first, second
  AngleSets angles;
  std::vector<std::uint8_t> ends;  // per arc and end: endOnOtherLine[2][2], rangeEnd[2]

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & patches & angles & ends;
  }
};

struct Overlaps {
  std::vector<std::uint32_t> patches;    // two per overlap
  std::vector<std::uint32_t> angles;     // one per overlap
  std::vector<std::uint8_t> reachesEnd;  // four per overlap

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & patches & angles & reachesEnd;
  }
};

struct Vertices {
  std::vector<std::uint32_t> patches;   // three per vertex
  std::vector<std::uint32_t> angles;    // one per vertex
  std::vector<std::int32_t> crossings;  // one per vertex

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & patches & angles & crossings;
  }
};

/// Every patch's subdivision, patch after patch and slab after slab.
struct Subdivisions {
  std::vector<std::uint32_t> faceCounts;   // per patch
  std::vector<std::uint32_t> slabCounts;   // per patch
  std::vector<std::uint32_t> slabAngles;   // per slab: from, to, sample
  std::vector<std::uint32_t> curveCounts;  // per slab
  std::vector<std::uint32_t> curves;       // curveCounts[i] per slab
  std::vector<std::uint32_t> faces;        // curveCounts[i] + 1 per slab

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & faceCounts & slabCounts & slabAngles & curveCounts & curves & faces;
  }
};

struct Gluing {
  std::vector<std::uint32_t> glues;      // first patch, face, second patch, face, edge kind, angle
  std::vector<std::uint32_t> unmatched;  // patch, face

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & glues & unmatched;
  }
};

/// The free cell graph (CellGraph::Parts).
struct Graph {
  std::vector<std::uint32_t> criticalAngles;  // angle table indices
  std::vector<std::uint32_t> nodes;           // per node: cell, first interval, last interval, sample angle
  std::vector<double> nodeGeometry;           // per node: point x, y, box low x, low y, high x, high y
  std::vector<std::uint32_t> edges;           // from, to, angle
  std::vector<std::uint32_t> runCounts;       // per piece
  std::vector<std::uint32_t> runs;            // interval, node: runCounts[i] pairs for piece i
  std::vector<std::uint32_t> unboundedRuns;   // interval, node

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & criticalAngles & nodes & nodeGeometry & edges & runCounts & runs & unboundedRuns;
  }
};

struct Space {
  Mesh robot, world;
  bool perturbed = true;
  std::uint64_t seed = 1;
  double relativeSize = 0, absoluteSize = 0;
  double scale = 1;
  Functions functions;
  Angles angles;
  Patches patches;
  Curves curves;
  Overlaps overlaps;
  Vertices vertices;
  Subdivisions subdivisions;
  Gluing acrossCurves, aroundSpirals, acrossHorizontalEdges;
  std::vector<std::uint8_t> shellSides;   // ShellSide per shell
  std::vector<std::int32_t> cellOfShell;  // -1: none
  std::uint32_t cellCount = 0;
  std::string stageNames;  // one per line
  std::vector<double> stageSeconds;
  Graph graph;

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & robot & world & perturbed & seed & relativeSize & absoluteSize & scale & functions & angles & patches &
        curves & overlaps & vertices & subdivisions & acrossCurves & aroundSpirals & acrossHorizontalEdges &
        shellSides & cellOfShell & cellCount & stageNames & stageSeconds & graph;
  }
};

}  // namespace freespace::saved
// clang-format on

// Plain records: no class information or object tracking in the archive (Boost would
// otherwise look each record's type up by name as it reads it).
#define FREESPACE_SAVED_RECORD(T)                                                            \
  BOOST_CLASS_IMPLEMENTATION(freespace::saved::T, boost::serialization::object_serializable) \
  BOOST_CLASS_TRACKING(freespace::saved::T, boost::serialization::track_never)
FREESPACE_SAVED_RECORD(Functions)
FREESPACE_SAVED_RECORD(Angles)
FREESPACE_SAVED_RECORD(AngleSets)
FREESPACE_SAVED_RECORD(Mesh)
FREESPACE_SAVED_RECORD(Patches)
FREESPACE_SAVED_RECORD(Curves)
FREESPACE_SAVED_RECORD(Overlaps)
FREESPACE_SAVED_RECORD(Vertices)
FREESPACE_SAVED_RECORD(Subdivisions)
FREESPACE_SAVED_RECORD(Gluing)
FREESPACE_SAVED_RECORD(Graph)
FREESPACE_SAVED_RECORD(Space)
#undef FREESPACE_SAVED_RECORD
