// The speed/accuracy study (`htx study`, docs/study.md): sweeps of scenes and perspective methods,
// each point rendered by the bit-accurate model against the float64 reference (accuracy) and timed
// on an engine that counts clocks (the Verilated GPU when built, else the model's estimate), with
// each method's predicted error bound from AUTO's chooser (docs/auto.md) beside the measurement.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "htx/model/config.hpp"
#include "htx/model/types.hpp"

namespace htx::study {

// AUTO with every choice compared, as if choosing cost the CPU nothing (docs/auto.md, "When
// choosing does not pay"): a point's method that parse_method does not take.
inline constexpr const char* kAutoCompared = "auto_compared";
// AUTO as the configuration prices it, or with every choice compared.
inline bool is_auto_method(const std::string& method) { return method == "auto" || method == kAutoCompared; }

// One rendering of the study: a scene with every triangle's method overridden (or AUTO within a
// tolerance), labelled with the sweep it belongs to and the value of the swept parameter.
struct Point {
  std::string sweep;      // ratio, range, subdiv, tradeoff
  std::string scene;      // built-in scene spec, e.g. "wsweep:r=10,du=256"
  std::string param;      // the swept parameter: r, du, n, tolerance, or "" (none)
  double value = 0;       // its value at this point
  std::string method;     // a name parse_method takes ("subdiv16", "auto", ...), or kAutoCompared
  double tolerance = 0;   // AUTO's tolerance in texels (is_auto_method only)
};

// The sweeps, in the order they run. `quick` keeps the ends and the middle of each swept range, and
// of the trade-off sweep `cube` at 1/16 texel (for tests and a first look); the full sweeps are what
// docs/study.md charts.
const std::vector<std::string>& sweep_names();
// Throws std::invalid_argument naming the accepted sweeps for an unknown name.
std::vector<Point> sweep_points(const std::string& sweep, bool quick);

// What a timing engine reports for one rendering.
struct Timing {
  uint64_t clocks = 0;      // raster clocks of drawing the scene
  uint64_t fragments = 0;   // fragments traversal produced
  int64_t mismatch = -1;    // pixels whose colour or depth differ from the model's frame; -1: not compared
};
// Renders the screen scene on a clock-counting engine; given the model's frame for the comparison.
using Timer = std::function<Timing(const ScreenScene& scene, const ModelConfig& config, const Frame& model)>;

struct Options {
  ModelConfig config;        // the model configuration (rtl_config's when the timer is the RTL)
  std::string config_name;   // its name, for the tables
  int width = 160, height = 120;
  Timer timer;               // empty: the model's estimate (docs/model.md §9)
  std::string clock_source = "estimate";
  bool quick = false;        // the points are sweep_points(..., true): the summary says so
};

struct Result {
  Point point;
  // Texel-coordinate error against ref over the pixels both frames texture (docs/metrics.md).
  double max_error = 0, p999_error = 0, rms_error = 0;
  uint64_t compared_pixels = 0;
  uint64_t coverage_diff_pixels = 0;
  uint64_t surface_diff_pixels = 0;  // textured in both by different meshes (not in the errors)
  // The largest predicted bound (AUTO's, docs/auto.md) of the methods the textured triangles were
  // drawn with; negative when a method has no bound (QUADRATIC) or nothing was textured; not finite
  // (and `finite` false) when a triangle's predicted bound is not.
  double bound = -1;
  // The largest ratio, over the compared pixels, of a pixel's error to the predicted bound of the
  // triangle that drew it in the model's frame (PixelProbe::tri): <= 1 where every pixel is within
  // its own triangle's bound. Negative when some textured triangle has no bound (as `bound`) or no
  // pixel was compared; NaN when a triangle's bound is not finite; +infinity where a pixel errs
  // under a bound of 0.
  double bound_ratio = -1;
  uint64_t clocks = 0, fragments = 0;
  double clocks_per_pixel = 0;  // clocks / fragments (0 when nothing was drawn)
  int64_t mismatch = -1;        // the timer's comparison with the model's frame
  uint64_t divfree_cap_hits = 0;
  std::string methods_used;     // "recip_nr:3 subdiv16:5": triangles per resolved method
  bool finite = true;           // every figure above is a finite number (bound_ratio aside)
};

Result run_point(const Point& point, const Options& options);

// What makes a point's accuracy figures not a clean measurement: no pixel compared (its errors of
// 0 say nothing), pixels textured in one frame only, or by another mesh in each (left out of the
// errors). Empty when there is none; otherwise e.g. "no pixel compared; coverage differs at 3 pixels".
std::string accuracy_problems(const Result& r);

// Where a method breaks down along a sweep: the first swept value at which its largest error
// exceeds `threshold` texels (none: it never does), and whether its predicted bound held at every
// point of the sweep (the behaviour past the breakdown stays bounded, finite and predicted).
struct Breakdown {
  std::string sweep, param, method;
  double threshold = 0;
  bool breaks = false;
  double at = 0;               // first value over the threshold, when breaks
  double worst_error = 0;      // largest error over the sweep
  // Every point of the sweep had a bound for every textured triangle (false once one has none).
  bool has_bound = true;
  // Largest Result::bound_ratio over the sweep's points (per pixel, against the pixel's own
  // triangle's bound): -1 once a point has no bound; NaN once a point's bound is not finite.
  double worst_bound_ratio = 0;
  // Every point had a finite bound for every triangle and every pixel was within its triangle's.
  bool bound_holds = true;
  bool finite = true;
};
std::vector<Breakdown> find_breakdowns(const std::vector<Result>& results, double threshold);

// CSV with a header row; one line per result, in order.
void write_csv(std::ostream& out, const std::vector<Result>& results);
// A Markdown summary: per sweep a breakdown table, and the speed/accuracy table of the trade-off
// sweep; a quick run, the points the timer's frame differs at, and the points with accuracy_problems
// are said first.
std::string summary_markdown(const std::vector<Result>& results, const Options& options);

// Writes DIR/<chart>.dat and DIR/<chart>.gp for each chart the results allow, and returns the
// scripts' file names. Running `gnuplot NAME.gp` in DIR draws NAME.svg.
std::vector<std::string> write_chart_scripts(const std::string& dir, const std::vector<Result>& results,
                                             const Options& options);

}  // namespace htx::study
