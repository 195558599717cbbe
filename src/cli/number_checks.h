#pragma once

#include <cmath>
#include <string>

#include <CLI/CLI.hpp>

namespace freespace::cli {

/// Checks of option values whose failures exit with status 2 naming the option.

/// A check for options that take a size: a finite number, at least 0
/// (CLI::NonNegativeNumber lets NaN and infinities through).
inline CLI::Validator finiteNonNegative() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        if (CLI::detail::lexical_cast(text, value) && std::isfinite(value) && value >= 0) return {};
        return "must be a finite number, at least 0, not '" + text + "'";
      },
      "SIZE");
}

/// A check for coordinates and angles: a finite number.
inline CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        if (CLI::detail::lexical_cast(text, value) && std::isfinite(value)) return {};
        return "must be a finite number, not '" + text + "'";
      },
      "NUMBER");
}

/// A check for file names: not empty.
inline CLI::Validator nonEmpty() {
  return CLI::Validator([](std::string& text) -> std::string { return text.empty() ? "must not be empty" : ""; },
                        "FILE");
}

/// A check for counts and seeds: digits only (an unsigned option would otherwise
/// take "-1" as 2^64 - 1).
inline CLI::Validator wholeNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos) return {};
        return "must be a whole number (digits only), not '" + text + "'";
      },
      "WHOLE");
}

}  // namespace freespace::cli
