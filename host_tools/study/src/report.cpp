// The study's tables: CSV of every point, breakdowns along the sweeps, and a Markdown summary.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

#include "htx/study/study.hpp"

namespace htx::study {

namespace {

// SUBDIV's sweep varies the method's own parameter: its points form one series.
std::string series_of(const Result& r) { return r.point.sweep == "subdiv" ? "subdiv" : r.point.method; }

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string num(double v, const char* format = "%.4g") {
  char text[48];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string fraction_name(double t) {
  if (t >= 1) return num(t, "%g");
  return "1/" + num(1 / t, "%g");
}

}  // namespace

std::vector<Breakdown> find_breakdowns(const std::vector<Result>& results, double threshold) {
  std::vector<Breakdown> out;
  std::map<std::pair<std::string, std::string>, size_t> index;
  for (const Result& r : results) {
    if (r.point.param.empty() || r.point.param == "tolerance") continue;
    const auto key = std::make_pair(r.point.sweep, series_of(r));
    auto it = index.find(key);
    if (it == index.end()) {
      it = index.emplace(key, out.size()).first;
      Breakdown b;
      b.sweep = r.point.sweep;
      b.param = r.point.param;
      b.method = key.second;
      b.threshold = threshold;
      out.push_back(b);
    }
    Breakdown& b = out[it->second];
    // The sweeps run in ascending order of their parameter, so the first point over is the lowest.
    if (!b.breaks && r.max_error > threshold) {
      b.breaks = true;
      b.at = r.point.value;
    }
    b.worst_error = std::max(b.worst_error, r.max_error);
    // Once a point has no bound (QUADRATIC), the sweep has none: a later point's does not replace it.
    if (b.has_bound) {
      if (r.bound < 0) {
        b.has_bound = false;
        b.bound_holds = false;
        b.worst_bound_ratio = -1;
      } else if (!std::isfinite(r.bound) || std::isnan(r.bound_ratio)) {
        b.bound_holds = false;  // a bound that is not a number holds nothing
        b.worst_bound_ratio = std::numeric_limits<double>::quiet_NaN();
      } else if (r.bound_ratio >= 0) {  // (negative: no pixel compared, which the summary flags)
        if (!std::isnan(b.worst_bound_ratio)) b.worst_bound_ratio = std::max(b.worst_bound_ratio, r.bound_ratio);
        b.bound_holds = b.bound_holds && r.bound_ratio <= 1;
      }
    }
    b.finite = b.finite && r.finite;
  }
  return out;
}

void write_csv(std::ostream& out, const std::vector<Result>& results) {
  out << "sweep,scene,param,value,method,tolerance,max_error,p999_error,rms_error,compared_pixels,"
         "coverage_diff_pixels,surface_diff_pixels,bound,bound_ratio,clocks,fragments,clocks_per_pixel,mismatch,divfree_cap_hits,methods_used,"
         "finite\n";
  for (const Result& r : results) {
    const Point& p = r.point;
    out << p.sweep << ',' << csv_field(p.scene) << ',' << p.param << ',' << num(p.value, "%g") << ',' << p.method
        << ',' << num(p.tolerance, "%g") << ',' << num(r.max_error, "%.6g") << ',' << num(r.p999_error, "%.6g")
        << ',' << num(r.rms_error, "%.6g") << ',' << r.compared_pixels << ',' << r.coverage_diff_pixels << ','
        << r.surface_diff_pixels << ',' << num(r.bound, "%.6g") << ',' << num(r.bound_ratio, "%.6g") << ',' << r.clocks << ',' << r.fragments << ',' << num(r.clocks_per_pixel, "%.6g")
        << ',' << r.mismatch << ',' << r.divfree_cap_hits << ',' << csv_field(r.methods_used) << ','
        << (r.finite ? 1 : 0) << '\n';
  }
}

std::string summary_markdown(const std::vector<Result>& results, const Options& options) {
  std::ostringstream md;
  if (options.quick)
    md << "**A quick run (`--quick`): only the ends and the middle of each sweep, and the trade-off on "
          "`cube` at 1/16 texel; not the full study.**\n\n";
  md << "Configuration `" << options.config_name << "`, " << options.width << "x" << options.height
     << ", clocks from " << options.clock_source << ". Errors are texel-coordinate errors against `ref` "
     << "(docs/metrics.md); bounds are AUTO's predictions (docs/auto.md), and each pixel's error is "
     << "taken against the bound of the triangle that drew it.\n";

  int64_t mismatched = 0;
  for (const Result& r : results) mismatched += r.mismatch > 0 ? 1 : 0;
  if (mismatched)
    md << "\n**" << mismatched << " point(s) where the timing engine's frame differs from the model's.**\n";
  std::ostringstream problems;
  size_t problem_points = 0;
  for (const Result& r : results) {
    const std::string why = accuracy_problems(r);
    if (why.empty()) continue;
    ++problem_points;
    problems << "- " << r.point.sweep << " `" << r.point.scene << "` " << r.point.method
             << (is_auto_method(r.point.method) ? " (" + fraction_name(r.point.tolerance) + ")" : "") << ": " << why
             << "\n";
  }
  if (problem_points)
    md << "\n**" << problem_points << " point(s) whose errors are not a clean measurement** (docs/metrics.md):\n\n"
       << problems.str();

  const std::vector<Breakdown> tight = find_breakdowns(results, 1.0 / 16);
  const std::vector<Breakdown> visible = find_breakdowns(results, 0.5);
  std::string sweep;
  for (size_t i = 0; i < tight.size(); ++i) {
    const Breakdown& t = tight[i];
    const Breakdown& v = visible[i];
    if (t.sweep != sweep) {
      sweep = t.sweep;
      md << "\n### Sweep `" << sweep << "` (swept: " << t.param << ")\n\n"
         << "| method | worst error | over 1/16 texel from " << t.param << " = | over 1/2 texel from " << t.param
         << " = | worst error / bound | bound holds | finite |\n|---|---|---|---|---|---|---|\n";
    }
    md << "| " << t.method << " | " << num(t.worst_error) << " | " << (t.breaks ? num(t.at, "%g") : "never")
       << " | " << (v.breaks ? num(v.at, "%g") : "never") << " | "
       << (!t.has_bound ? "no bound" : num(t.worst_bound_ratio, "%.3f")) << " | "
       << (!t.has_bound ? "no bound" : t.bound_holds ? "yes" : "**no**") << " | " << (t.finite ? "yes" : "**no**")
       << " |\n";
  }

  std::string scene;
  for (const Result& r : results) {
    if (r.point.sweep != "tradeoff") continue;
    if (r.point.scene != scene) {
      scene = r.point.scene;
      md << "\n### Trade-off on `" << scene << "`\n\n"
         << "| method | clocks / pixel | max error | p99.9 error | largest bound | worst error / bound | drawn with "
            "|\n|---|---|---|---|---|---|---|\n";
    }
    const std::string name = r.point.method == "auto" ? "auto (" + fraction_name(r.point.tolerance) + ")"
                             : r.point.method == kAutoCompared
                                 ? "auto, every choice compared (" + fraction_name(r.point.tolerance) + ")"
                                 : r.point.method;
    md << "| " << name << " | " << num(r.clocks_per_pixel, "%.2f") << " | " << num(r.max_error) << " | "
       << num(r.p999_error) << " | " << (r.bound < 0 ? "-" : num(r.bound)) << " | "
       << (r.bound < 0 || r.bound_ratio < 0 ? "-" : num(r.bound_ratio, "%.3f")) << " | " << r.methods_used << " |\n";
  }
  return md.str();
}

}  // namespace htx::study
