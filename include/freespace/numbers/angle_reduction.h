#pragma once

namespace freespace {

/// The angle in [-pi, pi] that `theta` stands for: theta - 2 pi k for the integer k
/// nearest theta / (2 pi), rounded once to the nearest double, for every finite theta
/// (docs/design.md section 2). Reducing by the double nearest 2 pi instead would be
/// off by k times its error (at 1e15, by 0.04 rad). Angles already in [-pi, pi] are
/// returned as they are. Throws std::invalid_argument for NaN and infinities.
double reducedAngle(double theta);

}  // namespace freespace
