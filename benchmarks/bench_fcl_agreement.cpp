// Agreement of the exact collision test, on meshes as the project reads them
// (repaired and taken as the solids they show), with FCL on the triangles exactly as
// the files hold them, as OMPL.app's checker uses them (the robot re-centred as
// OMPL.app does). States are uniform over the problem's volume (or the environment's
// box grown by the robot's reach) and all angles, from a fixed seed. States near
// contact are skipped: those where moving the robot by 1e-4 of the scene's size
// along x or y changes FCL's answer. Of the rest, FCL free while the exact test finds
// a collision with the surfaces at least that far apart is the robot lying inside an
// enclosed region (FCL tests surfaces only): counted on their own. Every other
// difference is a disagreement; those where FCL on the meshes as read (repaired,
// capped) agrees with the exact test come from the repair and are counted apart.
//
// Usage: bench_fcl_agreement [--samples N] [--ignore-open] PROBLEM.cfg ...
// (default: 10000 samples; --ignore-open drops triangles that enclose nothing, as the
// command line's option does)
#include <filesystem>
#include <iostream>
#include <random>
#include <string>

#include "benchmark_arguments.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/io/mesh_reader.h"

using namespace freespace;

namespace {

struct Counts {
  int nearContact = 0;
  int agreements = 0;
  int insideEnclosedRegion = 0;
  int repairedGeometry = 0;  // disagreements that FCL on the repaired meshes shares
  int disagreements = 0;
};

// The robot's triangles as read, moved as loadProblem moves the prepared robot.
TriangleSoup robotAsRead(const LoadedProblem& loaded) {
  const std::filesystem::path folder = std::filesystem::path(loaded.cfgPath).parent_path();
  TriangleSoup robot = readTriangleSoup((folder / loaded.problem.robot).string());
  for (Point3& vertex : robot.vertices) vertex -= loaded.robotCentre;
  return robot;
}

TriangleSoup worldAsRead(const LoadedProblem& loaded) {
  const std::filesystem::path folder = std::filesystem::path(loaded.cfgPath).parent_path();
  return readTriangleSoup((folder / loaded.problem.world).string());
}

Eigen::AlignedBox2d stateBounds(const LoadedProblem& loaded) {
  if (loaded.problem.volume) return *loaded.problem.volume;
  const Box3 world = loaded.world.bounds();
  const double reach = loaded.robot.bounds().sizes().head<2>().norm();
  return {Eigen::Vector2d(world.min().x() - reach, world.min().y() - reach),
          Eigen::Vector2d(world.max().x() + reach, world.max().y() + reach)};
}

bool nearContact(const FclCollisionChecker& fcl, const Pose2& pose, bool collides, double step) {
  for (const auto& [dx, dy] : {std::pair{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step}}) {
    if (fcl.inCollision({pose.x + dx, pose.y + dy, pose.theta}) != collides) return true;
  }
  return false;
}

void measure(const std::string& cfg, int samples, const PreparationSettings& settings) {
  const LoadedProblem loaded = loadProblem(cfg, nullptr, settings);
  const FclCollisionChecker fcl(robotAsRead(loaded), worldAsRead(loaded));
  const FclCollisionChecker fclRepaired(loaded.robot, loaded.world);
  const ExactCollisionChecker exact(loaded.robot, loaded.world);
  const Eigen::AlignedBox2d bounds = stateBounds(loaded);
  const double step = 1e-4 * std::max(loaded.world.bounds().diagonal().norm(), loaded.robot.bounds().diagonal().norm());
  std::mt19937_64 random(20261204);
  std::uniform_real_distribution<double> x(bounds.min().x(), bounds.max().x());
  std::uniform_real_distribution<double> y(bounds.min().y(), bounds.max().y());
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  Counts counts;
  for (int i = 0; i < samples; ++i) {
    const Pose2 pose{x(random), y(random), theta(random)};
    const bool fclCollides = fcl.inCollision(pose);
    if (nearContact(fcl, pose, fclCollides, step)) {
      ++counts.nearContact;
      continue;
    }
    const bool exactCollides = exact.inCollision(pose);
    if (fclCollides == exactCollides) {
      ++counts.agreements;
    } else if (!fclCollides && fcl.distance(pose) >= step) {
      ++counts.insideEnclosedRegion;
    } else if (fclRepaired.inCollision(pose) == exactCollides) {
      ++counts.repairedGeometry;
    } else {
      ++counts.disagreements;
    }
  }
  std::cout << std::filesystem::path(cfg).stem().string() << ": " << samples << " states, " << counts.nearContact
            << " near contact skipped, " << counts.agreements << " agree, " << counts.insideEnclosedRegion
            << " with the robot inside an enclosed region (FCL free, exact collision), " << counts.repairedGeometry
            << " where the repair changed the geometry (FCL on the repaired meshes agrees), " << counts.disagreements
            << " disagreements" << std::endl;
}

int run(int argc, char** argv) {
  int samples = 10000;
  PreparationSettings settings;
  std::vector<std::string> problems;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--samples" && i + 1 < argc) {
      samples = static_cast<int>(benchmarks::wholeNumber(argument, argv[++i]));
    } else if (argument == "--ignore-open") {
      settings.solid.ignoreOpen = true;
    } else {
      benchmarks::rejectOption(argument, "bench_fcl_agreement [--samples N] [--ignore-open] PROBLEM.cfg ...");
      problems.push_back(argument);
    }
  }
  if (problems.empty()) {
    throw std::invalid_argument("usage: bench_fcl_agreement [--samples N] [--ignore-open] PROBLEM.cfg ...");
  }
  for (const std::string& cfg : problems) measure(cfg, samples, settings);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_fcl_agreement", [&] { return run(argc, argv); });
}
