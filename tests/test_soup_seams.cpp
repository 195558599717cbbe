// Seams of a soup (src/geometry/soup_seams.h): which edges are cuts of a planar face,
// and how constraint segments are joined where the points on the cuts are left out.

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "geometry/soup_seams.h"

namespace freespace::detail {
namespace {

using Edge = Seams::Edge;

std::set<Edge> asSet(const std::vector<Edge>& edges) { return {edges.begin(), edges.end()}; }

TEST(Seams, AreEdgesOfTwoTrianglesContinuingOneAnotherInOnePlane) {
  // A unit square cut along (0, 2) (a seam); a third triangle folded back over the
  // square's edge (1, 2), in its plane, and a fourth standing up on the edge (0, 3).
  const std::vector<Point3> vertices{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0, 0.5, 1}};
  const std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 2, 3}, {1, 2, 4}, {0, 3, 5}};
  const Seams seams(vertices, triangles, {true, true, true, true});
  ASSERT_EQ(seams.all().size(), 1u);
  ASSERT_NE(seams.sides(2, 0), nullptr);
  EXPECT_EQ(*seams.sides(2, 0), (Seams::Sides{0, 1}));
  EXPECT_EQ(seams.sides(1, 2), nullptr) << "folded onto each other: the same side";
  EXPECT_EQ(seams.sides(0, 3), nullptr) << "not in one plane";

  const Seams notCandidates(vertices, triangles, {true, false, true, true});
  EXPECT_TRUE(notCandidates.all().empty());

  // A third triangle on the cut: an edge of three triangles is no seam.
  std::vector<TriangleIndices> withThird = triangles;
  withThird.push_back({0, 2, 5});
  EXPECT_TRUE(Seams(vertices, withThird, {true, true, true, true, true}).all().empty());
}

TEST(SeamPoints, JoinEverySegmentFromOneSideToEveryOneFromTheOther) {
  // Points 10 and 11 left out on one line: 1 - 10 - 11 - 2, with 3 a second end
  // beyond 11 (two segments on that side) and an unrelated segment kept.
  const std::vector<Edge> segments{{1, 10}, {10, 11}, {2, 11}, {3, 11}, {4, 5}};
  std::map<std::uint32_t, SeamPoints::Around> around;
  around[10] = {std::vector<std::uint32_t>{1}, std::vector<std::uint32_t>{11}};
  around[11] = {std::vector<std::uint32_t>{10}, std::vector<std::uint32_t>{2, 3}};
  EXPECT_EQ(asSet(SeamPoints::joined(segments, around)), (std::set<Edge>{{1, 2}, {1, 3}, {4, 5}}));
  // The same, the points left out in the other order.
  std::map<std::uint32_t, SeamPoints::Around> reversed;
  reversed[10] = {std::vector<std::uint32_t>{11}, std::vector<std::uint32_t>{1}};
  reversed[11] = {std::vector<std::uint32_t>{2, 3}, std::vector<std::uint32_t>{10}};
  EXPECT_EQ(asSet(SeamPoints::joined(segments, reversed)), (std::set<Edge>{{1, 2}, {1, 3}, {4, 5}}));
}

}  // namespace
}  // namespace freespace::detail
