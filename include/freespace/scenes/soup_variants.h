#pragma once

// Triangle soups as modelling tools export them: test data for the loader's repair
// and solid interpretation, imitating what real planar environments and robots
// contain (double-sided surfaces, pieces glued along internal walls, T-junctions,
// float noise, touching and interpenetrating pieces, walls at several heights), and
// two defects the loader must refuse. Each soup is built from the primitives of
// scene_generator.h with base coordinates on the scene grid; unlike those, a
// variant need not be a closed, outward surface, and Mesh::fromSoup may refuse it.

#include <cstdint>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/scenes/scene_generator.h"

namespace freespace {

// ---------------------------------------------------------------------------------
// How a surface is written.

/// A double-sided surface, as exporters write planes and solids alike: every
/// triangle followed by its reversed copy (same vertex indices, opposite order).
TriangleSoup doubleSided(const TriangleSoup& soup);

/// The soup with every coordinate rounded to float, as a file stores it, and moved
/// by a whole number of steps between -ulps and +ulps (random, the same for a
/// seed). A step is the float spacing at the coordinate's magnitude, and at 1 for
/// magnitudes below 1, so that zero heights move too, as they do when a modeller
/// applies a transform: every vertex slot moves on its own, so copies of one point
/// (in separate pieces) differ in the last digits. A coordinate on the scene grid
/// below 2^14 moves by exactly its steps (for up to 8 ulps); others may be rounded
/// to float once more.
TriangleSoup withFloatNoise(const TriangleSoup& soup, std::uint64_t seed, unsigned ulps);

// ---------------------------------------------------------------------------------
// Pieces glued or joined without their common faces.

/// A solid prism built as a modeller builds an extruded outline: the outline is
/// triangulated (ear clipping) and each triangle extruded over [z0, z1] into a
/// closed prism of its own; all prisms in one soup, so every internal wall is there
/// twice, once from each prism, and the edges along internal walls are used by 4
/// triangles (or more where several prisms meet).
TriangleSoup gluedPrisms(const Polygon2& outline, double z0, double z1);

/// In pairs across x, y and z, the low side first.
enum class BoxFace { west, east, south, north, bottom, top };

/// The surface of a box without the given faces: an open piece, as left where a
/// modeller removed faces that another piece covers.
TriangleSoup openBox(const Box3& box, const std::vector<BoxFace>& missing);

/// A long wall box with two short boxes against its north face, split at x =
/// `split`, `depth` deep, as a modeller merging touching boxes leaves them: the
/// touching faces (the long box's north face and the short boxes' south faces and
/// the faces between them) are gone, so the surface is closed but the short boxes'
/// shared corners lie in the middle of the long box's north edges (T-junctions), and
/// those edges are used by one triangle each.
TriangleSoup tJunctionWall(const Box3& longBox, double split, double depth);

/// A wall box whose two end caps are missing because both ends are buried inside
/// perpendicular walls: the piece is open; with those walls around its ends the
/// union is closed. The wall runs along its longer horizontal side.
TriangleSoup wallWithBuriedEnds(const Box3& wall);

// ---------------------------------------------------------------------------------
// Boxes touching one another.

enum class Contact { face, edge, vertex };

/// `box` and a copy of it moved so that the two touch: by the box's x size to the
/// east (face: they share the whole east face, corners included); also by its y
/// size to the north and half its height up (edge: they touch along the upper half
/// of a vertical edge, and no corner of one is a corner of the other); or also by
/// its whole height up (vertex: they touch at one corner only).
TriangleSoup touchingBoxes(const Box3& box, Contact contact);

// ---------------------------------------------------------------------------------
// Defects the loader must refuse.

/// The box, and one box width east of it a vertical sheet as long and as high as
/// the box: a lone double-sided quad of zero thickness, whose edges are each used
/// as often in one direction as in the other, as a closed surface's are, yet it
/// encloses nothing.
TriangleSoup openSheetBesideBox(const Box3& box);

/// The box with the seam between its top and east faces torn open: the top face
/// stops `gap` short of the east edge and the east face `gap` below it, so the two
/// faces' edges are gap * sqrt(2) apart (far more than float noise) and the rim of
/// the crack runs along both faces, at right angles, and across the end faces.
TriangleSoup tornSeamBox(const Box3& box, double gap);

// ---------------------------------------------------------------------------------
// Robots written as soups.

/// A robot's soup as written and the solid it shows (a checked mesh).
struct SoupRobot {
  TriangleSoup soup;
  Mesh solid;
};

/// A robot mesh written double-sided; its vertices are the mesh's, so it stays
/// centred.
SoupRobot doubleSidedRobot(const Mesh& robot);

/// A car: a 1.5 x 0.75 rectangle (x by y) with a corner in the middle of each long
/// side (a hexagon outline), over z in [0, height], made of glued prisms
/// (gluedPrisms: four prisms) and written double-sided. The outline and its
/// triangulation are symmetric under a half turn about the z axis, so its vertices
/// average to x = y = 0 however they are counted: as written, duplicates included;
/// distinct; or as OMPL.app imports them (one per position and normal). OMPL.app's
/// re-centring of a robot at that average then leaves it in place.
SoupRobot makeGluedCarRobot(double height);

}  // namespace freespace
