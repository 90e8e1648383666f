// planarbench report: the HTML + Markdown report of a results file (SPEC §6).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "threshold_names.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/reports/report.hpp"

namespace pb::cli {

namespace {

struct ReportOptionsCli {
  std::string results;
  std::string out;
  std::string thresholds;
  std::string sweep;
  std::vector<std::string> campaigns;
  std::string impacts;
  std::string scenes;
  bool quiet = false;
};

namespace fs = std::filesystem;

// The report writes report.html, report.md and figures/*.svg inside --out:
// none of them may replace an input (issue 24), also through a link there.
// The figures' names are known only once the inputs are read, so every
// figures/*.svg is held to it: those already there (a link among them would
// be followed) and any input named like one.
void check_report_spares_inputs(const ReportOptionsCli& opt) {
  std::vector<NamedInput> inputs = {{"the results file", opt.results},
                                    {"--thresholds", opt.thresholds},
                                    {"--sweep", opt.sweep},
                                    {"--impacts", opt.impacts},
                                    {"--scenes", opt.scenes}};
  for (const auto& c : opt.campaigns) inputs.push_back({"--campaign", c});
  const fs::path dir = opt.out;
  const fs::path figures = dir / "figures";
  std::vector<fs::path> outputs = {dir / "report.html", dir / "report.md"};
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(figures, ec)) {
    if (e.path().extension() == ".svg") outputs.push_back(e.path());
  }
  const fs::path figures_canonical = fs::weakly_canonical(figures, ec);
  for (const auto& in : inputs) {
    if (in.path.empty() || in.path.extension() != ".svg") continue;
    if (fs::weakly_canonical(in.path, ec).parent_path() == figures_canonical) outputs.push_back(in.path);
  }
  for (const auto& out : outputs) {
    check_spares_inputs("--out", out, inputs,
                        "give another --out folder (the report writes report.html, report.md and "
                        "figures/*.svg in it)");
  }
}

int run_report(const ReportOptionsCli& opt) {
  ReportOptions options;
  options.results = opt.results;
  options.out_dir = opt.out;
  options.thresholds = opt.thresholds;
  options.sweep = opt.sweep;
  options.campaigns.assign(opt.campaigns.begin(), opt.campaigns.end());
  options.impacts = opt.impacts;
  options.scenes = opt.scenes;
  // a misspelt case or engine would otherwise be a check silently never made
  options.check_thresholds = [&opt](const std::vector<Threshold>& t, const ResultsFile& r) {
    check_threshold_names(opt.thresholds, t, r);
  };
  if (opt.results.empty() && opt.sweep.empty()) {
    throw InputError("report", 0, "", "give a results file, --sweep FILE, or both");
  }
  if (opt.results.empty() && !opt.thresholds.empty()) {
    throw InputError("--thresholds", 0, "",
                     "needs a results file (the sweep has no metrics to check)");
  }
  check_report_spares_inputs(opt);
  const ReportSummary s = write_report(options);
  if (!opt.quiet) {
    std::printf("wrote %s and %s (%zu figures, %zu SVG files, %zu metrics", s.html.c_str(),
                s.markdown.c_str(), s.figures, s.svg_files, s.metrics);
    if (!opt.thresholds.empty()) {
      std::printf(", %zu of %zu checks passed, %zu breached, %zu known breach(es)",
                  s.checks - s.checks_failed - s.checks_known, s.checks, s.checks_failed,
                  s.checks_known);
    }
    if (s.work_precision_cases > 0) {
      std::printf(", work-precision of %zu cases", s.work_precision_cases);
    }
    if (s.campaign_cases > 0) std::printf(", campaign of %zu cases", s.campaign_cases);
    if (s.friction_figures > 0) std::printf(", %zu friction figures", s.friction_figures);
    if (s.validity_figures > 0) std::printf(", %zu physical-validity figures", s.validity_figures);
    if (s.impacts_figures > 0) std::printf(", measured impacts (%zu figures)", s.impacts_figures);
    std::printf(")\n");
  }
  return 0;
}

}  // namespace

Action add_report_command(CLI::App& app) {
  auto opt = std::make_shared<ReportOptionsCli>();
  auto* cmd = app.add_subcommand(
      "report",
      "Write an HTML + Markdown report of a results file: the paper's figures with every engine "
      "overlaid, metrics, parameter mapping, capability matrix, timings, provenance");
  cmd->add_option("results", opt->results,
                  "Results file written by `planarbench run` or `campaign merge` (a campaign's table "
                  "gets its own section), or a sweep's file; may be left out with --sweep")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", opt->out,
                  "Report folder (created): report.html, report.md, figures/*.svg")
      ->required();
  cmd->add_option("--thresholds", opt->thresholds,
                  "Thresholds file (TOML): adds pass/fail to every checked metric")
      ->check(CLI::ExistingFile);
  cmd->add_option("--sweep", opt->sweep,
                  "Sweep file written by `planarbench sweep`: adds the work-precision section "
                  "(log-log error vs wall time per case, time to reach 1e-3 and 1e-5 m, cost per "
                  "simulated second)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--campaign", opt->campaigns,
                  "A campaign's file (`planarbench campaign merge`) beside the results; repeatable. "
                  "The first adds its campaign section; the friction section draws the friction "
                  "curve from one that sweeps a pair's friction and records "
                  "slide_acceleration_mps2 (campaigns/friction_curve.toml), and the block family "
                  "from one that records hold_drift_m, slide_acceleration_error or "
                  "stop_time_error (campaigns/block_family.toml)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--impacts", opt->impacts,
                  "A file of `planarbench impacts fit` or `impacts score`: adds the measured-impacts "
                  "section (such a file may also be given as the results file)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--scenes", opt->scenes,
                  "A results file of scenes (`planarbench run --case scenes`): adds the scenes "
                  "section (per family: sag, drift, creep, support and interface forces, energy, "
                  "penetration and cost against the number of bodies)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--quiet,-q", opt->quiet, "Print nothing on success");
  return [opt] { return run_report(*opt); };
}

}  // namespace pb::cli
