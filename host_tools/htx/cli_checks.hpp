// Checks of option values that the option parser applies, so that a value outside what an option
// takes is refused with status 2 before any work, as CLI11's own range and list checks are.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <string>

namespace htx {

// --timeout's range: a millisecond (the port's resolution) to a day.
inline constexpr double kMinTimeoutSeconds = 0.001, kMaxTimeoutSeconds = 86400;

// A finite number of seconds within the range above (CLI::Range lets NaN through).
inline CLI::Validator timeout_seconds() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double s = 0;
        if (!CLI::detail::lexical_cast(text, s) || !std::isfinite(s) || s < kMinTimeoutSeconds ||
            s > kMaxTimeoutSeconds)
          return "want seconds from 0.001 to 86400, not " + text;
        return {};
      },
      "SECONDS in [0.001, 86400]");
}

// A finite number greater than 0 (CLI::PositiveNumber lets infinity through).
inline CLI::Validator positive_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0;
        if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || !(v > 0))
          return "want a finite number > 0, not " + text;
        return {};
      },
      "> 0");
}

inline std::chrono::milliseconds timeout_ms(double seconds) {
  return std::chrono::milliseconds(std::llround(seconds * 1000));
}

}  // namespace htx
