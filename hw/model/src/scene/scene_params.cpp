#include "scene_params.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace htx {

namespace {

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);  // 1073741823, not 1.07374e+09
  return buf;
}

}  // namespace

SceneParams::SceneParams(const std::string& spec) {
  const size_t colon = spec.find(':');
  name_ = spec.substr(0, colon);
  if (colon == std::string::npos) return;
  std::string rest = spec.substr(colon + 1);
  size_t pos = 0;
  while (pos <= rest.size()) {
    const size_t comma = rest.find(',', pos);
    const std::string pair = rest.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    const size_t eq = pair.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pair.size())
      throw std::invalid_argument("scene '" + name_ + "': malformed parameter '" + pair + "' (want key=value)");
    const std::string key = pair.substr(0, eq);
    if (!values_.emplace(key, pair.substr(eq + 1)).second)
      throw std::invalid_argument("scene '" + name_ + "': parameter '" + key + "' given twice");
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
}

void SceneParams::note(const std::string& key, double fallback, double min, double max, bool integer,
                       const char* unit) {
  if (!was_asked(key)) asked_.push_back({key, fallback, min, max, integer, unit});
}

bool SceneParams::was_asked(const std::string& key) const {
  return std::any_of(asked_.begin(), asked_.end(), [&](const SceneParamInfo& p) { return p.key == key; });
}

double SceneParams::number(const std::string& key, double fallback, double min, double max, const char* unit) {
  note(key, fallback, min, max, false, unit);
  return read(key, fallback, min, max);
}

double SceneParams::read(const std::string& key, double fallback, double min, double max) {
  const auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  // A decimal number (no hex, no spaces, no nan or inf); one too small for a double is its
  // nearest double (1e-400 is 0), one too large is out of range (stod threw for both, which read
  // as "not a number").
  const std::string& text = it->second;
  const bool decimal = !text.empty() && text.find_first_not_of("0123456789+-.eE") == std::string::npos;
  char* end = nullptr;
  errno = 0;
  const double v = decimal ? std::strtod(text.c_str(), &end) : 0.0;
  const bool overflow = errno == ERANGE && std::fabs(v) > 1.0;
  if (!decimal || end != text.c_str() + text.size())
    throw std::invalid_argument("scene '" + name_ + "': parameter " + key + "='" + text + "' is not a number");
  if (overflow || v < min || v > max)
    throw std::invalid_argument("scene '" + name_ + "': parameter " + key + "=" + it->second + " out of range [" +
                                format_number(min) + ", " + format_number(max) + "]");
  return v;
}

int SceneParams::integer(const std::string& key, int fallback, int min, int max, const char* unit) {
  note(key, fallback, min, max, true, unit);
  const double v = read(key, fallback, min, max);
  if (v != std::floor(v))
    throw std::invalid_argument("scene '" + name_ + "': parameter " + key + " must be an integer");
  return static_cast<int>(v);
}

std::string describe_scene_params(const std::vector<SceneParamInfo>& params) {
  std::string out;
  for (const SceneParamInfo& p : params) {
    if (!out.empty()) out += ", ";
    out += p.key + "=" + format_number(p.fallback) + " (" + format_number(p.min) + ".." + format_number(p.max);
    if (!p.unit.empty()) out += " " + p.unit;
    out += ")";
  }
  return out;
}

void SceneParams::check_all_used() const {
  for (const auto& [key, value] : values_)
    if (!was_asked(key))
      throw std::invalid_argument("scene '" + name_ + "' has no parameter '" + key + "'");
}

}  // namespace htx
