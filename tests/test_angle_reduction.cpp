// Angles are reduced by the true 2 pi for every finite double: checked against an
// independent reduction in Boost.Multiprecision (binary floats of 1400 bits, pi from
// Boost.Math), and through the whole exact collision test against FCL, whose rotation
// takes std::cos and std::sin of the angle as given (the C library reduces exactly).
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "command_runner.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/numbers/angle_reduction.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/free_space.h"

using namespace freespace;

namespace {

using Wide = boost::multiprecision::number<
    boost::multiprecision::cpp_bin_float<1400, boost::multiprecision::digit_base_2>>;

double wideReduction(double theta) {
  static const Wide turn = 2 * boost::math::constants::pi<Wide>();
  const Wide angle(theta);
  return static_cast<double>(angle - round(angle / turn) * turn);
}

// Doubles of every binary exponent from -4 to 1023, either sign.
double randomAngle(std::mt19937_64& random) {
  std::uniform_int_distribution<int> exponent(-4, 1023);
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  const double magnitude = std::ldexp(mantissa(random), exponent(random));
  return random() % 2 == 0 ? magnitude : -magnitude;
}

double ulpsApart(double a, double b) {
  return std::fabs(a - b) / (std::nextafter(std::fabs(b), INFINITY) - std::fabs(b));
}

}  // namespace

TEST(AngleReduction, AgreesWithAnIndependentWideReduction) {
  std::mt19937_64 random(20261204);
  int exact = 0;
  constexpr int kAngles = 20000;
  for (int i = 0; i < kAngles; ++i) {
    const double theta = randomAngle(random);
    const double reduced = reducedAngle(theta);
    const double expected = wideReduction(theta);
    ASSERT_LE(ulpsApart(reduced, expected), 1.0) << theta;
    ASSERT_LE(std::fabs(reduced), M_PI + 4e-16) << theta;
    if (reduced == expected) ++exact;
  }
  EXPECT_GE(exact, kAngles * 99 / 100);
}

TEST(AngleReduction, KnownValuesAndAnglesInRange) {
  EXPECT_EQ(reducedAngle(1e15), 2.1096981170701126);
  EXPECT_EQ(wideReduction(1e15), 2.1096981170701126);
  for (double theta : {0.0, -0.0, 1.0, -3.0, M_PI, -M_PI, std::nextafter(M_PI, 0.0)}) {
    EXPECT_EQ(reducedAngle(theta), theta);
  }
  EXPECT_EQ(reducedAngle(std::numeric_limits<double>::max()), wideReduction(std::numeric_limits<double>::max()));
  EXPECT_THROW(reducedAngle(std::nan("")), std::invalid_argument);
  EXPECT_THROW(reducedAngle(INFINITY), std::invalid_argument);
  EXPECT_THROW(reducedAngle(-INFINITY), std::invalid_argument);
}

TEST(AngleReduction, ExactTestAgreesWithFclAtHugeAngles) {
  const LoadedProblem loaded = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg");
  const ExactCollisionChecker exact(loaded.robot, loaded.world);
  const FclCollisionChecker fcl(loaded.robot, loaded.world);
  const Box3 bounds = loaded.world.bounds();
  const double clear = 1e-6 * bounds.diagonal().norm();
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> x(bounds.min().x(), bounds.max().x()), y(bounds.min().y(), bounds.max().y());
  int compared = 0, collisions = 0;
  for (int i = 0; i < 3000; ++i) {
    double theta = randomAngle(random);
    if (std::fabs(theta) < 1e3) theta *= 1e6;
    const Pose2 pose{x(random), y(random), theta};
    const bool fclCollides = fcl.inCollision(pose);
    if (!fclCollides && fcl.distance(pose) < clear) continue;  // FCL's verdict unclear
    ++compared;
    collisions += fclCollides;
    ASSERT_EQ(exact.inCollision(pose), fclCollides) << pose.x << " " << pose.y << " " << theta;
  }
  EXPECT_GT(compared, 2500);
  EXPECT_GT(collisions, 100);
}

// locate at theta and at theta + 2 pi k for k up to about 1e300 / 2 pi (the angles
// randomAngle draws) answers as the exact test on the construction's meshes.
TEST(AngleReduction, LocateAgreesWithTheExactTestAtHugeAngles) {
  const LoadedProblem loaded = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg");
  const FreeSpace space(loaded.robot, loaded.world);
  const ExactCollisionChecker exact(space.meshes().robot, space.meshes().world);
  const Box3 bounds = space.meshes().world.bounds();
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> x(bounds.min().x(), bounds.max().x()), y(bounds.min().y(), bounds.max().y());
  int free = 0, huge = 0;
  for (int i = 0; i < 1000; ++i) {
    const Pose2 pose{x(random), y(random), randomAngle(random)};
    huge += std::fabs(pose.theta) > 1e15;
    const bool located = space.locate(pose).free;
    free += located;
    ASSERT_EQ(located, !exact.inCollision(pose)) << pose.x << " " << pose.y << " " << pose.theta;
  }
  EXPECT_GT(free, 100);
  EXPECT_GT(huge, 500);
}

TEST(AngleReduction, CheckAnswersForTheAngleGiven) {
  // At 1e15 the angle is 2.1096981170701126 (mod 2 pi); reduced by the double 2 pi it
  // would be 0.04 rad off, where the keyhole's robot collides.
  const std::string cfg = "--cfg '" + std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg'";
  const freespace::testing::CommandResult huge = freespace::testing::runFreespace("check " + cfg + " --at 0 0 1e15");
  const freespace::testing::CommandResult reduced = freespace::testing::runFreespace("check " + cfg + " --at 0 0 2.1096981170701126");
  ASSERT_EQ(huge.status, 0) << huge.err;
  EXPECT_NE(huge.out.find("exact free"), std::string::npos) << huge.out;
  EXPECT_NE(reduced.out.find("exact free"), std::string::npos) << reduced.out;
}
