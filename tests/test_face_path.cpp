// Translations inside one face of a slice (pathInFace) on the bundled scenes: every
// motion of every path between two configurations of one node, at their angle, is
// certified free by the clearance (MotionChecker), an independent measure. The
// distance to the face's loops (nearestOnBoundary) is the exact clearance there, up
// to the corners' rounding. The certified clearance along a translation from the
// loops (certifiedClearanceAlong) never exceeds the exact clearance at points along
// it, is given only where the translation stays in the face, and at a point is the
// exact clearance but for the corners' rounding (small).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <memory>
#include <string>

#include "bundled_problem.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/face_path.h"
#include "freespace/space/motion_checker.h"
#include "random_configurations.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

class BundledFacePaths : public ::testing::TestWithParam<std::string> {};

/// The angle of a random slice and its faces; none at a critical angle.
std::optional<std::pair<double, std::vector<SliceFace>>> randomSlice(const FreeSpace& space,
                                                                     RandomConfigurations& random) {
  const double theta = random.next().theta;
  try {
    return std::pair(theta,
                     space.sliceFaces().at(AlgebraicAngle::rational(HalfAngle::fromRadians(theta)), space.algebra()));
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

TEST_P(BundledFacePaths, EveryMotionIsCertifiedFree) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  const MotionChecker checker(space);
  const double scale = space.meshes().scale;
  RandomConfigurations random(space, 5);
  int paths = 0, motions = 0, uncertified = 0, estimates = 0, misestimated = 0, located = 0, mislocated = 0;
  for (int slice = 0; slice < 4; ++slice) {
    const std::optional<std::pair<double, std::vector<SliceFace>>> sliced = randomSlice(space, random);
    if (!sliced) continue;
    const auto& [theta, faces] = *sliced;
    std::map<std::uint32_t, Pose2> previousInNode;
    std::map<std::uint32_t, std::unique_ptr<FaceTriangulation>> triangulations;  // faces with loops, by node
    for (const SliceFace& face : faces) {
      if (!face.loops.empty()) triangulations[face.node] = std::make_unique<FaceTriangulation>(face);
    }
    for (int sample = 0; sample < 150; ++sample) {
      Pose2 pose = random.next();
      pose.theta = theta;
      const std::optional<std::uint32_t> node = space.nodeOf(pose);
      if (!node || space.clearance(pose).lower < 1e-6) continue;
      const auto found = previousInNode.find(*node);
      const std::optional<Pose2> previous =
          found == previousInNode.end() ? std::nullopt : std::optional<Pose2>(found->second);
      previousInNode[*node] = pose;
      // The face's triangulation holds the pose exactly when its node does (locate's).
      for (const auto& [faceNode, triangulation] : triangulations) {
        ++located;
        mislocated += triangulation->contains({pose.x * scale, pose.y * scale}) != (faceNode == *node);
      }
      const SliceFace& face =
          *std::find_if(faces.begin(), faces.end(), [&](const SliceFace& f) { return f.node == *node; });
      if (!face.loops.empty()) {
        const double estimate = nearestOnBoundary(face, {pose.x * scale, pose.y * scale}).distance / scale;
        const Clearance exact = space.clearance(pose);
        ++estimates;
        misestimated += !(std::fabs(estimate - exact.lower) <= 1e-9 * (1 + exact.lower));
      }
      if (!previous) continue;
      const auto path = pathInFace(face, {previous->x * scale, previous->y * scale}, {pose.x * scale, pose.y * scale});
      ASSERT_TRUE(path) << "node " << *node << " at theta " << theta;
      ++paths;
      for (std::size_t i = 0; i + 1 < path->size(); ++i) {
        const Pose2 a{(*path)[i][0] / scale, (*path)[i][1] / scale, theta};
        const Pose2 b{(*path)[i + 1][0] / scale, (*path)[i + 1][1] / scale, theta};
        ++motions;
        uncertified += !checker.check(a, b).free;
      }
    }
  }
  std::cout << GetParam() << ": " << paths << " paths, " << motions << " motions, " << uncertified
            << " not certified free; " << estimates << " clearances from the loops, " << misestimated
            << " more than 1e-9 off; " << located << " located in faces' triangulations, " << mislocated
            << " wrongly\n";
  EXPECT_GT(paths, 20);
  EXPECT_EQ(uncertified, 0);
  EXPECT_GT(estimates, 100);
  EXPECT_EQ(misestimated, 0);
  EXPECT_GT(located, 100);
  EXPECT_EQ(mislocated, 0);
}

TEST_P(BundledFacePaths, LoopsCertifyTranslationsInsideTheFaceBelowTheExactClearance) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  const double scale = space.meshes().scale;
  RandomConfigurations random(space, 7);
  std::uniform_real_distribution<double> fraction(0, 1);
  std::mt19937 draw(11);
  int segments = 0, certified = 0, wrong = 0, points = 0, loose = 0;
  double widestRounding = 0;  // the corners' rounding, relative to the scene's size
  const double size = space.meshes().world.bounds().diagonal().norm();
  for (int slice = 0; slice < 4; ++slice) {
    const std::optional<std::pair<double, std::vector<SliceFace>>> sliced = randomSlice(space, random);
    if (!sliced) continue;
    const auto& [theta, faces] = *sliced;
    for (int sample = 0; sample < 100; ++sample) {
      Pose2 from = random.next(), to = random.next();
      from.theta = to.theta = theta;
      // Short translations as often as long ones (from a tenth of the scene down).
      const double shrink = std::pow(10.0, -4 * fraction(draw));
      to = MotionChecker::interpolate(from, to, shrink);
      const std::array<double, 2> a{from.x * scale, from.y * scale}, b{to.x * scale, to.y * scale};
      for (const SliceFace& face : faces) {
        ++segments;
        const std::optional<double> along = certifiedClearanceAlong(face, a, b);
        // A point: the exact clearance within its certified width when inside.
        const std::optional<double> at = certifiedClearanceAlong(face, a, a);
        const std::optional<std::uint32_t> node = space.nodeOf(from);
        if (at) {
          ++points;
          const Clearance exact = space.clearance(from);
          wrong += node != face.node || !(*at / scale <= exact.upper);
          // The loops lie within their corners' rounding of the exact boundary.
          loose += !(*at / scale >= exact.lower - 2 * face.cornerError / scale - 1e-9 * (1 + exact.lower));
          widestRounding = std::max(widestRounding, face.cornerError / scale / size);
        }
        if (!along) continue;
        ++certified;
        wrong += !at;
        for (int k = 0; k <= 50; ++k) {
          const Pose2 pose = MotionChecker::interpolate(from, to, k / 50.0);
          const Clearance exact = space.clearance(pose);
          wrong += space.nodeOf(pose) != face.node ||
                   !(*along / scale - MotionChecker::interpolationRounding(from, to) <= exact.upper);
        }
      }
    }
  }
  std::cout << GetParam() << ": " << segments << " translations and faces, " << certified << " certified by the loops, "
            << points << " points; " << wrong << " wrong, " << loose
            << " points further below the exact clearance than twice their face's rounding " << widestRounding
            << " (widest, relative to the scene)\n";
  EXPECT_GT(certified, 20);
  EXPECT_GT(points, 50);
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(loose, 0);
  EXPECT_LT(widestRounding, 1e-6);
}

/// A face bounded by a jagged ring of `corners` corners (radii 8 to 10) around a
/// square hole of side 2.
SliceFace jaggedFace(int corners, std::mt19937& random) {
  std::uniform_real_distribution<double> radius(8, 10);
  SliceFace face;
  SliceLoop outer;
  for (int k = 0; k < corners; ++k) {
    const double angle = 2 * M_PI * k / corners, r = radius(random);
    outer.corners.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  face.loops.push_back(outer);
  face.loops.push_back(SliceLoop{{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}});
  return face;
}

/// The distance from p to the segment from a to b, in long double.
long double segmentDistance(const std::array<double, 2>& p, const std::array<double, 2>& a,
                            const std::array<double, 2>& b) {
  const long double ux = (long double)b[0] - a[0], uy = (long double)b[1] - a[1];
  const long double wx = (long double)p[0] - a[0], wy = (long double)p[1] - a[1];
  const long double t = std::clamp((wx * ux + wy * uy) / (ux * ux + uy * uy), 0.0L, 1.0L);
  return std::hypot(wx - t * ux, wy - t * uy);
}

// BoundaryDistances (an R-tree of the edges for faces of many, each edge in turn for
// the others) against the least distance to every edge in long double, at random
// points inside and around the face: the same distance (to 1e-12 relative), to a
// point of the boundary at that distance.
TEST(BoundaryDistances, FindTheNearestPointOfTheLoops) {
  std::mt19937 random(20261207);
  for (const int corners : {12, 100, 700}) {
    const SliceFace face = jaggedFace(corners, random);
    const BoundaryDistances distances(face);
    std::uniform_real_distribution<double> coordinate(-12, 12);
    for (int sample = 0; sample < 2000; ++sample) {
      const std::array<double, 2> point{coordinate(random), coordinate(random)};
      long double least = HUGE_VALL, footOnBoundary = HUGE_VALL;
      const BoundaryPoint nearest = distances.nearest(point);
      for (const SliceLoop& loop : face.loops) {
        for (std::size_t k = 0; k < loop.corners.size(); ++k) {
          const auto& a = loop.corners[k];
          const auto& b = loop.corners[(k + 1) % loop.corners.size()];
          least = std::min(least, segmentDistance(point, a, b));
          footOnBoundary = std::min(footOnBoundary, segmentDistance(nearest.point, a, b));
        }
      }
      ASSERT_NEAR(nearest.distance, least, 1e-12 * (1 + least)) << corners << " corners, sample " << sample;
      ASSERT_LT(footOnBoundary, 1e-12) << corners << " corners, sample " << sample;
      ASSERT_NEAR(std::hypot(point[0] - nearest.point[0], point[1] - nearest.point[1]), nearest.distance,
                  1e-12 * (1 + least));
    }
  }
}

// BoundaryDistances' certified clearance along a translation and its inside test
// (from the edges near the motion and along the ray only, for a face of many edges)
// against the same from every edge, at random points and translations: the same
// answers.
TEST(BoundaryDistances, CertifyAndLocateAsEveryEdgeDoes) {
  std::mt19937 random(20261207);
  for (const int corners : {200, 700}) {
    SliceFace face = jaggedFace(corners, random);
    face.cornerError = 1e-12;
    const BoundaryDistances distances(face);
    std::uniform_real_distribution<double> coordinate(-12, 12), step(-3, 3);
    int inside = 0, certified = 0;
    for (int sample = 0; sample < 2000; ++sample) {
      const std::array<double, 2> from{coordinate(random), coordinate(random)};
      const std::array<double, 2> to =
          sample % 4 == 0 ? from : std::array<double, 2>{from[0] + step(random), from[1] + step(random)};
      ASSERT_EQ(distances.liesInside(from), liesInside(face, from)) << corners << " corners, sample " << sample;
      inside += liesInside(face, from);
      const std::optional<double> near = distances.certifiedClearanceAlong(from, to);
      const std::optional<double> every = certifiedClearanceAlong(face, from, to);
      ASSERT_EQ(near.has_value(), every.has_value()) << corners << " corners, sample " << sample;
      if (!every) continue;
      ++certified;
      ASSERT_NEAR(*near, *every, 1e-12 * *every) << corners << " corners, sample " << sample;
    }
    // Both answers met often enough to matter.
    EXPECT_GT(inside, 500);
    EXPECT_GT(certified, 200);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledFacePaths,
                         ::testing::Values("keyhole", "keyhole_wide", "flip_window", "maze", "overhang", "table",
                                           "room_door", "random_polyhedra", "turn_around"));

}  // namespace
