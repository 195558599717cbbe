#pragma once

// RapidCheck generators of numbers for the arithmetic tests.

#include <rapidcheck.h>

#include <cmath>

namespace freespace::testing {

/// Doubles of mixed magnitudes and signs, exact small values and zero.
inline double anyDouble() {
  switch (*rc::gen::inRange(0, 4)) {
    case 0: return 0.0;
    case 1: return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-20, 21)) / 8.0;
    case 2: return std::ldexp(*rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-1000000, 1000001)) / 3.0,
                              *rc::gen::inRange(-60, 61));
    default: return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-1000000, 1000001)) * 1.0e-7 / 3.0;
  }
}

}  // namespace freespace::testing
