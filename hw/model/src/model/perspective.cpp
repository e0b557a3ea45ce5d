#include "htx/model/perspective.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

namespace htx::model {

namespace {

std::array<i128, 3> vertex_values(const fw::TriangleRecord& r, i128 (*get)(const fw::VertexRecord&)) {
  return {get(r.v[0]), get(r.v[1]), get(r.v[2])};
}

// Reciprocals of span lengths 1..64 for SUBDIV's linear steps: round(2^16 / L).
int64_t inverse_length(int64_t len) { return ((int64_t{1} << 17) + len) / (2 * len); }

}  // namespace

int64_t divfree_exact_index(i128 num, i128 q, unsigned grid_bits, unsigned level, unsigned coord_bits) {
  if (q < 1) q = 1;
  // x = 2^f U / (Q 2^L) in grid cells; cell j holds x - 2^-(P+1) in [j, j+1), P = coord_bits.
  const i128 n = mul_checked(num, static_cast<i128>(1) << (grid_bits + coord_bits + 1)) -
                 mul_checked(q, static_cast<i128>(1) << level);
  return static_cast<int64_t>(floor_div(n, mul_checked(q, static_cast<i128>(1) << (level + coord_bits + 1))));
}

TriangleUnit::TriangleUnit(const fw::TriangleRecord& rec, const TriState& state, const ModelConfig& cfg, int width,
                           int height, const Log2Unit* log2_unit, unsigned top_level)
    : cfg_(cfg), state_(state), log2_(log2_unit), top_level_(top_level) {
  setup_ = setup_coverage(rec, width, height);
  if (setup_.empty) return;
  setup_recip_ = {cfg.recip_table_bits, cfg.recip_guard_bits, cfg.recip_width, cfg.setup_nr_steps};
  pixel_nr_ = setup_recip_;
  pixel_nr_.steps = cfg.pixel_nr_steps;
  pixel_lut_ = setup_recip_;
  pixel_lut_.steps = 0;
  const Reciprocal inv = reciprocal(setup_recip_, static_cast<u128>(setup_.det));
  const DetReciprocal d{inv.value, inv.shift};
  const unsigned gf = cfg.grad_frac_bits;
  const fw::TriangleRecord& r = setup_.rec;
  z_ = make_plane(setup_, vertex_values(r, [](const fw::VertexRecord& v) -> i128 { return v.z; }), d, gf);
  q_ = make_plane(setup_, vertex_values(r, [](const fw::VertexRecord& v) -> i128 { return v.q; }), d, gf);
  uq_ = make_plane(setup_, vertex_values(r, [](const fw::VertexRecord& v) -> i128 { return v.uq; }), d, gf);
  vq_ = make_plane(setup_, vertex_values(r, [](const fw::VertexRecord& v) -> i128 { return v.vq; }), d, gf);
  for (unsigned c = 0; c < 4; ++c) {
    std::array<i128, 3> ch{};
    for (int i = 0; i < 3; ++i) {
      ch[i] = (r.v[i].rgba >> (8 * c)) & 0xFF;
      if (cfg.perspective_color) ch[i] *= r.v[i].q;  // 8 x q_bits multiply at setup
    }
    color_[c] = make_plane(setup_, ch, d, gf);
  }
  // AFFINE interpolates the vertex texel coordinates themselves: u_i = uq_i / q_i from the shared
  // reciprocal unit at setup (three divisions per axis).
  std::array<i128, 3> ua{}, va{};
  for (int i = 0; i < 3; ++i) {
    ua[i] = divide(r.v[i].uq, r.v[i].q, setup_recip_);
    va[i] = divide(r.v[i].vq, r.v[i].q, setup_recip_);
  }
  ua_ = make_plane(setup_, ua, d, gf);
  va_ = make_plane(setup_, va, d, gf);
  grid_bits_ = state.filter == Filter::Nearest ? 0 : cfg.divfree_frac_bits;
  const i128 g[6] = {uq_.gx, uq_.gy, vq_.gx, vq_.gy, q_.gx, q_.gy};
  lod_shift_ = lod_gradient_shift(g, cfg.lod_grad_bits);
  for (int i = 0; i < 6; ++i) lod_grad_[i] = g[i] >> lod_shift_;
  // Estimate: edge and determinant arithmetic, one division for 1/det, 6 for the affine vertex
  // coordinates, then 9 planes x 2 gradients through one multiplier pair.
  setup_cycles_ = 8 + 7 * uint64_t{cfg.recip_issue_interval} + 18;
}

int64_t TriangleUnit::divide(i128 num, i128 q, const RecipParams& p) const {
  if (q < 1) q = 1;  // cannot happen inside a triangle with positive vertex q; defined anyway
  return divide_fixed(p, num, q, cfg_.texcoord_frac_bits);
}

uint32_t TriangleUnit::depth_at(int64_t px, int64_t py) const {
  const i128 z = shift_round(z_.at(px, py), static_cast<int>(cfg_.grad_frac_bits));
  const i128 top = (i128{1} << cfg_.z_bits) - 1;
  return static_cast<uint32_t>(z < 0 ? 0 : (z > top ? top : z));
}

Rgba8 TriangleUnit::color_at(int64_t px, int64_t py) const {
  uint8_t ch[4];
  for (int c = 0; c < 4; ++c) {
    const i128 a = cfg_.perspective_color
                       ? static_cast<i128>(divide_fixed(pixel_nr_, color_[c].at(px, py),
                                                        std::max<i128>(q_.at(px, py), 1), 0))
                       : shift_round(color_[c].at(px, py), static_cast<int>(cfg_.grad_frac_bits));
    ch[c] = static_cast<uint8_t>(a < 0 ? 0 : (a > 255 ? 255 : a));
  }
  return {ch[0], ch[1], ch[2], ch[3]};
}

Rgba8 TriangleUnit::flat_color() const {
  const uint32_t c = setup_.rec.v[0].rgba;  // vertex 0 is never reordered
  return {static_cast<uint8_t>(c), static_cast<uint8_t>(c >> 8), static_cast<uint8_t>(c >> 16),
          static_cast<uint8_t>(c >> 24)};
}

int32_t TriangleUnit::lod_at(const Log2Unit& unit, int64_t px, int64_t py, int64_t u, int64_t v) const {
  LodInputs in;
  in.q = std::max<i128>(q_.at(px, py), 1);
  in.gux = lod_grad_[0];
  in.guy = lod_grad_[1];
  in.gvx = lod_grad_[2];
  in.gvy = lod_grad_[3];
  in.gqx = lod_grad_[4];
  in.gqy = lod_grad_[5];
  in.grad_shift = lod_shift_;
  in.u = u;
  in.v = v;
  in.tex_frac_bits = cfg_.texcoord_frac_bits;
  return compute_lod(unit, in, cfg_.lod_frac_bits);
}

void TriangleUnit::span_coords(int y, int x0, int x1, Method method, SpanCoords* out) const {
  const size_t n = static_cast<size_t>(x1 - x0 + 1);
  out->u.resize(n);
  out->v.resize(n);
  out->divfree_steps.assign(n, 0);
  out->divfree_capped.assign(n, 0);
  out->cycles = 0;
  const int64_t py = 256 * int64_t{y} + 128;
  switch (method) {
    case Method::Affine:
      span_affine(py, x0, x1, out);
      out->cycles = n + 1;
      return;
    case Method::RecipLut:
      span_divide(py, x0, x1, pixel_lut_, out);
      out->cycles = n + 1;
      return;
    case Method::RecipNr:
      span_divide(py, x0, x1, pixel_nr_, out);
      out->cycles = n * cfg_.recip_issue_interval + 1;
      return;
    case Method::Subdiv:
    case Method::Quadratic:
      span_subdiv(py, x0, x1, method == Method::Quadratic, out);
      return;
    case Method::DivFree:
      span_divfree(py, x0, x1, out);
      return;
    case Method::Auto:
      break;
  }
  throw std::logic_error("span_coords: AUTO must be resolved before the raster unit");
}

void TriangleUnit::span_affine(int64_t py, int x0, int x1, SpanCoords* out) const {
  const int gf = static_cast<int>(cfg_.grad_frac_bits);
  const int64_t px0 = 256 * int64_t{x0} + 128;
  i128 au = ua_.at(px0, py), av = va_.at(px0, py);
  const i128 su = 256 * ua_.gx, sv = 256 * va_.gx;
  for (size_t k = 0; k < out->u.size(); ++k) {
    out->u[k] = static_cast<int64_t>(shift_round(au, gf));
    out->v[k] = static_cast<int64_t>(shift_round(av, gf));
    au += su;
    av += sv;
  }
}

void TriangleUnit::span_divide(int64_t py, int x0, int x1, const RecipParams& p, SpanCoords* out) const {
  const int64_t px0 = 256 * int64_t{x0} + 128;
  i128 q = q_.at(px0, py), u = uq_.at(px0, py), v = vq_.at(px0, py);
  const i128 sq = 256 * q_.gx, su = 256 * uq_.gx, sv = 256 * vq_.gx;
  for (size_t k = 0; k < out->u.size(); ++k) {
    // One reciprocal of q per pixel serves both axes (divide_fixed recomputes it for v only
    // because the model has no state; the value is the same).
    out->u[k] = divide(u, q, p);
    out->v[k] = divide(v, q, p);
    q += sq;
    u += su;
    v += sv;
  }
  (void)x1;
}

void TriangleUnit::span_subdiv(int64_t py, int x0, int x1, bool quadratic, SpanCoords* out) const {
  const int n = static_cast<int>(state_.subdiv_n);
  auto exact = [&](int x, int64_t* u, int64_t* v) {
    const int64_t px = 256 * int64_t{x} + 128;
    const i128 q = q_.at(px, py);
    *u = divide(uq_.at(px, py), q, pixel_nr_);
    *v = divide(vq_.at(px, py), q, pixel_nr_);
  };
  uint64_t divisions = 0;
  for (int xa = x0; xa <= x1; xa += n) {
    const int xb = std::min(xa + n, x1);
    int64_t ua, va, ub, vb;
    exact(xa, &ua, &va);
    ++divisions;
    const size_t ka = static_cast<size_t>(xa - x0);
    out->u[ka] = ua;
    out->v[ka] = va;
    if (xb == xa) break;
    exact(xb, &ub, &vb);
    const int64_t len = xb - xa;
    if (!quadratic || len < 2) {
      // Linear between the exact points: a step with 8 extra fraction bits from a 64-entry
      // reciprocal-of-length table, accumulated (j * step).
      const int64_t inv = inverse_length(len);
      const i128 du = shift_round(static_cast<i128>(ub - ua) * inv, 8);
      const i128 dv = shift_round(static_cast<i128>(vb - va) * inv, 8);
      for (int64_t j = 1; j < len; ++j) {
        out->u[ka + static_cast<size_t>(j)] = ua + static_cast<int64_t>(shift_round(du * j, 8));
        out->v[ka + static_cast<size_t>(j)] = va + static_cast<int64_t>(shift_round(dv * j, 8));
      }
    } else {
      // QUADRATIC (model only): the parabola through the exact values at both ends and at the
      // midpoint h, evaluated exactly and rounded (Lagrange form over h L (L - h)).
      const int64_t h = len / 2;
      int64_t um, vm;
      exact(xa + static_cast<int>(h), &um, &vm);
      ++divisions;
      const i128 den = static_cast<i128>(h) * len * (len - h);
      for (int64_t j = 1; j < len; ++j) {
        const i128 c0 = static_cast<i128>(j - h) * (j - len) * (len - h);
        const i128 c1 = -static_cast<i128>(j) * (j - len) * len;
        const i128 c2 = static_cast<i128>(j) * (j - h) * h;
        const i128 nu = c0 * ua + c1 * um + c2 * ub;
        const i128 nv = c0 * va + c1 * vm + c2 * vb;
        out->u[ka + static_cast<size_t>(j)] = static_cast<int64_t>(floor_div(2 * nu + den, 2 * den));
        out->v[ka + static_cast<size_t>(j)] = static_cast<int64_t>(floor_div(2 * nv + den, 2 * den));
      }
    }
    if (xb == x1) {
      const size_t kb = static_cast<size_t>(xb - x0);
      out->u[kb] = ub;
      out->v[kb] = vb;
      ++divisions;
      break;
    }
  }
  out->cycles = out->u.size() + divisions * cfg_.recip_issue_interval + 1;
}

int64_t TriangleUnit::grid_coord(int64_t j, unsigned level) const {
  // The centre of grid cell j: (j + 1/2) 2^(level - f) level-0 texels, as a texel coordinate.
  return (2 * j + 1) * (int64_t{1} << (static_cast<int>(cfg_.texcoord_frac_bits + level) - static_cast<int>(grid_bits_) - 1));
}

void TriangleUnit::span_divfree(int64_t py, int x0, int x1, SpanCoords* out) const {
  const unsigned f = grid_bits_;
  const unsigned tf = cfg_.texcoord_frac_bits;
  const int64_t cap = cfg_.divfree_cap;
  const int64_t px0 = 256 * int64_t{x0} + 128;
  const int64_t row = py >> 8;
  i128 q = q_.at(px0, py), u = uq_.at(px0, py), v = vq_.at(px0, py);
  const i128 sq = 256 * q_.gx, su = 256 * uq_.gx, sv = 256 * vq_.gx;
  // DIVFREE's only divisions, the RECIP_NR divider's (pixel_nr_steps): the coordinate U / Q with TF
  // fraction bits; one reciprocal of Q serves both axes.
  const auto divided = [&](i128 num) { return divide(num, q, pixel_nr_); };
  // The triangle's first pixel is seeded by one division. The same reciprocal of Q also gives the
  // coordinate's derivatives there, (g_U 2^TF - c g_Q) / Q per subpixel along x and y (TF units per
  // pixel, 16 fraction bits), which start the span-start predictor; the seed's coordinate also serves
  // the first span's level choice.
  int64_t seed_u = 0, seed_v = 0;
  int64_t seed_ux = 0, seed_uy = 0, seed_vx = 0, seed_vy = 0;
  if (!df_started_) {
    seed_u = divided(u);
    seed_v = divided(v);
    // A derivative beyond twice the coordinate range per pixel predicts nothing: the numerator
    // saturates at that many TF units times Q.
    const i128 limit = mul_checked(static_cast<i128>(1) << (cfg_.uv_int_bits + tf + 1), q);
    auto derivative = [&](i128 g_num, i128 g_q, int64_t c) {
      const i128 num = mul_checked(256, mul_checked(g_num, static_cast<i128>(1) << tf) - mul_checked(c, g_q));
      return divide_fixed(pixel_nr_, std::clamp<i128>(num, -limit, limit), q, 16);
    };
    seed_ux = derivative(uq_.gx, q_.gx, seed_u);
    seed_uy = derivative(uq_.gy, q_.gy, seed_u);
    seed_vx = derivative(vq_.gx, q_.gx, seed_v);
    seed_vy = derivative(vq_.gy, q_.gy, seed_v);
  }
  // Bilinear and trilinear track on the grid of the mip level the LOD unit picks at the span's
  // first pixel (from the previous span's grid position; the first span from the seed division),
  // so the steps per pixel stay near 2^f whatever the minification. (Bilinear still samples level 0;
  // its coordinate is then as coarse as the minification.) A level change rescales the carried
  // index, slope and row movement. Nearest always tracks whole level-0 texels: it must find the
  // exact texel.
  unsigned level = df_level_;
  if (state_.filter != Filter::Nearest && log2_ != nullptr) {
    const int64_t cu = df_started_ ? grid_coord(df_ju_, df_level_) : seed_u;
    const int64_t cv = df_started_ ? grid_coord(df_jv_, df_level_) : seed_v;
    const int32_t lod = lod_at(*log2_, px0, py, cu, cv);
    const int64_t l = lod == INT32_MIN ? 0 : (lod >> cfg_.lod_frac_bits);
    level = static_cast<unsigned>(std::clamp<int64_t>(l, 0, top_level_));
    if (df_started_ && level != df_level_) {
      auto rescale = [&](int64_t j) {
        return level > df_level_ ? j >> (level - df_level_) : j * (int64_t{1} << (df_level_ - level));
      };
      df_ju_ = rescale(df_ju_);
      df_jv_ = rescale(df_jv_);
      df_row_u_ = rescale(df_row_u_);
      df_row_v_ = rescale(df_row_v_);
      df_slope_u_ = rescale(df_slope_u_);
      df_slope_v_ = rescale(df_slope_v_);
    }
    df_level_ = level;
  }
  out->divfree_level = level;
  // Cell boundaries sit half a coordinate ulp above the grid lines (P = TF + L - f fraction bits
  // of a cell), so DIVFREE picks the texel nearest sampling picks for the exact quotient rounded to
  // the texel-coordinate precision, exact ties included. A divided coordinate c (TF fraction bits
  // of level-0 texels, i.e. P bits of a cell) lies in cell (c - 1) >> P: the sampler's nearest rule
  // on the cell grid.
  const unsigned p_bits = tf + level - f;
  const auto cell_of = [p_bits](int64_t coord) { return (coord - 1) >> p_bits; };
  const auto exact_u = [&] { return divfree_exact_index(u, q, f, level, p_bits); };
  const auto exact_v = [&] { return divfree_exact_index(v, q, f, level, p_bits); };
  // A span's first pixel is predicted from the previous span's first pixel by a plane in cells:
  // j_a + (dy * row + dx * slope) with the movement per row at fixed x and per pixel along x (both
  // 16 fraction bits), dy and dx the distance in rows and pixels between the two span starts.
  const int64_t dx = x0 - df_x0_, dy = row - df_row_;
  auto plane_step = [dx, dy](int64_t per_row, int64_t per_pixel) {
    return static_cast<int64_t>(shift_round(static_cast<i128>(dy) * per_row + static_cast<i128>(dx) * per_pixel, 16));
  };
  int64_t ju = 0, jv = 0, du = 0, dv = 0;
  if (df_started_) {
    ju = df_ju_ + plane_step(df_row_u_, df_slope_u_);
    jv = df_jv_ + plane_step(df_row_v_, df_slope_v_);
  } else {
    ju = cell_of(seed_u);
    jv = cell_of(seed_v);
  }
  const size_t n = out->u.size();
  const size_t slope_to = std::min<size_t>(n - 1, 64);  // the slope spans at most the first 64 pixels
  int64_t first_ju = 0, first_jv = 0, slope_ju = 0, slope_jv = 0;
  uint64_t cycles = 1;
  // Move j toward the exact index one grid step at a time, at most `cap` steps: identical to
  // reference 004's loop "while N < 0: j -= 1; while M >= 0: j += 1" on the integer conditions
  // of divfree_exact_index (N and M step by constants in x and by multiples of Q in j).
  auto track = [cap](int64_t target, int64_t* j) {
    const int64_t d = target - *j;
    const int64_t s = std::min(d < 0 ? -d : d, cap);
    *j += d < 0 ? -s : s;
    return s;
  };
  for (size_t k = 0; k < n; ++k) {
    // Each pixel after the first starts from the previous index plus the previous movement (one
    // adder; the indices of a span are close to linear in x, so the grid steps only cover the
    // curvature).
    if (k > 0) {
      ju += du;
      jv += dv;
    }
    const int64_t prev_u = ju - du, prev_v = jv - dv;  // the previous pixel's final index
    const int64_t target_u = exact_u(), target_v = exact_v();
    const int64_t steps_u = track(target_u, &ju), steps_v = track(target_v, &jv);
    out->divfree_steps[k] = static_cast<uint32_t>(steps_u + steps_v);
    cycles += static_cast<uint64_t>(std::max<int64_t>(1, std::max(steps_u, steps_v)));  // axes step in parallel
    if (ju != target_u || jv != target_v) {
      // The cap stopped the walk: the pixel takes the divided value on the stopped axis (one
      // division; its reciprocal of Q would serve both axes) and the walk goes on from there, so
      // the pixel's error is the divider's and nothing propagates.
      if (ju != target_u) ju = cell_of(divided(u));
      if (jv != target_v) jv = cell_of(divided(v));
      out->divfree_capped[k] = 1;
      cycles += cfg_.recip_issue_interval;
    }
    if (k == 0) {
      if (df_started_) {
        // The movement per row that, with the current slope, explains this span start:
        // ((j - j_a) 2^16 - dx * slope) / dy, the division by the row count from the reciprocal-of-
        // length table (a gap of more than 64 rows keeps the old value).
        if (dy <= 64) {
          const int64_t inv_dy = inverse_length(dy);
          auto per_row = [&](int64_t moved, int64_t per_pixel) {
            const i128 rest = static_cast<i128>(moved) * 65536 - static_cast<i128>(dx) * per_pixel;
            return static_cast<int64_t>(shift_round(rest * inv_dy, 16));
          };
          df_row_u_ = per_row(ju - df_ju_, df_slope_u_);
          df_row_v_ = per_row(jv - df_jv_, df_slope_v_);
        }
      } else {
        // The seed's derivatives in cells (16 fraction bits).
        df_row_u_ = static_cast<int64_t>(shift_round(seed_uy, static_cast<int>(p_bits)));
        df_row_v_ = static_cast<int64_t>(shift_round(seed_vy, static_cast<int>(p_bits)));
        df_slope_u_ = static_cast<int64_t>(shift_round(seed_ux, static_cast<int>(p_bits)));
        df_slope_v_ = static_cast<int64_t>(shift_round(seed_vx, static_cast<int>(p_bits)));
        df_started_ = true;
      }
      df_ju_ = ju;
      df_jv_ = jv;
      df_x0_ = x0;
      df_row_ = row;
      // The second pixel is predicted with the slope.
      du = static_cast<int64_t>(shift_round(df_slope_u_, 16));
      dv = static_cast<int64_t>(shift_round(df_slope_v_, 16));
    } else {
      du = ju - prev_u;
      dv = jv - prev_v;
    }
    if (k == 0) {
      first_ju = ju;
      first_jv = jv;
    }
    if (k == slope_to) {
      slope_ju = ju;
      slope_jv = jv;
    }
    out->u[k] = grid_coord(ju, level);
    out->v[k] = grid_coord(jv, level);
    q += sq;
    u += su;
    v += sv;
  }
  if (n >= 2) {
    // The span measures the slope over its first (up to 64) pixels, next to where the following
    // span starts, with the reciprocal-of-length table of SUBDIV.
    const int64_t len = static_cast<int64_t>(slope_to);
    df_slope_u_ = (slope_ju - first_ju) * inverse_length(len);
    df_slope_v_ = (slope_jv - first_jv) * inverse_length(len);
  }
  out->cycles = cycles;
  (void)x1;
}

Method auto_method(const ScreenTri& tri, const ModelConfig& cfg) {
  double wmin = tri.v[0].w, wmax = tri.v[0].w, du = 0;
  for (int i = 0; i < 3; ++i) {
    wmin = std::min(wmin, tri.v[i].w);
    wmax = std::max(wmax, tri.v[i].w);
    for (int j = 0; j < 3; ++j) {
      du = std::max(du, std::fabs(tri.v[i].u - tri.v[j].u));
      du = std::max(du, std::fabs(tri.v[i].v - tri.v[j].v));
    }
  }
  const double sr = wmin > 0 ? std::sqrt(wmax / wmin) : 1e30;
  const double err = du * (sr - 1) / (sr + 1);
  if (err <= 1.0 / 64 && cfg.has_method(Method::Affine)) return Method::Affine;
  if (cfg.has_method(Method::RecipNr)) return Method::RecipNr;
  if (cfg.has_method(Method::RecipLut)) return Method::RecipLut;
  return Method::Subdiv;
}

}  // namespace htx::model
