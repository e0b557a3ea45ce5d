// One study point: the model's frame against ref (accuracy), the timer's clocks (speed), and the
// predicted bound of the methods the triangles were drawn with (AUTO's bounds, docs/auto.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

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

  // Each textured triangle's predicted bound, by its index in drawing order (PixelProbe::tri).
  const fw::AutoConfig ac = fw::auto_config_of(options.config);
  std::vector<double> bounds(screen.tris.size(), -1);
  std::map<std::string, int> used;
  bool textured = false, unbounded = false, not_finite = false;
  double largest = 0, first_not_finite = 0;
  for (size_t i = 0; i < screen.tris.size(); ++i) {
    const ScreenTri& t = screen.tris[i];
    if (!t.state.textured) continue;
    textured = true;
    ++used[method_name(t.state.method, t.state.subdiv_n)];
    const double b = method_bound(screen, t, ac);
    bounds[i] = b;
    if (!std::isfinite(b)) {
      if (!not_finite) first_not_finite = b;
      not_finite = true;
    } else if (b < 0) {
      unbounded = true;
    } else {
      largest = std::max(largest, b);
    }
  }
  // A bound that is not a number is not "no bound": it is kept, and makes the point not finite.
  r.bound = not_finite ? first_not_finite : textured && !unbounded ? largest : -1;
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

  // Each pixel against the bound of its own triangle, over the pixels the errors are taken over
  // (compute_metrics: textured in both frames by the same mesh).
  if (not_finite) {
    r.bound_ratio = std::numeric_limits<double>::quiet_NaN();
  } else if (r.bound >= 0 && r.compared_pixels > 0) {
    double worst = 0;
    for (size_t i = 0; i < ref.probe.size(); ++i) {
      const PixelProbe& e = model.probe[i];
      const PixelProbe& f = ref.probe[i];
      if (!compared_pixel(e, f)) continue;
      if (e.tri < 0 || static_cast<size_t>(e.tri) >= bounds.size())
        throw std::logic_error("study: the model's probe names no triangle of the scene");
      const double b = bounds[static_cast<size_t>(e.tri)];
      const double err = texel_error(e, f);
      worst = std::max(worst, b > 0 ? err / b : err > 0 ? std::numeric_limits<double>::infinity() : 0.0);
    }
    r.bound_ratio = worst;
  }

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

std::string accuracy_problems(const Result& r) {
  std::string out;
  const auto add = [&out](const std::string& what) { out += (out.empty() ? "" : "; ") + what; };
  if (r.compared_pixels == 0) add("no pixel compared");
  if (r.coverage_diff_pixels > 0)
    add("textured in one frame only at " + std::to_string(r.coverage_diff_pixels) + " pixels");
  if (r.surface_diff_pixels > 0)
    add("another mesh in each frame at " + std::to_string(r.surface_diff_pixels) + " pixels");
  return out;
}

}  // namespace htx::study
