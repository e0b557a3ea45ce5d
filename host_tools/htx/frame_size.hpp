// --size WxH (the subcommands that render) and htx sim's --frame-size: two decimal numbers and an
// 'x', nothing else (no sign, no space, no number past `max`, which sscanf's %d and %u let wrap).
#pragma once

#include <charconv>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "htx/model/geometry.hpp"

namespace htx {

// W and H in 1..max, or nothing when `text` is not exactly that.
inline std::optional<std::pair<uint32_t, uint32_t>> parse_wxh(const std::string& text, uint32_t max) {
  const size_t x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  auto side = [max](const char* first, const char* last) -> std::optional<uint32_t> {
    if (first == last || *first < '0' || *first > '9') return std::nullopt;  // from_chars takes no '+', but a '-'
    uint64_t v = 0;
    const auto r = std::from_chars(first, last, v);
    if (r.ec != std::errc() || r.ptr != last || v < 1 || v > max) return std::nullopt;
    return static_cast<uint32_t>(v);
  };
  const auto w = side(text.data(), text.data() + x);
  const auto h = side(text.data() + x + 1, text.data() + text.size());
  if (!w || !h) return std::nullopt;
  return std::make_pair(*w, *h);
}

inline void parse_size(const std::string& text, int& w, int& h) {
  const auto size = parse_wxh(text, static_cast<uint32_t>(kMaxScreenSize));
  if (!size)
    throw std::invalid_argument("--size '" + text + "': want WxH with 1 <= W, H <= " + std::to_string(kMaxScreenSize));
  w = static_cast<int>(size->first);
  h = static_cast<int>(size->second);
}

}  // namespace htx
