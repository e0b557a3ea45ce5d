// htx study: the speed/accuracy study (docs/study.md). Each sweep point is rendered by the model
// against ref for accuracy and timed on the Verilated GPU (or the model's estimate) for speed; the
// results go to a CSV, a Markdown summary and gnuplot charts.
#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "commands.hpp"
#include "frame_size.hpp"
#include "htx/model/file_out.hpp"
#include "htx/model/names.hpp"
#include "htx/study/study.hpp"
#include "output_path.hpp"
#if __has_include("htx/rtl/raster_engine.hpp")
#include "htx/rtl/raster_engine.hpp"
#define HTX_HAVE_RTL_ENGINE 1
#endif

namespace htx {

namespace {

struct StudyArgs {
  std::vector<std::string> sweeps;
  std::string config = "icebreaker";
  std::string size = "160x120";
  std::string clocks;
  std::string out_dir = "study-out";
  bool quick = false;
  bool no_charts = false;
};

study::Options make_options(const StudyArgs& a) {
  study::Options o;
  parse_size(a.size, o.width, o.height);
  o.config_name = a.config;
  o.quick = a.quick;
#ifdef HTX_HAVE_RTL_ENGINE
  const std::string clocks = a.clocks.empty() ? "rtl" : a.clocks;
#else
  const std::string clocks = a.clocks.empty() ? "estimate" : a.clocks;
#endif
  if (clocks == "estimate") {
    o.config = model_config(a.config);
    return o;
  }
#ifdef HTX_HAVE_RTL_ENGINE
  // The model runs with the configuration the RTL builds, so its frame is the RTL's (checked).
  o.config = rtl_config(a.config);
  o.clock_source = "rtl";
  o.timer = [](const ScreenScene& scene, const ModelConfig& config, const Frame& model) {
    RtlStats stats;
    const Frame frame = render_rtl(scene, config, &stats);
    return study::Timing{stats.cycles, stats.covered_pixels, static_cast<int64_t>(frame_mismatch_pixels(frame, model))};
  };
  return o;
#else
  throw std::invalid_argument("--clocks rtl: this build has no rtl engine (use --clocks estimate)");
#endif
}

void run_study(const StudyArgs& a) {
  const study::Options options = make_options(a);
  // Each sweep once, in the order first named (`htx study ratio ratio` would repeat its rows).
  std::vector<std::string> sweeps;
  for (const std::string& sweep : a.sweeps.empty() ? study::sweep_names() : a.sweeps)
    if (std::find(sweeps.begin(), sweeps.end(), sweep) == sweeps.end()) sweeps.push_back(sweep);
  std::vector<study::Point> points;
  for (const std::string& sweep : sweeps)
    for (const study::Point& p : study::sweep_points(sweep, a.quick))
      // (AUTO with every choice compared differs from AUTO only where the configuration prices choosing.)
      if (p.method == study::kAutoCompared
              ? options.config.auto_choice_cycles > 0
              : p.method == "auto" || options.config.has_method(parse_method(p.method).method))
        points.push_back(p);

  namespace fs = std::filesystem;
  fs::create_directories(a.out_dir);
  // The tables are checked before the points run (a full study is minutes of work); the charts'
  // files are the scripts' own and gnuplot reports them.
  const std::string csv_path = a.out_dir + "/study.csv", md_path = a.out_dir + "/study.md";
  require_output_files({&csv_path, &md_path});
  std::vector<study::Result> results;
  size_t mismatched = 0, not_finite = 0, unclean = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const study::Result r = study::run_point(points[i], options);
    const std::string problems = study::accuracy_problems(r);
    std::cout << "[" << i + 1 << "/" << points.size() << "] " << r.point.sweep << " " << r.point.scene << " "
              << r.point.method << (r.point.param == "tolerance" ? " " + std::to_string(r.point.tolerance) : "")
              << ": max error " << r.max_error << ", " << r.clocks_per_pixel << " clocks/pixel"
              << (r.mismatch > 0 ? ", FRAME DIFFERS FROM THE MODEL'S" : "")
              << (problems.empty() ? "" : ", NOT A CLEAN MEASUREMENT: " + problems) << std::endl;
    mismatched += r.mismatch > 0 ? 1 : 0;
    not_finite += r.finite ? 0 : 1;
    unclean += problems.empty() ? 0 : 1;
    results.push_back(r);
  }

  std::ostringstream csv;
  study::write_csv(csv, results);
  write_file(csv_path, csv.str());
  const std::string summary = study::summary_markdown(results, options);
  write_file(md_path, summary);
  std::cout << "\n" << summary << "\nresults -> " << csv_path << ", " << md_path << "\n";

  const std::vector<std::string> scripts = study::write_chart_scripts(a.out_dir, results, options);
  if (a.no_charts) {
    std::cout << "chart scripts (not run) -> " << a.out_dir << "\n";
  } else {
    for (const std::string& script : scripts) {
      // In the output directory: the scripts name their data and their SVG relative to it.
      const ChildStatus gnuplot = run_child({"gnuplot", script}, a.out_dir);
      if (gnuplot.spawn_error == ENOENT) {
        std::cout << "gnuplot not found: chart scripts written to " << a.out_dir << " but not drawn\n";
        break;
      }
      if (!gnuplot.succeeded())
        throw std::runtime_error("gnuplot failed on " + a.out_dir + "/" + script + " (" + gnuplot.describe() + ")");
      std::cout << "chart -> " << a.out_dir << "/" << fs::path(script).replace_extension(".svg").string() << "\n";
    }
  }
  if (mismatched)
    throw std::runtime_error(std::to_string(mismatched) + " point(s) where the RTL frame differs from the model's");
  if (not_finite) throw std::runtime_error(std::to_string(not_finite) + " point(s) with a figure that is not finite");
  // (A point with no pixel compared reports errors of 0; pixels textured in one frame only, or by
  // another mesh in each, are left out of its errors: study.md lists them.)
  if (unclean)
    throw std::runtime_error(std::to_string(unclean) +
                             " point(s) whose errors are not a clean measurement (no pixel compared, or pixels "
                             "textured in one frame only or by another mesh): listed in " + md_path);
}

}  // namespace

void register_study(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  auto* cmd = app.add_subcommand("study", "The speed/accuracy study: sweeps of methods and scenes, tables and charts");
  cmd->add_option("sweep", args->sweeps, "sweeps to run: ratio, range, offset, subdiv, tradeoff (default: all)")
      ->check(CLI::IsMember(study::sweep_names()));
  cmd->add_option("--config", args->config, "configuration: full | icebreaker")
      ->check(CLI::IsMember({"full", "icebreaker"}))
      ->capture_default_str();
  cmd->add_option("--size", args->size, "frame size WxH")->capture_default_str();
  cmd->add_option("--clocks", args->clocks,
                  "where clocks come from: rtl (the Verilated GPU, the default when built) or estimate (the model's)")
      ->check(CLI::IsMember({"rtl", "estimate"}));
  cmd->add_option("--out-dir", args->out_dir, "directory for study.csv, study.md and the charts")
      ->capture_default_str();
  cmd->add_flag("--quick", args->quick,
                "a few points per sweep: the ends and the middle of each swept range, the trade-off on cube at "
                "1/16 texel (study.md says it was a quick run)");
  cmd->add_flag("--no-charts", args->no_charts, "write the gnuplot scripts without running gnuplot");
  cmd->callback([args] { run_study(*args); });
}

}  // namespace htx
