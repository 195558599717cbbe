#pragma once

// A built free space as plain data for Boost.Serialization (free_space_file.cpp):
// rationals as bytes (sign, numerator, denominator), algebraic angles as indices into a
// table of angles (each distinct angle once, by its double enclosure where that
// isolates it, a rational angle by its t where that is a double) whose functions are
// stored by the double enclosures of their exact coefficients and those coefficients.

#include <cstdint>
#include <string>
#include <vector>

#include <boost/serialization/level.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/tracking.hpp>
#include <boost/serialization/vector.hpp>

namespace freespace::saved {

/// A function by the double enclosures of its exact coefficients and, decoded only
/// when first needed, the exact coefficients themselves.
struct Function {
  std::vector<std::uint32_t> key;  // empty: no key
  std::uint32_t chart0Coefficients = 0;
  std::vector<double> enclosures;  // lower, upper per coefficient: chart 0's, then chart 1's
  std::string exact;               // the coefficients as rationals one after another, in the same order

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & key & chart0Coefficients & enclosures & exact;
  }
};

struct Angle {
  std::int32_t function = -1;  // -1: a rational angle
  std::int32_t chart = 0;
  /// The root's double enclosure, which isolates it; an exact isolating interval
  /// (lo, hi) only when it is narrower than the doubles can say (else both empty).
  /// A rational angle's t in lower and upper when it is a double, else in lo.
  double lower = 0, upper = 0;
  std::string lo, hi;
  std::int32_t index = -1;

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & function & chart & lower & upper & lo & hi & index;
  }
};

struct AngleSet {
  bool fullCircle = false;
  std::vector<std::uint32_t> arcs;  // from, to, wraps: three per arc

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & fullCircle & arcs;
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

struct Patch {
  std::vector<std::int32_t> contact;   // kind, robot, world, side
  AngleSet range;
  std::vector<std::uint32_t> segment;  // per end: robotVertex, vertex, edge[0], edge[1]
  std::vector<std::int32_t> lineTags;  // kind, side, vertices[4]
  std::vector<double> linePoints;      // points[4], xyz
  std::vector<std::uint8_t> spiralRobotVertex;
  std::vector<double> spiralPoints;    // per end: points[3], xyz

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & contact & range & segment & lineTags & linePoints & spiralRobotVertex & spiralPoints;
  }
};

struct Curve {
  std::uint32_t first = 0, second = 0;
  AngleSet angles;
  std::vector<std::uint8_t> ends;  // per arc and end: endOnOtherLine[2][2], rangeEnd[2]

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & first & second & angles & ends;
  }
};

struct Overlap {
  std::vector<std::uint32_t> patches;
  std::uint32_t angle = 0;
  std::vector<std::uint8_t> reachesEnd;

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & patches & angle & reachesEnd;
  }
};

struct Vertex {
  std::vector<std::uint32_t> patches;
  std::uint32_t angle = 0;
  std::int32_t crossing = -1;

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & patches & angle & crossing;
  }
};

struct Slab {
  std::uint32_t from = 0, to = 0, sample = 0;
  std::vector<std::uint32_t> curves, faces;

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & from & to & sample & curves & faces;
  }
};

struct Subdivision {
  std::vector<Slab> slabs;
  std::uint32_t faceCount = 0;

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & slabs & faceCount;
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
  std::vector<Function> functions;
  std::vector<Angle> angles;
  std::vector<Patch> patches;
  std::vector<Curve> curves;
  std::vector<Overlap> overlaps;
  std::vector<Vertex> vertices;
  std::vector<Subdivision> subdivisions;
  std::vector<Gluing> gluings;             // across curves, around spirals, across horizontal edges
  std::vector<std::uint8_t> shellSides;    // ShellSide per shell
  std::vector<std::int32_t> cellOfShell;   // -1: none
  std::uint32_t cellCount = 0;
  std::vector<std::string> stageNames;
  std::vector<double> stageSeconds;
  Graph graph;

  template <class Archive>
  void serialize(Archive& archive, unsigned) {
    archive & robot & world & perturbed & seed & relativeSize & absoluteSize & scale & functions & angles & patches &
        curves & overlaps & vertices & subdivisions & gluings & shellSides & cellOfShell & cellCount & stageNames &
        stageSeconds & graph;
  }
};

}  // namespace freespace::saved

// Plain records: no class information or object tracking in the archive (Boost would
// otherwise look each record's type up by name as it reads it).
#define FREESPACE_SAVED_RECORD(T)                                                 \
  BOOST_CLASS_IMPLEMENTATION(freespace::saved::T, boost::serialization::object_serializable) \
  BOOST_CLASS_TRACKING(freespace::saved::T, boost::serialization::track_never)
FREESPACE_SAVED_RECORD(Function)
FREESPACE_SAVED_RECORD(Angle)
FREESPACE_SAVED_RECORD(AngleSet)
FREESPACE_SAVED_RECORD(Mesh)
FREESPACE_SAVED_RECORD(Patch)
FREESPACE_SAVED_RECORD(Curve)
FREESPACE_SAVED_RECORD(Overlap)
FREESPACE_SAVED_RECORD(Vertex)
FREESPACE_SAVED_RECORD(Slab)
FREESPACE_SAVED_RECORD(Subdivision)
FREESPACE_SAVED_RECORD(Gluing)
FREESPACE_SAVED_RECORD(Graph)
FREESPACE_SAVED_RECORD(Space)
#undef FREESPACE_SAVED_RECORD
