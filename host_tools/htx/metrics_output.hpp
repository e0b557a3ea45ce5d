// htx render's metrics JSON (docs/metrics.md), as every engine writes it.
#pragma once

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace htx {

// An engine without a per-pixel probe (soc, board; rtl where its frame is not the model's): the
// figures taken from the probe would describe an empty one, so they are null.
inline void null_probe_figures(nlohmann::json* j) {
  for (const char* key :
       {"max_texel_error", "rms_texel_error", "p999_texel_error", "coverage_diff_pixels", "surface_diff_pixels"})
    (*j)[key] = nullptr;
}

// The figures taken from the probe, from `from` (an engine whose frame is this one's pixel for
// pixel and which has a probe) into *j.
inline void take_probe_figures(const nlohmann::json& from, nlohmann::json* j) {
  for (const char* key :
       {"max_texel_error", "rms_texel_error", "p999_texel_error", "compared_pixels", "coverage_diff_pixels",
        "surface_diff_pixels"})
    (*j)[key] = from.at(key);
}

inline void write_metrics(const std::string& path, const nlohmann::json& j) {
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write metrics to '" + path + "'");
  std::cout << "metrics -> " << path << "\n";
}

}  // namespace htx
