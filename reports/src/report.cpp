#include "planarbench/reports/report.hpp"

#include <fmt/format.h>

#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/reports/run_validity.hpp"
#include "planarbench/reports/thresholds.hpp"
#include "planarbench/results_file.hpp"
#include "planarbench/sweep_file.hpp"
#include "report_campaign.hpp"
#include "report_impacts.hpp"
#include "report_figures.hpp"
#include "report_files.hpp"
#include "report_friction.hpp"
#include "report_validity.hpp"
#include "report_scenes.hpp"
#include "report_html.hpp"
#include "planarbench/output_file.hpp"
#include "report_mapping.hpp"
#include "report_markdown.hpp"
#include "report_provenance.hpp"
#include "report_svg.hpp"
#include "report_tables.hpp"
#include "report_verdict.hpp"
#include "report_versions.hpp"
#include "report_web_assets.hpp"
#include "report_work_precision.hpp"
#include "report_work_precision_svg.hpp"

namespace pb {

namespace fs = std::filesystem;
using internal::Report;

namespace {

internal::CaseSection case_section(const Case& c, const CaseRuns& cr,
                                   const internal::FigureLimits& limits) {
  internal::CaseSection s;
  s.name = c.name;
  s.description = c.description;
  s.paper = c.paper;
  s.truth = truth_kind_name(c.truth);
  s.assumptions = c.assumptions;
  s.overrides = cr.overrides;
  s.figures = internal::case_figures(c, cr, limits);
  return s;
}

// the work-precision section of a sweep file, and its provenance
void add_work_precision(Report& report, const fs::path& path) {
  const SweepFile sweep = read_sweep_file(path);
  report.sweep_file = path.string();
  report.work_precision_note = internal::work_precision_note(sweep, path.string());
  for (const auto& c : sweep.cases) {
    report.work_precision.push_back(internal::work_precision_case(c));
  }
  report.sweep_provenance =
      internal::sweep_provenance_table(internal::read_file_provenance(path), sweep);
}

// the sweep file's /parameters, for the page header of a sweep-only report
std::vector<std::pair<std::string, std::string>> sweep_parameters(const fs::path& path) {
  return internal::read_file_provenance(path).parameters;
}

// An existing report folder must be a folder whose pages, if present, are
// regular files (a FIFO named report.html would otherwise be replaced): checked
// before anything is read or computed.
void check_report_folder(const fs::path& dir) {
  std::error_code ec;
  const auto status = fs::status(dir, ec);
  if (!fs::exists(status)) return;  // created later, with everything in it new
  if (!fs::is_directory(status)) {
    throw InputError("--out", 0, dir.string(), "exists and is not a folder; give a report folder");
  }
  for (const char* page : {"report.html", "report.md"}) (void)output_target("--out", dir / page);
}

// the report's files into options.out_dir (write_report below)
ReportSummary write_report_files(const internal::Report& report, const internal::WebAssets& assets,
                                 const ReportOptions& options, std::size_t n_metrics,
                                 std::size_t n_checks, std::size_t failed, std::size_t known);

}  // namespace

ReportSummary write_report(const ReportOptions& options) {
  // web assets first: without them there is no page, and no reason to compute
  const auto assets = internal::load_web_assets(internal::web_dir(options.web_dir));
  if (options.results.empty() && options.sweep.empty()) {
    throw InputError("report", 0, "", "give a results file, --sweep FILE, or both");
  }
  check_report_folder(options.out_dir);
  // without a results file the report is the work-precision section alone
  const bool with_results = !options.results.empty();
  const ResultsFile results = with_results ? read_results_file(options.results) : ResultsFile{};
  // a sweep given as the results file is read as --sweep; a campaign's table
  // is its own section
  const bool sweep_as_results = results.campaign && results.campaign->kind == "sweep";
  const bool has_runs = with_results && !results.cases.empty();
  const auto provenance =
      with_results ? internal::read_file_provenance(options.results) : internal::FileProvenance{};
  const auto thresholds =
      options.thresholds.empty() ? std::vector<Threshold>{} : load_thresholds(options.thresholds);
  if (options.check_thresholds && !thresholds.empty()) options.check_thresholds(thresholds, results);

  Report report;
  report.results_file = options.results.string();
  report.thresholds_file = options.thresholds.string();
  report.provenance = provenance.parameters;
  if (!options.sweep.empty()) {
    add_work_precision(report, options.sweep);
    // a sweep-only page shows the sweep's build, host and time in its header
    if (!with_results) report.provenance = sweep_parameters(options.sweep);
  }
  if (sweep_as_results && options.sweep.empty()) add_work_precision(report, options.results);
  const bool impacts_as_results = results.campaign && internal::is_impacts_table(*results.campaign);
  if (results.campaign && !sweep_as_results && !impacts_as_results) {
    report.campaign = internal::campaign_section(*results.campaign, options.results.string());
  }
  if (impacts_as_results) {
    report.impacts = internal::impacts_section(*results.campaign, options.results.string());
  }
  // a file of `planarbench impacts fit` or `score` beside the results
  if (!options.impacts.empty()) {
    const ResultsFile impacts = read_results_file(options.impacts);
    if (!impacts.campaign || !internal::is_impacts_table(*impacts.campaign)) {
      throw InputError("--impacts", 0, options.impacts.string(),
                       "holds no table of measured impacts; give a file of `planarbench impacts "
                       "fit` or `impacts score`");
    }
    report.impacts = internal::impacts_section(*impacts.campaign, options.impacts.string());
  }
  // campaigns beside the results: the first's section (unless the results
  // are one), and what the friction section draws from them
  std::vector<ResultsFile> campaign_files;
  std::vector<internal::NamedCampaign> campaigns;
  campaign_files.reserve(options.campaigns.size());
  for (const auto& file : options.campaigns) {
    campaign_files.push_back(read_results_file(file));
    const ResultsFile& f = campaign_files.back();
    if (!f.campaign || f.campaign->kind != "campaign") {
      throw InputError("--campaign", 0, file.string(),
                       "holds no campaign table; give a file of `planarbench campaign merge`");
    }
    campaigns.push_back({&*f.campaign, file.string()});
  }
  if (!campaigns.empty() && report.campaign.file.empty()) {
    report.campaign = internal::campaign_section(*campaigns.front().table, campaigns.front().file);
  }
  internal::FigureLimits limits;
  limits.max_outside = options.max_points_outside_contact;
  limits.max_inside = options.max_points_inside_contact;
  report.downsampling_note = fmt::format(
      "Series are down-sampled for embedding: every sample inside a contact window (each "
      "episode of any run, padded by two output intervals) is kept up to {} per series (a "
      "longer, sustained contact keeps the lowest and highest sample of each block, so peaks "
      "survive), at most {} evenly spaced samples per series outside them. The results file "
      "has every sample.",
      limits.max_inside, limits.max_outside);

  // per case: the case model, its figures, its metrics
  std::vector<Case> cases;
  std::vector<MetricValue> metrics;
  std::vector<InvalidRun> invalid;  // NaN or inf in a run's samples: its checks fail
  for (const auto& cr : results.cases) {
    cases.push_back(case_as_run(cr));
    report.cases.push_back(case_section(cases.back(), cr, limits));
    auto m = case_metrics(cases.back(), cr);
    metrics.insert(metrics.end(), m.begin(), m.end());
    const auto bad = invalid_runs(cr);
    invalid.insert(invalid.end(), bad.begin(), bad.end());
    for (const auto* r : internal::runs_in_report_order(cr)) {
      report.mappings.push_back(internal::MappingEntry{cr.case_name, r->engine_name,
                                                       run_status_name(r->status), r->mapping,
                                                       internal::not_expressed(r->mapping)});
    }
  }
  report.friction = internal::friction_section(cases, results, campaigns);
  report.validity = internal::validity_section(cases, results);
  if (options.scenes.empty()) {
    report.scenes = internal::scenes_section(cases, results);
  } else {
    const ResultsFile scene_results = read_results_file(options.scenes);
    std::vector<Case> scene_cases;
    for (const CaseRuns& cr : scene_results.cases) scene_cases.push_back(case_as_run(cr));
    report.scenes = internal::scenes_section(scene_cases, scene_results);
    if (report.scenes.tables.empty()) {
      throw InputError("--scenes", 0, options.scenes.string(),
                       "holds no scene runs (cases with [[generate]] bodies); give a file of "
                       "`planarbench run --case scenes`");
    }
  }
  const auto outcomes = check_thresholds(thresholds, metrics, invalid);
  std::size_t failed = 0;
  std::size_t known = 0;
  for (const auto& o : outcomes) {
    failed += fails_gate(o) ? 1 : 0;
    known += !o.passed && !fails_gate(o) ? 1 : 0;
  }
  if (!options.thresholds.empty()) {
    // the gate's verdict first, as `check` exits (issue 31): a known breach
    // is neither a pass nor a failure of the gate
    report.check_summary = fmt::format(
        "gate {}: {} failed; {} of {} checks within their bands{}", failed == 0 ? "passed" : "failed",
        failed, outcomes.size() - failed - known, outcomes.size(),
        known == 0 ? std::string()
                   : fmt::format(", {} known breaches (an engine's own model cannot meet the band, "
                                 "stated before the run)",
                                 known));
  }

  if (has_runs) {
    report.verdict = internal::verdict_table(results, cases, metrics, outcomes, report.mappings,
                                             report.work_precision);
    report.tables.push_back(internal::capability_table(results));
    report.tables.push_back(internal::physics_table(results));
    report.tables.push_back(internal::timings_table(results, cases));
    report.tables.push_back(
        internal::metrics_table(metrics, outcomes, !options.thresholds.empty()));
    // MuJoCo 2.2.2 and 3.3.8 side by side, when the file has both
    auto versions = internal::mujoco_versions_table(metrics, outcomes);
    if (!versions.rows.empty()) report.tables.push_back(std::move(versions));
  }
  if (!options.thresholds.empty()) {
    report.tables.push_back(internal::unmatched_thresholds_table(outcomes));
  }
  if (with_results) report.tables.push_back(internal::provenance_table(provenance, results));
  if (with_results && !has_runs) report.results_file.clear();

  // the files: figures first, the pages that reference them last; a write
  // that fails leaves no folder this call created behind (issue 49: an
  // empty figures/ stayed after a failed report)
  std::error_code ec;
  const bool had_out = fs::exists(options.out_dir, ec);
  const bool had_figures = fs::exists(options.out_dir / "figures", ec);
  try {
    return write_report_files(report, assets, options, metrics.size(), outcomes.size(), failed,
                              known);
  } catch (...) {
    if (!had_figures) fs::remove_all(options.out_dir / "figures", ec);
    if (!had_out && fs::is_empty(options.out_dir, ec)) fs::remove(options.out_dir, ec);
    throw;
  }
}

namespace {

ReportSummary write_report_files(const internal::Report& report, const internal::WebAssets& assets,
                                 const ReportOptions& options, std::size_t n_metrics,
                                 std::size_t n_checks, std::size_t failed, std::size_t known) {
  internal::ensure_directory(options.out_dir);
  internal::ensure_directory(options.out_dir / "figures");
  ReportSummary summary;
  for (const auto& c : report.cases) {
    for (const auto& f : c.figures) {
      ++summary.figures;
      for (const auto& v : internal::figure_views(f)) {
        internal::write_text_atomically(options.out_dir / v.file,
                                        internal::figure_svg(f, v.t0_s, v.t1_s, v.title));
        ++summary.svg_files;
      }
    }
  }
  for (const auto& w : report.work_precision) {
    internal::write_text_atomically(options.out_dir / internal::work_precision_file(w),
                                    internal::work_precision_svg(w));
    ++summary.svg_files;
  }
  for (const auto& c : report.campaign.cases) {
    for (const auto& f : c.figures) {
      internal::write_text_atomically(options.out_dir / ("figures/" + f.id + ".svg"), f.svg);
      ++summary.svg_files;
    }
  }
  for (const auto& f : report.friction.figures) {
    internal::write_text_atomically(options.out_dir / ("figures/" + f.id + ".svg"), f.svg);
    ++summary.svg_files;
  }
  for (const auto& f : report.impacts.figures) {
    internal::write_text_atomically(options.out_dir / ("figures/" + f.id + ".svg"), f.svg);
    ++summary.svg_files;
  }
  for (const auto& f : report.validity.figures) {
    internal::write_text_atomically(options.out_dir / ("figures/" + f.id + ".svg"), f.svg);
    ++summary.svg_files;
  }
  for (const auto& f : report.scenes.figures) {
    internal::write_text_atomically(options.out_dir / ("figures/" + f.id + ".svg"), f.svg);
    ++summary.svg_files;
  }
  summary.impacts_figures = report.impacts.figures.size();
  summary.friction_figures = report.friction.figures.size();
  summary.validity_figures = report.validity.figures.size();
  summary.campaign_cases = report.campaign.cases.size();
  summary.work_precision_cases = report.work_precision.size();
  summary.markdown = options.out_dir / "report.md";
  internal::write_text_atomically(summary.markdown, internal::report_markdown(report));
  summary.html = options.out_dir / "report.html";
  internal::write_text_atomically(summary.html, internal::report_html(report, assets));
  summary.metrics = n_metrics;
  summary.checks = n_checks;
  summary.checks_failed = failed;
  summary.checks_known = known;
  return summary;
}

}  // namespace

}  // namespace pb
