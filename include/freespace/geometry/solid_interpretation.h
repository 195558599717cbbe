#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace {

struct SolidSettings {
  /// Drop triangles that enclose nothing (with a warning) instead of refusing them.
  bool ignoreOpen = false;
  /// The repair tolerance (prepareMesh passes the one used): points this close to the
  /// plane of an opening count as lying in it, and faces enclosing nothing that are
  /// no thicker than this are slivers, dropped without a word.
  double tolerance = 0;
  /// The heights the other body spans (the world's for a robot, the robot's for a
  /// world), when known: triangles that enclose nothing and lie entirely below or above
  /// them, by more than the tolerance, can never touch it, so they are dropped with a
  /// report instead of refused (a stray sheet under the floor of a plan).
  std::optional<std::array<double, 2>> otherBodyHeights;
};

/// Triangles that enclose nothing: how many pieces, from how many repaired triangles, where.
struct OpenTriangles {
  std::size_t pieces = 0;
  std::size_t sourceTriangles = 0;
  Box3 bounds;
};

/// What the interpretation found and changed.
struct SolidReport {
  std::size_t closedComponents = 0;  // closed, edge-manifold components kept as they are
  std::size_t trianglesTurned = 0;   // their triangles turned to face outward like their neighbours
  std::size_t soupTriangles = 0;     // triangles of the other components
  std::size_t soupPieces = 0;        // edge-connected pieces among those
  std::size_t meetingPairs = 0;      // pairs of soup triangles meeting beyond shared vertices and edges
  std::size_t refinedTriangles = 0;  // soup triangles split along such meetings
  std::size_t enclosedRegions = 0;   // connected regions of space the soup encloses
  std::size_t solids = 0;            // closed components that bound the soup's solid
  std::size_t boundaryTriangles = 0;
  std::size_t capTriangles = 0;       // triangles added to close planar openings (left-out faces)
  std::size_t separatedEdges = 0;     // edges along which the solid touched itself, its pieces moved apart
  std::size_t internalTriangles = 0;  // pieces of triangles inside the solid, dropped
  OpenTriangles open;                 // triangles that enclose nothing (refused unless ignoreOpen)
  OpenTriangles outOfReach;           // those of them the other body can never touch (dropped)

  /// Lines for a user: what was kept, merged and dropped; empty when the mesh was
  /// made of closed components only.
  std::vector<std::string> describe() const;
};

/// The surface of the solid a repaired soup (repairSoup) shows (docs/design.md
/// section 9). Its components are its triangles joined through shared edges within
/// one piece of the input (`pieces`, from repairSoup: a file's objects; empty when not
/// known, then the whole soup is one piece). A component that is
/// closed and edge-manifold and whose surface does not meet itself means what it always
/// means: the solid it bounds (its triangles are turned to face outward, all alike);
/// voids that such components enclose together stay free. Every other triangle
/// belongs to the soup, whose solid is everything the soup's triangles enclose: the
/// complement of the unbounded region of space minus those triangles, found exactly
/// (the triangles are refined along their intersections, then the regions they bound
/// are told apart by walking around edges and by rays). A planar opening, where a face
/// was left out (the bottom of a wall, of a car), is closed by a cap of the plane's
/// region the opening's edges bound, where the cap separates an enclosed region from
/// the outside and makes less than half of its boundary. The result holds the closed
/// components, then the boundary of the soup's solid, facing out, as closed
/// edge-manifold components; every component has vertices of its own (components
/// touching along an edge or at a vertex stay apart). No component of the result meets
/// itself (checked exactly): build a Mesh from it with VertexWelding::asIndexed and
/// SelfIntersectionCheck::alreadyDone. New vertices (where triangles cross) are rounded
/// to doubles. Triangles that enclose nothing (an open sheet, a zero-thickness wall, a
/// crack) are an InputError naming `sourceName`, how many and where, unless
/// settings.ignoreOpen, which drops them and appends the same facts to `warnings`, or
/// they lie beyond settings.otherBodyHeights (then they are dropped and reported).
TriangleSoup interpretSolid(const TriangleSoup& repaired, const std::vector<std::uint32_t>& pieces,
                            const std::string& sourceName, const SolidSettings& settings = {},
                            SolidReport* report = nullptr, std::vector<std::string>* warnings = nullptr);

}  // namespace freespace
