#include "crosscheck_cases.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "htx/model/config.hpp"
#include "htx/model/names.hpp"
#include "htx/model/random.hpp"
#include "render_setup.hpp"
#include "soc_config.hpp"

namespace htx {

namespace {

// SplitMix64 (htx/model/random.hpp, as the seeded scenes use): every output a fixed function of
// the seed, so a case is the same on every machine and library.
class CaseRng {
 public:
  CaseRng(uint64_t seed, uint64_t index) : gen_(seed * 0x9E3779B97F4A7C15ull ^ (index + 1) * 0xD1B54A32D192ED03ull) {}

  uint64_t next() { return gen_.next(); }
  double unit() { return gen_.uniform(); }
  // An integer in [lo, hi] (the modulo's bias is below 2^-40 for these ranges).
  int64_t between(int64_t lo, int64_t hi) {
    return lo + static_cast<int64_t>(next() % static_cast<uint64_t>(hi - lo + 1));
  }
  bool chance(double p) { return unit() < p; }
  template <class T, size_t N>
  const T& pick(const T (&items)[N]) {
    return items[next() % N];
  }

 private:
  SplitMix64 gen_;
};

// A value's text that reads back as a value in [min, max]: six digits unless their rounding
// crosses a bound, then every digit.
std::string number_text(double v, double min, double max) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  const double back = std::strtod(buf, nullptr);
  if (back < min || back > max) std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// A parameter's value: a bound a third of the time (edges are where the engines are tried
// hardest), otherwise uniform, or log-uniform over a positive range wider than 100:1 (where most
// uniform draws would be near the top).
std::string draw_param(CaseRng& rng, const SceneParamInfo& p) {
  const double r = rng.unit();
  double v;
  if (r < 1.0 / 6) {
    v = p.min;
  } else if (r < 2.0 / 6) {
    v = p.max;
  } else if (p.min > 0 && p.max > 100 * p.min && rng.chance(0.5)) {
    v = p.min * std::exp(rng.unit() * std::log(p.max / p.min));
  } else {
    v = p.min + rng.unit() * (p.max - p.min);
  }
  if (p.integer) {
    const int64_t i = std::llround(v);
    const int64_t lo = static_cast<int64_t>(p.min), hi = static_cast<int64_t>(p.max);
    return std::to_string(i < lo ? lo : i > hi ? hi : i);
  }
  return number_text(v, p.min, p.max);
}

const char* const kConfigs[] = {"full", "full", "icebreaker", "icebreaker-board"};
const Method kMethods[] = {Method::Affine,  Method::Subdiv,    Method::RecipLut, Method::RecipNr,
                           Method::DivFree, Method::Quadratic, Method::Auto};
const Filter kFilters[] = {Filter::Nearest, Filter::Bilinear, Filter::Trilinear};

// Nine times in ten one the configuration builds on the GPU (AUTO, or a built method but the
// model's QUADRATIC), otherwise any: the engines must refuse those alike.
std::string draw_method(CaseRng& rng, const ModelConfig& config) {
  Method m;
  if (rng.chance(0.1)) {
    m = rng.pick(kMethods);
  } else {
    std::vector<Method> built;
    for (Method b : kMethods)
      if (b == Method::Auto || (b != Method::Quadratic && config.has_method(b))) built.push_back(b);
    m = built[rng.next() % built.size()];
  }
  if (m != Method::Subdiv) return method_name(m);
  const int64_t steps[] = {2, 4, 8, 16, 32, 64, rng.between(2, 64)};
  return method_name(m, static_cast<unsigned>(rng.pick(steps)));
}

// As the methods: one the configuration builds nine times in ten.
std::string draw_filter(CaseRng& rng, const ModelConfig& config) {
  std::vector<Filter> built;
  for (Filter f : kFilters)
    if (config.has_filter(f)) built.push_back(f);
  const Filter f = rng.chance(0.1) || built.empty() ? rng.pick(kFilters) : built[rng.next() % built.size()];
  return std::string(filter_name(f));
}

}  // namespace

CrosscheckCase draw_crosscheck_case(uint64_t seed, uint64_t index, const std::vector<SceneInfo>& scenes,
                                    CrosscheckEngine engine) {
  const bool soc = engine == CrosscheckEngine::Soc;
  // (The two engines' sequences are apart: one seed's case K is not the same scene on both.)
  CaseRng rng(seed, soc ? ~index : index);
  CrosscheckCase c;
  const SceneInfo& scene = scenes.at(rng.next() % scenes.size());
  c.scene = scene.name;
  char sep = ':';
  for (const SceneParamInfo& p : scene.params) {
    if (rng.chance(0.2)) continue;  // left at its default
    c.scene += sep + p.key + "=" + draw_param(rng, p);
    sep = ',';
  }
  c.config = soc ? "icebreaker" : rng.pick(kConfigs);  // (the SoC's GPU)
  const ModelConfig config = named_config(c.config);
  if (!rng.chance(0.15)) c.method = draw_method(rng, config);
  if (!rng.chance(0.25)) c.filter = draw_filter(rng, config);
  c.untextured = rng.chance(0.1);
  // AUTO's tolerance, log-uniform over 1/256 .. 4 texels (a scene's own triangles may ask for AUTO).
  // (The console takes 1/N texel: a power of two, whose decimal is exact.)
  if ((c.method.empty() || c.method == "auto") && rng.chance(0.3))
    c.tolerance = soc ? number_text(std::exp2(-static_cast<double>(rng.between(0, 8))), 0x1.0p-8, 1.0)
                      : number_text(std::exp2(-8.0 + 10.0 * rng.unit()), 0x1.0p-8, 4.0);
  if (soc) {
    c.width = render_app::kWidth, c.height = render_app::kHeight;  // the console's screen
    return c;
  }
  const double r = rng.unit();
  if (r < 0.3) {
    c.width = 320, c.height = 240;
  } else if (r < 0.5) {
    c.width = 160, c.height = 120;
  } else {
    c.width = static_cast<int>(rng.between(1, 400));
    c.height = static_cast<int>(rng.between(1, 300));
  }
  return c;
}

std::string crosscheck_case_options(const CrosscheckCase& c) {
  std::string s = "--config " + c.config;
  if (!c.method.empty()) s += " --method " + c.method;
  if (!c.filter.empty()) s += " --filter " + c.filter;
  if (!c.tolerance.empty()) s += " --tolerance " + c.tolerance;
  if (c.untextured) s += " --untextured";
  return s + " --size " + std::to_string(c.width) + "x" + std::to_string(c.height);
}

std::string crosscheck_render_command(const CrosscheckCase& c, const std::string& engine, const std::string& out,
                                      const std::string& metrics) {
  std::string cmd =
      "htx render " + c.scene + " --engine " + engine + " " + crosscheck_case_options(c) + " --out " + out;
  if (!metrics.empty()) cmd += " --metrics " + metrics;
  return cmd;
}

}  // namespace htx
