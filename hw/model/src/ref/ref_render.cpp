#include <algorithm>
#include <cmath>
#include <limits>

#include "htx/model/ref.hpp"
#include "ref_raster.hpp"
#include "ref_sampler.hpp"

namespace htx {

namespace {

uint16_t to_rgb565(const ref::Rgba& c) {
  auto q = [](double x, int max) {
    const double v = std::nearbyint(std::clamp(x, 0.0, 1.0) * max);
    return static_cast<uint16_t>(v);
  };
  return static_cast<uint16_t>(q(c[0], 31) << 11 | q(c[1], 63) << 5 | q(c[2], 31));
}

// LOD is reported within these bounds (a zero derivative would give -inf).
constexpr double kMinLod = -32, kMaxLod = 32;

}  // namespace

long long ref_nearest_index(double c) { return static_cast<long long>(std::ceil(c)) - 1; }

Frame render_ref(const ScreenScene& scene, const RefOptions& options) {
  const int w = scene.width, h = scene.height;
  Frame f;
  f.width = w;
  f.height = h;
  const size_t n = static_cast<size_t>(std::max(w, 0)) * static_cast<size_t>(std::max(h, 0));
  const unsigned bits = std::clamp(options.depth_bits, 1u, 32u);
  const double depth_max = std::ldexp(1.0, static_cast<int>(bits)) - 1;
  const double clear_depth = std::min(static_cast<double>(scene.clear_depth), depth_max) / depth_max;
  f.color.assign(n, scene.clear_color);
  f.depth.assign(n, static_cast<uint32_t>(clear_depth * depth_max));
  f.probe.assign(n, PixelProbe{});
  std::vector<double> zbuf(n, clear_depth);

  for (const ScreenTri& tri : scene.tris) {
    ++f.counters.triangles;
    const ref::TriSetup s = ref::setup_triangle(tri, w, h);
    if (s.empty) continue;
    const TriState& st = tri.state;
    const Texture* tex = nullptr;
    if (st.textured && st.texture >= 0 && static_cast<size_t>(st.texture) < scene.textures.size() &&
        !scene.textures[static_cast<size_t>(st.texture)].levels.empty())
      tex = &scene.textures[static_cast<size_t>(st.texture)];
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = 1.0 / tri.v[k].w;

    for (int j = s.y0; j <= s.y1; ++j) {
      for (int i = s.x0; i <= s.x1; ++i) {
        if (!ref::covers(s, i, j)) continue;
        ++f.counters.fragments;
        const ref::Barycentric b = ref::barycentric(s, i + 0.5, j + 0.5);
        const size_t idx = static_cast<size_t>(j) * w + i;
        const double z = std::clamp(
            (b.l[0] * tri.v[0].z + b.l[1] * tri.v[1].z + b.l[2] * tri.v[2].z) / (b.l[0] + b.l[1] + b.l[2]), 0.0, 1.0);
        if (!depth_passes(st.depth_func, z, zbuf[idx])) continue;

        // Rational linear interpolation: A = sum(l_k q_k A_k) / sum(l_k q_k) (the scale of l cancels).
        double qs = 0, dqx = 0, dqy = 0;
        for (int k = 0; k < 3; ++k) {
          qs += b.l[k] * q[k];
          dqx += b.dx[k] * q[k];
          dqy += b.dy[k] * q[k];
        }
        auto persp = [&](auto attr) {
          double s_ = 0;
          for (int k = 0; k < 3; ++k) s_ += b.l[k] * q[k] * attr(tri.v[k]);
          return s_ / qs;
        };
        ref::Rgba color;
        if (st.gouraud) {
          color = {persp([](const ScreenVertex& v) { return v.r; }), persp([](const ScreenVertex& v) { return v.g; }),
                   persp([](const ScreenVertex& v) { return v.b; }), persp([](const ScreenVertex& v) { return v.a; })};
        } else {
          color = {tri.v[0].r, tri.v[0].g, tri.v[0].b, tri.v[0].a};
        }

        PixelProbe probe;
        if (tex) {
          const double u = persp([](const ScreenVertex& sv) { return sv.u; });
          const double v = persp([](const ScreenVertex& sv) { return sv.v; });
          // d(u)/dx = (d(u q)/dx - u dq/dx) / q, with u q and q affine in screen space.
          double duq_x = 0, duq_y = 0, dvq_x = 0, dvq_y = 0;
          for (int k = 0; k < 3; ++k) {
            duq_x += b.dx[k] * q[k] * tri.v[k].u;
            duq_y += b.dy[k] * q[k] * tri.v[k].u;
            dvq_x += b.dx[k] * q[k] * tri.v[k].v;
            dvq_y += b.dy[k] * q[k] * tri.v[k].v;
          }
          const double ux = (duq_x - u * dqx) / qs, uy = (duq_y - u * dqy) / qs;
          const double vx = (dvq_x - v * dqx) / qs, vy = (dvq_y - v * dqy) / qs;
          const double rho = std::max(std::hypot(ux, vx), std::hypot(uy, vy));
          const double lod = rho > 0 ? std::clamp(std::log2(rho), kMinLod, kMaxLod) : kMinLod;
          const bool finite = std::isfinite(u) && std::isfinite(v);
          const ref::Sample smp =
              ref::sample_texture(*tex, st.filter, st.wrap_u, st.wrap_v, finite ? u : 0, finite ? v : 0, lod);
          if (st.combine == Combine::Modulate) {
            for (int c = 0; c < 4; ++c) color[c] *= smp.color[c];
          } else {
            color = smp.color;
          }
          probe.covered = true;
          probe.u = u;
          probe.v = v;
          probe.level = smp.level;
          probe.lod = lod;
          probe.mesh = tri.mesh;
        }
        f.color[idx] = to_rgb565(color);
        f.probe[idx] = probe;
        ++f.counters.pixels_written;
        if (st.depth_write) {
          zbuf[idx] = z;
          f.depth[idx] = static_cast<uint32_t>(std::nearbyint(z * depth_max));
        }
      }
    }
  }
  return f;
}

std::vector<uint32_t> ref_coverage_count(const ScreenScene& scene) {
  const int w = scene.width, h = scene.height;
  std::vector<uint32_t> count(static_cast<size_t>(std::max(w, 0)) * static_cast<size_t>(std::max(h, 0)), 0);
  for (const ScreenTri& tri : scene.tris) {
    const ref::TriSetup s = ref::setup_triangle(tri, w, h);
    if (s.empty) continue;
    for (int j = s.y0; j <= s.y1; ++j)
      for (int i = s.x0; i <= s.x1; ++i)
        if (ref::covers(s, i, j)) ++count[static_cast<size_t>(j) * w + i];
  }
  return count;
}

}  // namespace htx
