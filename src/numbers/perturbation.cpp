#include "freespace/numbers/perturbation.h"

#include <cmath>
#include <stdexcept>

namespace freespace {

Perturbation::Perturbation(const PerturbationSettings& settings, double sceneSize)
    : record_{settings.enabled, settings.seed, settings.relativeSize, settings.relativeSize * sceneSize},
      random_(settings.seed) {
  if (!(settings.relativeSize >= 0) || !std::isfinite(settings.relativeSize) || !(sceneSize >= 0) ||
      !std::isfinite(sceneSize)) {
    throw std::invalid_argument("perturbation size must be finite and not negative");
  }
  if (!settings.enabled) record_.absoluteSize = 0;
}

double Perturbation::perturb(double coordinate) {
  if (!record_.enabled || record_.absoluteSize == 0) return coordinate;
  // 53 random bits give a uniform double in [0, 1); map it to [-1, 1).
  const double unit = static_cast<double>(random_() >> 11) * 0x1.0p-53;
  return coordinate + (2 * unit - 1) * record_.absoluteSize;
}

}  // namespace freespace
