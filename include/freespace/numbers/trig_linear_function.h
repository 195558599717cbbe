#pragma once

#include <memory>
#include <optional>

#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"

namespace freespace {

/// The angle function of a trig-linear form (EF and SF functions, docs/design.md section
/// 4): its charts' polynomials are tangentPolynomial of the form. `form(NumberType<T>{})`
/// returns the TrigLinear<T> computed from double inputs, written once for every
/// number type; `approximateForm` is its value in double intervals, which callers
/// have already computed for a quick test and which the function keeps instead of
/// computing it again.
template <class Form>
std::shared_ptr<const AngleFunction> trigLinearFunction(const Form& form, std::optional<AngleFunction::RootKey> key,
                                                        const TrigLinear<Interval>& approximateForm) {
  RoundingScope rounding;
  return std::make_shared<AngleFunction>([form](auto type, int chart) { return tangentPolynomial(form(type), chart); },
                                         key, tangentPolynomials(approximateForm));
}

}  // namespace freespace
