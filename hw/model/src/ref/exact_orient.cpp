#include "exact_orient.hpp"

#include <cmath>
#include <limits>

namespace htx::ref {

namespace {

struct Expansion {
  double c[16];
  int n = 0;

  // Adds x exactly (Shewchuk's Grow-Expansion): components stay non-overlapping and ordered by
  // increasing magnitude, so the sign of the sum is the sign of the last non-zero component.
  void add(double x) {
    double q = x;
    for (int i = 0; i < n; ++i) {
      const double s = q + c[i];
      const double bv = s - q;
      const double err = (q - (s - bv)) + (c[i] - bv);
      c[i] = err;
      q = s;
    }
    c[n++] = q;
  }

  // Adds the exact product a*b (as a rounded product plus its fma-computed error).
  void add_product(double a, double b) {
    const double p = a * b;
    add(std::fma(a, b, -p));
    add(p);
  }

  int sign() const {
    for (int i = n - 1; i >= 0; --i)
      if (c[i] != 0) return c[i] > 0 ? 1 : -1;
    return 0;
  }
};

}  // namespace

int orient2d_sign(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (bx - ax) * (cy - ay);
  const double right = (by - ay) * (cx - ax);
  const double det = left - right;
  // Shewchuk's static bound for this evaluation order; outside it the rounded sign is the true one.
  constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
  const double bound = (3.0 + 16.0 * eps) * eps * (std::fabs(left) + std::fabs(right));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  // Exact: expand into six products (the ax*ay terms cancel) and sum them without rounding.
  Expansion e;
  e.add_product(bx, cy);
  e.add_product(-bx, ay);
  e.add_product(-ax, cy);
  e.add_product(-by, cx);
  e.add_product(by, ax);
  e.add_product(ay, cx);
  return e.sign();
}

}  // namespace htx::ref
