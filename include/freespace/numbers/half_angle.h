#pragma once

#include <cmath>

#include "freespace/numbers/angle_reduction.h"

namespace freespace {

/// An angle in tangent half-angle form (docs/design.md section 2). Two charts cover the
/// circle without a singular point:
///   chart 0: theta in [-pi/2, pi/2],      t = tan(theta / 2)
///   chart 1: theta in (pi/2, pi] or (-pi, -pi/2), t = tan((theta - pi) / 2)
/// so t is always in [-1, 1]. With w = 1 + t^2, the rotation is rational in t:
///   chart 0: cos = (1 - t^2) / w,  sin = 2t / w
///   chart 1: cos = -(1 - t^2) / w, sin = -2t / w   (a half turn further)
struct HalfAngle {
  int chart = 0;
  double t = 0;

  /// A double angle becomes the rational angle with t = the double tan(.) above.
  /// Every exact computation then uses exactly this t: the rotation is rational and
  /// differs from the true theta by about 1e-16 rad. Any finite theta is reduced
  /// exactly (reducedAngle).
  static HalfAngle fromRadians(double theta) {
    const double wrapped = reducedAngle(theta);  // in [-pi, pi]
    if (std::fabs(wrapped) <= M_PI / 2) return {0, std::tan(wrapped / 2)};
    const double shifted = wrapped > 0 ? wrapped - M_PI : wrapped + M_PI;
    return {1, std::tan(shifted / 2)};
  }

  /// cos and sin in any number type that converts from double (intervals need a
  /// RoundingScope), written once from the formulas above.
  template <class T>
  void cosSin(T& cosine, T& sine) const {
    const T tangent(t);
    const T tangentSquared = tangent * tangent;
    const T w = T(1) + tangentSquared;
    cosine = (T(1) - tangentSquared) / w;
    sine = (tangent + tangent) / w;
    if (chart == 1) {
      cosine = -cosine;
      sine = -sine;
    }
  }

  /// The angle in radians (for printing; not used by exact code).
  double radians() const { return 2 * std::atan(t) + (chart == 1 ? (t > 0 ? -M_PI : M_PI) : 0.0); }
};

}  // namespace freespace
