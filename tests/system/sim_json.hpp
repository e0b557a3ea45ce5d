// The object `htx sim --json` prints as the last line of its stdout, parsed (for system tests).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace htx::test {

// The last line of `out` that starts with '{' (the firmware's own output comes before it; the
// object may hold nested objects, such as "profile" and "hotspots").
inline nlohmann::json last_json_line(const std::string& out) {
  const size_t line = out.rfind("\n{");
  return nlohmann::json::parse(out.substr(line == std::string::npos ? out.find('{') : line + 1));
}

}  // namespace htx::test
