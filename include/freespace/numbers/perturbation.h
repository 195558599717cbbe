#pragma once

#include <cstdint>
#include <random>

namespace freespace {

/// How the input coordinates are perturbed once before construction (docs/design.md
/// section 5, step 1): every coordinate moves by a uniform random amount of at most
/// relativeSize times the scene size, so that no coincidence of unrelated features
/// remains. Switched off, coordinates are used as given.
struct PerturbationSettings {
  bool enabled = true;
  std::uint64_t seed = 1;
  double relativeSize = 1e-8;
};

/// What was done, reported with every result so that a run can be reproduced.
struct PerturbationRecord {
  bool enabled = true;
  std::uint64_t seed = 1;
  double relativeSize = 1e-8;
  double absoluteSize = 0;  // relativeSize times the scene size
};

/// A seeded stream of coordinate perturbations. The same settings, scene size and
/// order of calls give the same coordinates on every platform: the offsets are made
/// from the raw 64-bit output of std::mt19937_64, not from a distribution whose
/// algorithm the standard leaves open.
class Perturbation {
 public:
  Perturbation(const PerturbationSettings& settings, double sceneSize);

  /// The coordinate moved by the next offset in [-absoluteSize, absoluteSize].
  double perturb(double coordinate);

  const PerturbationRecord& record() const { return record_; }

 private:
  PerturbationRecord record_;
  std::mt19937_64 random_;
};

}  // namespace freespace
