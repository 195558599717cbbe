#pragma once

// Clearance against the exact collision test (an independent measure, on the
// construction's meshes): a configuration keeps its state (free or blocked) in every
// direction up to |clearance| (1 - 1e-6), sampled on 64 directions at 8 distances
// each, and changes it within |clearance| (1 + 1e-6): along the witness direction,
// or on a small circle around the witness point (where the nearest boundary point
// is a corner of the slice, a ray through it may only touch).

#include <chrono>
#include <cmath>
#include <random>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/space/free_space.h"
#include "random_configurations.h"

namespace freespace::testing {

struct ClearanceCheck {
  int samples = 0;
  int free = 0;
  int keepsStateTooClose = 0;   // a state change nearer than the clearance: too large
  int noChangeWithin = 0;       // no state change found within it: too small
  double widestRelative = 0;    // the widest certified interval, relative
  double clearanceSeconds = 0;  // spent in FreeSpace::clearance
};

inline ClearanceCheck clearanceAgainstCollision(const FreeSpace& space, int samples, unsigned seed) {
  constexpr int kDirections = 64, kDistances = 8;
  constexpr double kRelative = 1e-6;
  const ExactCollisionChecker collision(space.meshes().robot, space.meshes().world);
  const double scale = space.meshes().scale;
  RandomConfigurations configurations(space, seed);
  ClearanceCheck check;
  for (int i = 0; i < samples; ++i) {
    const Pose2 pose = configurations.next();  // construction coordinates
    const auto start = std::chrono::steady_clock::now();
    const Clearance clearance = space.clearance({pose.x / scale, pose.y / scale, pose.theta});
    check.clearanceSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool blocked = collision.inCollision(pose);
    ++check.samples;
    check.free += !blocked;
    if (!std::isfinite(clearance.lower)) continue;
    const double lower = std::min(std::fabs(clearance.lower), std::fabs(clearance.upper)) * scale;
    const double upper = std::max(std::fabs(clearance.lower), std::fabs(clearance.upper)) * scale;
    check.widestRelative = std::max(check.widestRelative, (upper - lower) / upper);
    const auto keepsState = [&](double px, double py) { return collision.inCollision({px, py, pose.theta}) == blocked; };
    bool kept = true;
    for (int k = 0; k < kDirections; ++k) {
      const double angle = 2 * M_PI * k / kDirections;
      for (int step = 1; step <= kDistances; ++step) {
        const double s = lower * (1 - kRelative) * step / kDistances;
        kept = kept && keepsState(pose.x + s * std::cos(angle), pose.y + s * std::sin(angle));
      }
    }
    check.keepsStateTooClose += !kept;
    const double beyond = upper * (1 + kRelative);
    bool changes = !keepsState(pose.x + beyond * clearance.direction[0], pose.y + beyond * clearance.direction[1]);
    // Around a corner of the slice the other state may be a thin wedge (measured: 3
    // degrees, and 0.1 degree, at corners of random_polyhedra): more points on the
    // circle when fewer find nothing.
    const double nx = clearance.nearest[0] * scale, ny = clearance.nearest[1] * scale;
    for (int points = 64; points <= 65536 && !changes; points *= 32) {
      for (int k = 0; k < points && !changes; ++k) {
        const double angle = 2 * M_PI * k / points, radius = kRelative * upper / 2;
        changes = !keepsState(nx + radius * std::cos(angle), ny + radius * std::sin(angle));
      }
    }
    check.noChangeWithin += !changes;
  }
  return check;
}

}  // namespace freespace::testing
