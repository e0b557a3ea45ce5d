// The speed/accuracy study's library (host_tools/study, `htx study`): its sweeps, that the model's
// measured errors on them stay within AUTO's predicted bounds, the breakdown finder, the CSV and the
// chart scripts. Clocks here are the model's estimate; tests/system runs `htx study` on the RTL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "htx/model/config.hpp"
#include "htx/study/study.hpp"

namespace {

using htx::study::Point;
using htx::study::Result;

htx::study::Options icebreaker_options() {
  htx::study::Options o;
  o.config = htx::model_config("icebreaker");
  o.config_name = "icebreaker";
  return o;
}

TEST(Study, SweepsRunInAscendingOrderOfTheirParameter) {
  for (const std::string& name : htx::study::sweep_names()) {
    for (bool quick : {true, false}) {
      const std::vector<Point> points = htx::study::sweep_points(name, quick);
      ASSERT_FALSE(points.empty()) << name;
      std::map<std::string, double> last;  // per method, the previous value
      for (const Point& p : points) {
        EXPECT_EQ(p.sweep, name);
        if (p.param.empty() || p.param == "tolerance") continue;
        const std::string series = name == "subdiv" ? "subdiv" : p.method;
        if (last.count(series)) {
          EXPECT_GT(p.value, last[series]) << name << " " << p.method;
        }
        last[series] = p.value;
      }
    }
  }
  EXPECT_THROW(htx::study::sweep_points("nosuch", true), std::invalid_argument);
}

// `--quick` keeps the ends and the middle of each swept range: three values per series, the first
// and the last of the full sweep among them.
TEST(Study, QuickSweepsKeepTheEndsAndTheMiddle) {
  for (const std::string& name : htx::study::sweep_names()) {
    std::map<std::string, std::vector<double>> full, quick;
    for (bool q : {false, true})
      for (const Point& p : htx::study::sweep_points(name, q)) {
        if (p.param.empty() || p.param == "tolerance") continue;
        (q ? quick : full)[name == "subdiv" ? "subdiv" : p.method].push_back(p.value);
      }
    for (const auto& [series, values] : quick) {
      ASSERT_EQ(values.size(), 3u) << name << " " << series;
      EXPECT_EQ(values.front(), full[series].front()) << name << " " << series;
      EXPECT_EQ(values.back(), full[series].back()) << name << " " << series;
    }
  }
}

// wsweep's AFFINE error is known exactly: du (sqrt(r) - 1) / (sqrt(r) + 1) at its worst pixel.
TEST(Study, AffineErrorFollowsTheExactFormulaOnWsweep) {
  const auto options = icebreaker_options();
  for (double r : {10.0, 1000.0}) {
    const Point p{"ratio", "wsweep:r=" + std::to_string(int(r)) + ",du=256", "r", r, "affine", 0};
    const Result res = htx::study::run_point(p, options);
    const double exact = 256 * (std::sqrt(r) - 1) / (std::sqrt(r) + 1);
    EXPECT_GT(res.max_error, 0.9 * exact) << r;
    EXPECT_LE(res.max_error, res.bound) << r;
    EXPECT_EQ(res.methods_used, "affine:1");
    EXPECT_GT(res.compared_pixels, 1000u);
  }
}

// Each method's measured error on the quick ratio, range and offset sweeps is within the bound AUTO
// predicts for it (QUADRATIC has none), and every figure is finite at the sweeps' extremes.
TEST(Study, MeasuredErrorsStayWithinThePredictedBounds) {
  const auto options = icebreaker_options();
  size_t bounded = 0;
  for (const char* sweep : {"ratio", "range", "offset"}) {
    for (const Point& p : htx::study::sweep_points(sweep, true)) {
      const Result r = htx::study::run_point(p, options);
      EXPECT_TRUE(r.finite) << p.scene << " " << p.method;
      EXPECT_EQ(r.coverage_diff_pixels, 0u) << p.scene << " " << p.method;
      EXPECT_EQ(r.surface_diff_pixels, 0u) << p.scene << " " << p.method;
      EXPECT_GT(r.clocks, 0u) << p.scene << " " << p.method;
      if (r.bound < 0) continue;
      ++bounded;
      EXPECT_LE(r.max_error, r.bound) << p.scene << " " << p.method;
      // Every pixel within the bound of the triangle that drew it.
      EXPECT_GE(r.bound_ratio, 0) << p.scene << " " << p.method;
      EXPECT_LE(r.bound_ratio, 1) << p.scene << " " << p.method;
    }
  }
  EXPECT_EQ(bounded, 45u);  // (3 + 3 + 3) values x 5 methods, all with a bound
}

// The bound check is per pixel: each pixel's error against the bound of the triangle that drew it
// (the model's probe names the triangle), not the scene's worst error against its loosest bound.
// On wsweep's one triangle the two are the same; on `floor` (116 triangles) SUBDIV's bound is 0.37
// (SUBDIV_4) and 5.0 texels (SUBDIV_16) on the triangles nearest the horizon, while pixels of
// triangles with bounds a hundred times smaller come far nearer their own (when written: 0.127
// against the scene-wide 0.0053, and 0.035 against 0.0006).
TEST(Study, TheBoundIsCheckedPerPixelAgainstItsOwnTriangle) {
  const auto options = icebreaker_options();
  const Result one = htx::study::run_point({"ratio", "wsweep:r=10,du=256", "r", 10, "affine", 0}, options);
  EXPECT_NEAR(one.bound_ratio, one.max_error / one.bound, 1e-12);
  for (const char* method : {"subdiv4", "subdiv16"}) {
    const Result many = htx::study::run_point({"tradeoff", "floor", "", 0, method, 0}, options);
    ASSERT_GT(many.compared_pixels, 1000u);
    EXPECT_GT(many.bound_ratio, 10 * many.max_error / many.bound) << method;
    EXPECT_LE(many.bound_ratio, 1) << method;
  }
}

TEST(Study, AutoStaysWithinItsToleranceOnTheCube) {
  const auto options = icebreaker_options();
  for (double tolerance : {1.0 / 64, 1.0 / 4}) {
    const Result r = htx::study::run_point({"tradeoff", "cube", "tolerance", tolerance, "auto", tolerance}, options);
    EXPECT_LE(r.bound, tolerance);
    EXPECT_LE(r.max_error, tolerance);
    EXPECT_FALSE(r.methods_used.empty());
  }
}

// "auto_compared" is AUTO with the choice priced as free: on `floor` at 1/16 texel the SoC's AUTO
// skips most choices (RECIP_NR), the compared one gives cheaper methods to some of those triangles,
// and both stay within the tolerance.
TEST(Study, AutoComparedComparesTheChoicesAutoSkips) {
  const auto options = icebreaker_options();
  const Result skipping = htx::study::run_point({"tradeoff", "floor", "tolerance", 0.0625, "auto", 0.0625}, options);
  const Result compared =
      htx::study::run_point({"tradeoff", "floor", "tolerance", 0.0625, "auto_compared", 0.0625}, options);
  const auto count_of = [](const std::string& used, const std::string& method) {
    const size_t at = used.find(method + ":");
    return at == std::string::npos ? 0 : std::stoi(used.substr(at + method.size() + 1));
  };
  EXPECT_GT(count_of(skipping.methods_used, "recip_nr"), count_of(compared.methods_used, "recip_nr"))
      << skipping.methods_used << " / " << compared.methods_used;
  EXPECT_LE(compared.clocks, skipping.clocks);
  for (const Result& r : {skipping, compared}) {
    EXPECT_LE(r.bound, 0.0625);
    EXPECT_LE(r.max_error, 0.0625);
  }
}

Result synthetic(const std::string& method, double value, double error, double bound) {
  Result r;
  r.point = {"ratio", "wsweep", "r", value, method, 0};
  r.max_error = error;
  r.bound = bound;
  r.bound_ratio = bound > 0 ? error / bound : -1;  // (one triangle)
  r.compared_pixels = 1000;
  return r;
}

TEST(Study, BreakdownIsTheFirstValueOverTheThreshold) {
  const std::vector<Result> results = {synthetic("affine", 1, 0.01, 0.1), synthetic("recip_nr", 1, 0.001, 0.01),
                                       synthetic("affine", 2, 0.2, 0.3),  synthetic("recip_nr", 2, 0.002, 0.01),
                                       synthetic("affine", 4, 0.9, 0.8),  synthetic("recip_nr", 4, 0.003, 0.01)};
  const auto b = htx::study::find_breakdowns(results, 0.1);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].method, "affine");
  EXPECT_TRUE(b[0].breaks);
  EXPECT_EQ(b[0].at, 2);
  EXPECT_DOUBLE_EQ(b[0].worst_error, 0.9);
  EXPECT_FALSE(b[0].bound_holds);  // 0.9 > 0.8 at r = 4
  EXPECT_DOUBLE_EQ(b[0].worst_bound_ratio, 0.9 / 0.8);
  EXPECT_EQ(b[1].method, "recip_nr");
  EXPECT_FALSE(b[1].breaks);
  EXPECT_TRUE(b[1].bound_holds);
}

// A point without a bound (QUADRATIC) leaves the sweep without one, whatever later points have; a
// bound that is not finite holds nothing; the summary prints whether the bound held.
TEST(Study, NoBoundIsStickyAndANonFiniteBoundDoesNotHold) {
  Result nan_bound = synthetic("recip_lut", 2, 0.01, std::numeric_limits<double>::infinity());
  nan_bound.bound_ratio = std::numeric_limits<double>::quiet_NaN();
  nan_bound.finite = false;
  const std::vector<Result> results = {synthetic("quadratic", 1, 0.01, -1), synthetic("quadratic", 2, 0.02, 0.1),
                                       synthetic("recip_lut", 1, 0.01, 0.1), nan_bound,
                                       synthetic("recip_lut", 4, 0.01, 0.1)};
  const auto b = htx::study::find_breakdowns(results, 0.1);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_FALSE(b[0].has_bound);
  EXPECT_EQ(b[0].worst_bound_ratio, -1);  // not the second point's 0.2
  EXPECT_FALSE(b[0].bound_holds);
  EXPECT_TRUE(b[1].has_bound);
  EXPECT_TRUE(std::isnan(b[1].worst_bound_ratio));
  EXPECT_FALSE(b[1].bound_holds);
  EXPECT_FALSE(b[1].finite);

  const std::string md = htx::study::summary_markdown(results, icebreaker_options());
  EXPECT_NE(md.find("| worst error / bound | bound holds | finite |"), std::string::npos) << md;
  EXPECT_NE(md.find("| quadratic | 0.02 | never | never | no bound | no bound | yes |"), std::string::npos) << md;
  EXPECT_NE(md.find("| recip_lut | 0.01 | never | never | nan | **no** | **no** |"), std::string::npos) << md;
}

// A point where nothing was compared (its errors of 0 say nothing), or where pixels were textured in
// one frame only or by another mesh in each, is listed in the summary; a quick run says so first.
TEST(Study, SummaryFlagsPointsThatCompareNothingOrDifferAndQuickRuns) {
  std::vector<Result> results = {synthetic("affine", 1, 0.5, 1), synthetic("affine", 2, 0, 1),
                                 synthetic("affine", 4, 0.5, 1)};
  EXPECT_EQ(htx::study::accuracy_problems(results[0]), "");
  results[1].compared_pixels = 0;
  results[2].coverage_diff_pixels = 3;
  results[2].surface_diff_pixels = 2;
  EXPECT_EQ(htx::study::accuracy_problems(results[1]), "no pixel compared");
  EXPECT_EQ(htx::study::accuracy_problems(results[2]),
            "textured in one frame only at 3 pixels; another mesh in each frame at 2 pixels");
  auto options = icebreaker_options();
  std::string md = htx::study::summary_markdown(results, options);
  EXPECT_NE(md.find("**2 point(s) whose errors are not a clean measurement**"), std::string::npos) << md;
  EXPECT_NE(md.find("- ratio `wsweep` affine: no pixel compared\n"), std::string::npos) << md;
  EXPECT_EQ(md.find("quick"), std::string::npos) << md;
  options.quick = true;
  md = htx::study::summary_markdown(results, options);
  EXPECT_EQ(md.rfind("**A quick run (`--quick`)", 0), 0u) << md;
}

TEST(Study, CsvHasOneQuotedRowPerResult) {
  std::vector<Result> results = {synthetic("affine", 10, 1.5, 2)};
  results[0].point.scene = "wsweep:r=10,du=256";
  results[0].methods_used = "affine:1";
  std::ostringstream out;
  htx::study::write_csv(out, results);
  std::istringstream in(out.str());
  std::string header, row, extra;
  ASSERT_TRUE(std::getline(in, header));
  ASSERT_TRUE(std::getline(in, row));
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header.rfind("sweep,scene,param,value,method,", 0), 0u);
  EXPECT_EQ(row.rfind("ratio,\"wsweep:r=10,du=256\",r,10,affine,", 0), 0u) << row;
  // As many fields as the header once the quoted comma is discounted.
  const auto commas = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
  EXPECT_EQ(commas(row) - 1, commas(header));
}

TEST(Study, ChartScriptsReadTheirDataAndDraw) {
  std::vector<Result> results;
  for (double r : {1.0, 10.0, 100.0})
    for (const char* m : {"affine", "recip_nr"}) results.push_back(synthetic(m, r, r * 0.01, 1));
  Result t = synthetic("affine", 0, 2, 3);
  t.point = {"tradeoff", "cube", "", 0, "affine", 0};
  t.clocks_per_pixel = 12.5;
  results.push_back(t);
  t.point = {"tradeoff", "cube", "tolerance", 0.0625, "auto", 0.0625};
  results.push_back(t);

  const std::string dir = ::testing::TempDir() + "htx_study_charts";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto scripts = htx::study::write_chart_scripts(dir, results, icebreaker_options());
  ASSERT_EQ(scripts, (std::vector<std::string>{"study_ratio.gp", "study_tradeoff_cube.gp"}));
  std::ifstream dat(dir + "/study_ratio.dat");
  std::stringstream text;
  text << dat.rdbuf();
  EXPECT_NE(text.str().find("# affine\n1 0.01\n10 0.1\n100 1\n"), std::string::npos) << text.str();
  // scripts/bootstrap installs gnuplot; the scripts must draw.
  for (const std::string& s : scripts) {
    const std::string command = "cd '" + dir + "' && gnuplot '" + s + "' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << s;
    const std::string svg = dir + "/" + s.substr(0, s.size() - 3) + ".svg";
    ASSERT_TRUE(std::filesystem::exists(svg)) << svg;
    EXPECT_GT(std::filesystem::file_size(svg), 1000u) << svg;
  }
}

}  // namespace
