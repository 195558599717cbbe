#include "freespace/numbers/angle_reduction.h"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace freespace {

namespace {

// Bits beyond theta's binary exponent: 53 for the result and guard bits for the
// closest approach of a double to a multiple of 2 pi (about 2^-61 of it), with room.
constexpr mpfr_prec_t kExtraBits = 192;

// Frees its MPFR numbers however the scope is left.
class MpfrNumbers {
 public:
  explicit MpfrNumbers(mpfr_prec_t precision) {
    for (mpfr_t& number : numbers_) mpfr_init2(number, precision);
  }
  ~MpfrNumbers() {
    for (mpfr_t& number : numbers_) mpfr_clear(number);
  }
  MpfrNumbers(const MpfrNumbers&) = delete;
  MpfrNumbers& operator=(const MpfrNumbers&) = delete;
  mpfr_t& operator[](int i) { return numbers_[i]; }

 private:
  mpfr_t numbers_[3];
};

}  // namespace

double reducedAngle(double theta) {
  if (!std::isfinite(theta)) throw std::invalid_argument("an angle must be a finite number");
  if (std::fabs(theta) <= M_PI) return theta;  // the double M_PI lies below pi
  int exponent = 0;
  std::frexp(theta, &exponent);
  // The remainder's error is about the quotient (2^exponent / 2 pi) times the
  // error of 2 pi at this precision.
  MpfrNumbers numbers(std::max(exponent, 0) + kExtraBits);
  mpfr_t &angle = numbers[0], &turn = numbers[1], &remainder = numbers[2];
  mpfr_set_d(angle, theta, MPFR_RNDN);  // exact: the precision exceeds 53 bits
  mpfr_const_pi(turn, MPFR_RNDN);
  mpfr_mul_2ui(turn, turn, 1, MPFR_RNDN);
  mpfr_remainder(remainder, angle, turn, MPFR_RNDN);
  return mpfr_get_d(remainder, MPFR_RNDN);
}

}  // namespace freespace
