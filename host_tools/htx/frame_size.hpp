// --size WxH, shared by the subcommands that render.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

#include "htx/model/geometry.hpp"

namespace htx {

inline void parse_size(const std::string& text, int& w, int& h) {
  int n = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &w, &h, &n) != 2 || static_cast<size_t>(n) != text.size() || w < 1 ||
      h < 1 || w > kMaxScreenSize || h > kMaxScreenSize)
    throw std::invalid_argument("--size '" + text + "': want WxH with 1 <= W, H <= " + std::to_string(kMaxScreenSize));
}

}  // namespace htx
