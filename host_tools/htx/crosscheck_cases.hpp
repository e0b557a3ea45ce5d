// htx crosscheck's cases: random renders (a built-in scene with random parameters, a configuration,
// a method, a filter, a size) drawn from a seed, the same on every machine, each written as the
// `htx render` command that makes it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "htx/model/scenes.hpp"

namespace htx {

struct CrosscheckCase {
  std::string scene;      // a built-in scene spec, NAME[:key=value,...]
  std::string config;     // full, icebreaker or icebreaker-board
  std::string method;     // empty: the scene's own
  std::string filter;     // empty: the scene's own
  std::string tolerance;  // AUTO's, as text; empty: htx render's default
  bool untextured = false;
  int width = 320, height = 240;
};

// What draws the cases beside the model: the rtl engine (any configuration and size), or the
// console firmware on the simulated SoC (its GPU's configuration, its screen, the methods it takes
// and tolerances of 1/N texel).
enum class CrosscheckEngine { Rtl, Soc };

// Case `index` (0, 1, ...) of the sequence `seed` names for `engine`: a function of the three alone
// (its own SplitMix64 stream, ranges mapped by hand, not by the standard library's distributions,
// whose results differ between implementations), drawn from `scenes`' parameters and ranges.
CrosscheckCase draw_crosscheck_case(uint64_t seed, uint64_t index, const std::vector<SceneInfo>& scenes,
                                    CrosscheckEngine engine = CrosscheckEngine::Rtl);

// The case's `htx render` options but the scene and engine: "--config C [--method M] [--filter F]
// [--tolerance T] [--untextured] --size WxH".
std::string crosscheck_case_options(const CrosscheckCase& c);

// The `htx render` arguments that make the case on `engine`, writing `out` (and `metrics`, if not
// empty). (Every part is plain: letters, digits and `:,=._-`, which no shell treats specially.)
std::string crosscheck_render_command(const CrosscheckCase& c, const std::string& engine, const std::string& out,
                                      const std::string& metrics = "");

}  // namespace htx
