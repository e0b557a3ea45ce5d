// AUTO for the host's double-precision screen scenes (`htx render --method auto --tolerance T`, the
// AUTO measurement test): every triangle asking for AUTO gets the method choose_method picks for it,
// the same chooser the firmware pipeline runs. A template over the host's ScreenScene and
// ModelConfig (hw/model types.hpp, config.hpp) so this library stays free of host headers.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "htx/fw/auto_select.h"

namespace htx::fw {

struct AutoSceneSummary {
  uint32_t resolved = 0;          // triangles that asked for AUTO
  uint32_t per_method[5] = {};    // how many got each method
  uint32_t not_within = 0;        // fell back: no method predicted within the tolerance
  uint32_t skipped = 0;           // RECIP_NR without comparing: choosing would not pay
  double predicted_cycles = 0;    // sum of the chosen methods' predicted cycles
};

// The chooser's view of a host screen triangle (float copies of its screen, depth and texel
// coordinates) and of how it samples its texture.
template <class ScreenTri>
AutoTriangle auto_triangle_of(const ScreenTri& tri) {
  AutoTriangle t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = static_cast<float>(tri.v[i].x);
    t.y[i] = static_cast<float>(tri.v[i].y);
    t.w[i] = static_cast<float>(tri.v[i].w);
    t.u[i] = static_cast<float>(tri.v[i].u);
    t.v[i] = static_cast<float>(tri.v[i].v);
  }
  return t;
}

template <class ScreenScene, class ScreenTri>
AutoSampling auto_sampling_of(const ScreenScene& scene, const ScreenTri& tri) {
  AutoSampling s;
  s.filter = static_cast<uint8_t>(tri.state.filter);
  if (tri.state.texture >= 0 && static_cast<size_t>(tri.state.texture) < scene.textures.size()) {
    const auto& tex = scene.textures[static_cast<size_t>(tri.state.texture)];
    s.top_level = static_cast<uint8_t>(tex.log2_width > tex.log2_height ? tex.log2_width : tex.log2_height);
  }
  return s;
}

// Untextured triangles have no texel error: they get the cheapest method (or RECIP_NR where
// choosing would not pay, as any triangle).
template <class ScreenScene, class Config>
AutoSceneSummary resolve_auto_methods(ScreenScene& scene, const Config& cfg, float tolerance) {
  AutoSceneSummary sum;
  const AutoConfig ac = auto_config_of(cfg);
  for (auto& tri : scene.tris) {
    using Method = decltype(tri.state.method);
    if (tri.state.method != Method::Auto) continue;
    const AutoChoice c = choose_method(auto_triangle_of(tri), ac, auto_sampling_of(scene, tri), cfg.methods,
                                       tri.state.textured ? tolerance : 1e12f);
    tri.state.method = static_cast<Method>(c.method);
    tri.state.subdiv_n = c.subdiv_n;
    ++sum.resolved;
    if (c.method < 5) ++sum.per_method[c.method];
    sum.not_within += c.within ? 0 : 1;
    sum.skipped += c.skipped ? 1 : 0;
    sum.predicted_cycles += c.cycles;
  }
  return sum;
}

}  // namespace htx::fw
