// One study point: the model's frame against ref (accuracy), the timer's clocks (speed), and the
// predicted bound of the methods the triangles were drawn with (AUTO's bounds, docs/auto.md).
#include <cmath>
#include <map>
#include <sstream>

#include "htx/fw/auto_scene.h"
#include "htx/model/geometry.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/model.hpp"
#include "htx/model/names.hpp"
#include "htx/model/ref.hpp"
#include "htx/model/scenes.hpp"
#include "htx/study/study.hpp"

namespace htx::study {

namespace {

// The predicted bound of the method a triangle is drawn with; negative when the method has none.
double method_bound(const ScreenScene& scene, const ScreenTri& tri, const fw::AutoConfig& ac) {
  const fw::AutoBounds b = fw::auto_bounds(fw::auto_triangle_of(tri), ac, fw::auto_sampling_of(scene, tri));
  switch (tri.state.method) {
    case Method::Affine: return b.affine;
    case Method::Subdiv: return fw::auto_bound_subdiv(b, ac, tri.state.subdiv_n);
    case Method::RecipLut: return b.recip_lut;
    case Method::RecipNr: return b.recip_nr;
    case Method::DivFree: return b.divfree;
    default: return -1;
  }
}

}  // namespace

Result run_point(const Point& point, const Options& options) {
  Result r;
  r.point = point;
  ScreenScene screen = prepare_screen_scene(load_scene(point.scene), options.width, options.height);
  // kAutoCompared: AUTO with the choice priced as free, so that every triangle's is compared.
  const bool compared = point.method == kAutoCompared;
  const MethodChoice choice = parse_method(compared ? "auto" : point.method);
  for (ScreenTri& t : screen.tris) {
    t.state.method = choice.method;
    t.state.subdiv_n = choice.subdiv_n;
  }
  if (choice.method == Method::Auto) {
    ModelConfig auto_config = options.config;
    if (compared) auto_config.auto_choice_cycles = 0;
    fw::resolve_auto_methods(screen, auto_config, float(point.tolerance));
  }

  const fw::AutoConfig ac = fw::auto_config_of(options.config);
  std::map<std::string, int> used;
  bool textured = false, unbounded = false;
  double bound = 0;
  for (const ScreenTri& t : screen.tris) {
    if (!t.state.textured) continue;
    textured = true;
    ++used[method_name(t.state.method, t.state.subdiv_n)];
    const double b = method_bound(screen, t, ac);
    if (b < 0 || !std::isfinite(b)) unbounded = true;
    bound = std::max(bound, b);
  }
  r.bound = textured && !unbounded ? bound : -1;
  std::ostringstream names;
  for (const auto& [name, count] : used) names << (names.tellp() > 0 ? " " : "") << name << ":" << count;
  r.methods_used = names.str();

  const Frame model = render_model(screen, options.config);
  RefOptions ref_options;
  ref_options.depth_bits = options.config.z_bits;
  const Frame ref = render_ref(screen, ref_options);
  const Metrics m = compute_metrics(model, ref, {"model", point.scene, point.method, "scene", options.config_name});
  r.max_error = m.max_texel_error;
  r.p999_error = m.p999_texel_error;
  r.rms_error = m.rms_texel_error;
  r.compared_pixels = m.compared_pixels;
  r.coverage_diff_pixels = m.coverage_diff_pixels;
  r.surface_diff_pixels = m.surface_diff_pixels;
  r.divfree_cap_hits = m.divfree_cap_hits;

  if (options.timer) {
    const Timing t = options.timer(screen, options.config, model);
    r.clocks = t.clocks;
    r.fragments = t.fragments;
    r.mismatch = t.mismatch;
  } else {
    r.clocks = model.counters.cycles;
    r.fragments = model.counters.fragments;
  }
  r.clocks_per_pixel = r.fragments ? double(r.clocks) / double(r.fragments) : 0;
  r.finite = std::isfinite(r.max_error) && std::isfinite(r.p999_error) && std::isfinite(r.rms_error) &&
             std::isfinite(r.bound) && std::isfinite(r.clocks_per_pixel);
  return r;
}

}  // namespace htx::study
