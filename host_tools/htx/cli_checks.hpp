// Checks of option values that the option parser applies, so that a value outside what an option
// takes is refused with status 2 before any work, as CLI11's own range and list checks are.
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
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

// A whole number written in decimal digits (a '-' first where `is_signed`) that fits 64 bits.
// CLI11 2.1 reads integers as C's strtoull with base 0, so "010" was 8 and "0x10" 16, and it
// wraps a negative number into an unsigned option and saturates one past 64 bits without a word.
// Leading zeros are dropped here, so that what CLI11 then reads is the decimal value.
inline CLI::Validator decimal_integer(bool is_signed) {
  return CLI::Validator(
      [is_signed](std::string& text) -> std::string {
        const std::string want = is_signed ? "want a whole number in decimal digits, not "
                                           : "want a whole number >= 0 in decimal digits, not ";
        const bool negative = is_signed && !text.empty() && text[0] == '-';
        const size_t first = negative ? 1 : 0;
        if (text.size() == first) return want + "'" + text + "'";
        for (size_t i = first; i < text.size(); ++i)
          if (text[i] < '0' || text[i] > '9') return want + text;
        const char* const end = text.data() + text.size();
        std::from_chars_result r{};
        if (is_signed) {
          int64_t v = 0;
          r = std::from_chars(text.data(), end, v);
        } else {
          uint64_t v = 0;
          r = std::from_chars(text.data(), end, v);
        }
        if (r.ec != std::errc() || r.ptr != end) return text + " does not fit 64 bits";
        const size_t digits = text.find_first_not_of('0', first);
        text = (negative ? "-" : "") + (digits == std::string::npos ? std::string("0") : text.substr(digits));
        if (text == "-0") text = "0";
        return {};
      },
      "", "decimal integer");
}

// Every integer option of `app` and its subcommands (CLI11's type names INT and UINT, followed by
// their validators' descriptions) takes decimal_integer's check, ahead of its other checks (a
// transform goes first, and may rewrite the text); main() applies it once all are registered.
inline void require_decimal_integers(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    const std::string base = type.substr(0, type.find(':'));
    if (base == "INT" || base == "UINT") option->transform(decimal_integer(base == "INT"));
  }
  for (CLI::App* sub : app.get_subcommands({})) require_decimal_integers(*sub);
}

inline std::chrono::milliseconds timeout_ms(double seconds) {
  return std::chrono::milliseconds(std::llround(seconds * 1000));
}

}  // namespace htx
