// htx render's metrics JSON (docs/metrics.md), as every engine writes it.
#pragma once

#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "htx/model/file_out.hpp"

namespace htx {

// The figures taken from the per-pixel probe (compared_pixels besides, which an empty probe makes 0),
// and DIVFREE's per-pixel step counts, which only the model counts (the GPU's CNT_DIVFREE_STEPS is a
// total; the console prints none).
inline constexpr const char* kProbeFigures[] = {"max_texel_error",      "rms_texel_error",     "p999_texel_error",
                                                "coverage_diff_pixels", "surface_diff_pixels", "divfree_max_steps",
                                                "divfree_mean_steps",   "divfree_cap_hits"};

// An engine without a per-pixel probe (soc, board; rtl where its frame is not the model's): the
// probe's figures (and DIVFREE's counts) would describe an empty one, so they are null, and so is
// `probe`.
inline void null_probe_figures(nlohmann::json* j) {
  for (const char* key : kProbeFigures) (*j)[key] = nullptr;
  (*j)["probe"] = nullptr;
}

// The probe's figures and DIVFREE's counts from `from`, the model's metrics for a frame that is this
// one pixel for pixel, into *j, with `probe` "model".
inline void take_probe_figures(const nlohmann::json& from, nlohmann::json* j) {
  for (const char* key : kProbeFigures) (*j)[key] = from.at(key);
  (*j)["compared_pixels"] = from.at("compared_pixels");
  (*j)["probe"] = "model";
}

inline void write_metrics(const std::string& path, const nlohmann::json& j) {
  write_file(path, j.dump(2) + "\n");
  std::cout << "metrics -> " << path << "\n";
}

}  // namespace htx
