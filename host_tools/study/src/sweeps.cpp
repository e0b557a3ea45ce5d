// The study's sweeps (docs/study.md says what each shows).
#include <cstdio>
#include <stdexcept>

#include "htx/study/study.hpp"

namespace htx::study {

namespace {

std::string format_value(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// The methods each sweep compares: the cheap end (AFFINE), SUBDIV at short and long spans, the
// table alone, the table with Newton steps, the division-free walk, and QUADRATIC (model only).
const std::vector<std::string> kMethods = {"affine",    "subdiv4",  "subdiv16", "subdiv64",
                                           "recip_lut", "recip_nr", "divfree",  "quadratic"};
const std::vector<std::string> kQuickMethods = {"affine", "subdiv16", "recip_lut", "recip_nr", "divfree"};

void add_methods(std::vector<Point>& points, const Point& base, bool quick) {
  for (const std::string& m : quick ? kQuickMethods : kMethods) {
    Point p = base;
    p.method = m;
    points.push_back(p);
  }
}

// wsweep's depth ratio r = w_far / w_near: AFFINE's error grows as du (sqrt(r) - 1) / (sqrt(r) + 1).
std::vector<Point> ratio_points(bool quick) {
  const std::vector<double> ratios = quick ? std::vector<double>{1, 10, 1000}
                                           : std::vector<double>{1, 1.5, 2, 3, 5, 10, 20, 50, 100, 200, 500, 1000};
  std::vector<Point> points;
  for (double r : ratios)
    add_methods(points, {"ratio", "wsweep:r=" + format_value(r) + ",du=256", "r", r, "", 0}, quick);
  return points;
}

// wsweep's coordinate span du at a fixed depth ratio: the reciprocal's relative error times the
// coordinate's magnitude, so RECIP_LUT's error grows with du where RECIP_NR's stays small.
std::vector<Point> range_points(bool quick) {
  const std::vector<double> spans = quick ? std::vector<double>{16, 256, 4096}
                                          : std::vector<double>{16, 32, 64, 128, 256, 512, 1024, 2048, 4096};
  std::vector<Point> points;
  for (double du : spans)
    add_methods(points, {"range", "wsweep:r=2,du=" + format_value(du), "du", du, "", 0}, quick);
  return points;
}

// wrap's coordinates far from the origin (every wrap mode, tilted panels; the repeat panel's reach
// +offset, the mirror panel's -offset): the error should not grow with the offset, since the raster
// unit interpolates coordinates relative to a per-triangle offset.
std::vector<Point> offset_points(bool quick) {
  const std::vector<double> offsets = quick ? std::vector<double>{1, 256, 16384}
                                            : std::vector<double>{1, 16, 256, 1024, 4096, 16384};
  std::vector<Point> points;
  for (double o : offsets)
    add_methods(points, {"offset", "wrap:offset=" + format_value(o), "offset", o, "", 0}, quick);
  return points;
}

// SUBDIV's span length on the grazing floor: accuracy against the exact points' cost.
std::vector<Point> subdiv_points(bool quick) {
  const std::vector<int> spans = quick ? std::vector<int>{2, 16, 64} : std::vector<int>{2, 4, 8, 16, 32, 64};
  std::vector<Point> points;
  for (int n : spans) points.push_back({"subdiv", "floor", "n", double(n), "subdiv" + std::to_string(n), 0});
  return points;
}

// Every method, and AUTO at a range of tolerances, on whole scenes: clocks per pixel against error.
std::vector<Point> tradeoff_points(bool quick) {
  const std::vector<std::string> scenes = quick ? std::vector<std::string>{"cube"}
                                                : std::vector<std::string>{"floor", "cube", "tunnel"};
  const std::vector<double> tolerances = quick ? std::vector<double>{1.0 / 16}
                                               : std::vector<double>{1.0 / 256, 1.0 / 64, 1.0 / 16, 1.0 / 4, 1.0};
  std::vector<Point> points;
  for (const std::string& scene : scenes) {
    add_methods(points, {"tradeoff", scene, "", 0, "", 0}, quick);
    for (double t : tolerances) points.push_back({"tradeoff", scene, "tolerance", t, "auto", t});
    // AUTO with every choice compared: what the skip costs the raster unit.
    if (!quick)
      for (double t : tolerances) points.push_back({"tradeoff", scene, "tolerance", t, kAutoCompared, t});
  }
  return points;
}

}  // namespace

const std::vector<std::string>& sweep_names() {
  static const std::vector<std::string> names = {"ratio", "range", "offset", "subdiv", "tradeoff"};
  return names;
}

std::vector<Point> sweep_points(const std::string& sweep, bool quick) {
  if (sweep == "ratio") return ratio_points(quick);
  if (sweep == "range") return range_points(quick);
  if (sweep == "offset") return offset_points(quick);
  if (sweep == "subdiv") return subdiv_points(quick);
  if (sweep == "tradeoff") return tradeoff_points(quick);
  throw std::invalid_argument("unknown sweep '" + sweep + "': want ratio, range, offset, subdiv or tradeoff");
}

}  // namespace htx::study
