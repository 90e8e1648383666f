#include "report_impacts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "planarbench/errors.hpp"
#include "planarbench/json_integer.hpp"
#include "report_campaign.hpp"
#include "report_svg.hpp"

namespace pb::internal {

namespace {

using Json = nlohmann::ordered_json;

std::string number(const Json& v, const char* format = "{:.4f}") {
  return v.is_null() ? std::string("n/a") : fmt::format(fmt::runtime(format), v.get<double>());
}

// a summary's key that files written before it lack (issue 34's e_F): "n/a"
std::string optional_number(const Json& summary, const char* key) {
  const auto v = summary.find(key);
  return v == summary.end() ? std::string("n/a") : number(*v);
}

std::string parameters_text(const Json& model, const Json& values) {
  std::string s;
  const auto& specs = model.at("parameters");
  for (std::size_t j = 0; j < values.size() && j < specs.size(); ++j) {
    s += fmt::format("{}{} = {:.4g}", j ? ", " : "", specs.at(j).at("name").get<std::string>(),
                     values.at(j).get<double>());
  }
  return s.empty() ? "-" : s;
}

// the fit whose parameters the model is reported with: the whole-file fit, or the scored one
const Json* headline_fit(const Json& model) {
  for (const auto& f : model.at("fits")) {
    const int fold = json_integer<int>(f.at("fold"), "fold");
    if (fold == -1 || fold == -2) return &f;
  }
  return nullptr;
}

std::size_t metric_index(const CampaignTable& t, const std::string& name) {
  for (std::size_t m = 0; m < t.metrics.size(); ++m) {
    if (t.metrics[m].name == name) return m;
  }
  return t.metrics.size();
}

std::string colour_of(const std::string& model, std::size_t index) {
  if (model == "reference_exact") return "#17becf";
  if (model == "reference_ln") return "#aec7e8";
  if (model == "reference_hc") return "#9edae5";
  if (model == "rigid") return "#000000";
  if (model == "naive_bounce") return "#7f7f7f";
  if (model == "rigid_compliant") return "#8c564b";
  if (model == "learned_residual") return "#e377c2";
  if (model.rfind("stored_", 0) == 0) return "#bcbd22";
  return engine_colour(model, index);
}

// what the data identify: each fitted parameter's spread over the folds (the
// study's identification, its rule in the description)
Table identification_table(const Json& d) {
  Table t;
  t.id = "impacts_identification";
  t.title = "Measured impacts: what the data identify";
  t.note = fmt::format(
      "Per model and fitted parameter: the whole-file fit, the range of the fold fits and the "
      "grouped jackknife's 95 % interval, +-2 SE with SE^2 = (k - 1) / k sum (p_i - mean)^2 "
      "over the k fold fits (on log p for a log-scale parameter, shown as a factor x/). "
      "Identified: the interval within +-{:.0f} % of the whole-file value; otherwise the "
      "objective is flat along it and its value is the fit's, not the data's.",
      100.0 * d.value("identified_half_width", std::nan("")));
  t.columns = {"model", "parameter", "whole file", "folds min", "folds max", "95 % (+-)",
               "identified"};
  for (const auto& m : d.at("models")) {
    if (!m.contains("identification")) continue;
    for (const auto& p : m.at("identification")) {
      const bool ok = p.at("identified").get<bool>();
      const double w = p.at("half_width").get<double>();
      t.rows.push_back({m.at("name").get<std::string>(), p.at("name").get<std::string>(),
                        fmt::format("{:.4g}", p.at("whole").get<double>()),
                        fmt::format("{:.4g}", p.at("fold_min").get<double>()),
                        fmt::format("{:.4g}", p.at("fold_max").get<double>()),
                        p.at("log_scale").get<bool>() ? fmt::format("x/ {:.2f}", 1.0 + w)
                        : p.value("relative_to", "value") == "range"
                            ? fmt::format("{:.1f} % of the range", 100.0 * w)
                            : fmt::format("{:.1f} %", 100.0 * w),
                        ok                                          ? "yes"
                        : p.at("whole_outside_folds").get<bool>() ? "no (whole-file fit outside the folds')"
                                                                    : "no"});
      t.row_status.push_back(ok ? "" : "fail");
    }
  }
  return t;
}

Table convention_table(const Json& d) {
  Table t;
  t.id = "impacts_convention";
  t.title = "Measured impacts: the angle convention";
  t.note = fmt::format(
      "The ground's impulse acts at the contact point, so an impact conserves the angular momentum "
      "about it. Post-impact momentum fitted against pre-impact over the file, for each sign pair "
      "of the stored angle and angular velocity (least squares, Pearson r); rule: {}.",
      d.at("convention").at("rule").get<std::string>());
  t.columns = {"angle, angular velocity", "slope", "intercept (kg m^2/s)", "r", "convention"};
  const int chosen = json_integer<int>(d.at("convention").at("chosen"), "convention.chosen");
  int k = 0;
  for (const auto& f : d.at("convention").at("fits")) {
    t.rows.push_back({f.at("label").get<std::string>(), number(f.at("slope"), "{:.3f}"),
                      number(f.at("intercept"), "{:.3g}"), number(f.at("correlation"), "{:.3f}"),
                      k == chosen ? "chosen" : ""});
    t.row_status.push_back(k == chosen ? "pass" : "");
    ++k;
  }
  return t;
}

}  // namespace

bool is_impacts_table(const CampaignTable& t) {
  return t.kind == "impacts_fit" || t.kind == "impacts_score";
}

namespace {

ImpactsSection section_of(const CampaignTable& t, const std::string& file) {
  ImpactsSection s;
  s.file = file;
  const Json& d = t.description;
  const bool scored = t.kind == "impacts_score";
  const bool in_sample = scored && d.value("in_sample", false);
  const char* judged = scored ? "scored" : "cross_validated";
  const Json& data = d.at("data");
  s.note = fmt::format(
      "{} measured impacts of {} (sha256 {}), the MCube ellipse (a = {} m, b = {} m, m = {} kg, "
      "k = {} m). Each engine runs every impact as a case: the ellipse started on the ballistic "
      "arc that reaches the measured pre-impact state at the touch, read once the contact has "
      "ended, carried back ballistically to the touch. Error eps = ||v_pred - v_meas||_M / "
      "||v_meas - v_pre||_M with M = diag(m, m, m k^2): predicting no impact scores 1; beside it the "
      "published metric e_F = ||v_pred - v_meas||_M / ||v_meas||_M (Fazeli et al., CoRL 2017: "
      "relative to the post-impact velocity, so smaller for the same miss; means do not convert) "
      "and the spin's own |theta'_pred - theta'_meas| / |theta'_meas - theta'_pre|, which the "
      "M-norm hardly sees. {} The stored predictions are the dataset's own, judged as given (its README finds them computed "
      "in the angle convention that does not conserve the momentum). Wall times on the machine "
      "in the provenance.",
      json_integer<std::size_t>(data.at("impacts"), "data.impacts"), data.at("path").get<std::string>(),
      data.at("sha256").get<std::string>().substr(0, 16),
      d.at("object").at("semi_axis_a_m").get<double>(), d.at("object").at("semi_axis_b_m").get<double>(),
      d.at("object").at("mass_kg").get<double>(), d.at("object").at("gyration_radius_m").get<double>(),
      scored ? fmt::format("Scored with parameters frozen in {} (fitted to the file of sha256 {}): "
                           "nothing refitted.",
                           d.at("parameters_from").at("path").get<std::string>(),
                           d.at("parameters_from").at("data_sha256").get<std::string>().substr(0, 16))
             : fmt::format("Parameters fitted by NLopt's simplex minimising {}; each "
                           "impact is judged by the fit of the {}-fold cross-validation that held it "
                           "out (seed {}), so no model is judged on impacts it was fitted to; the "
                           "parameters shown are the fit on the whole file.",
                           // files written before issue 34 minimised the median alone
                           d.value("objective", std::string("the median eps")),
                           json_integer<int>(d.at("folds"), "folds"), json_integer<std::uint64_t>(d.at("seed"), "seed")));
  s.tables.push_back(convention_table(d));

  // the models
  double rigid_median = std::nan("");
  for (const auto& m : d.at("models")) {
    if (m.at("name") == "rigid" && m.contains(judged) && !m.at(judged).at("eps_median").is_null()) {
      rigid_median = m.at(judged).at("eps_median").get<double>();
    }
  }
  Table models;
  models.id = "impacts_models";
  models.title = in_sample ? "Measured impacts: IN-SAMPLE scores (the file the parameters were fitted to: not predictions)"
                 : scored ? "Measured impacts: frozen parameters scored"
                          : "Measured impacts: cross-validated";
  models.note = in_sample ? "eps of every impact of the file the parameters were fitted to: how well the "
                            "models fit, not how well they predict."
                : scored ? "eps of every impact of the file, with the fit file's parameters."
                       : "eps of each impact as predicted by the fold fit that did not see it; "
                         "parameters: the whole-file fit. x/rigid: the median against the rigid "
                         "baseline's.";
  models.columns = {"model", "kind", "representation", "parameters", "eps median", "x rigid",
                    "eps mean", "eps p90", "e_F median", "e_F mean", "e_F p90",
                    "spin eps median", "|dx'| median (m/s)", "|dy'| median (m/s)",
                    "|dtheta'| median (rad/s)", "failed", "wall (s)"};
  for (const auto& m : d.at("models")) {
    if (!m.contains(judged)) continue;
    const Json& j = m.at(judged);
    const Json* fit = headline_fit(m);
    const double median = j.at("eps_median").is_null() ? std::nan("") : j.at("eps_median").get<double>();
    models.rows.push_back(
        {m.at("name").get<std::string>(), m.at("kind").get<std::string>(),
         m.at("description").get<std::string>(),
         fit ? parameters_text(m, fit->at("parameters")) : "-", number(j.at("eps_median")),
         std::isfinite(rigid_median) && std::isfinite(median) ? fmt::format("{:.2f}", median / rigid_median)
                                                              : "n/a",
         number(j.at("eps_mean")), number(j.at("eps_p90")), optional_number(j, "e_f_median"),
         optional_number(j, "e_f_mean"), optional_number(j, "e_f_p90"),
         optional_number(j, "spin_eps_median"), number(j.at("abs_error_vx_median_mps")),
         number(j.at("abs_error_vy_median_mps")), number(j.at("abs_error_w_median_radps"), "{:.3f}"),
         fmt::format("{} of {}", json_integer<int>(j.at("failed"), "failed"), json_integer<int>(j.at("impacts"), "impacts")),
         fmt::format("{:.1f}", m.at("wall_time_s").get<double>())});
    models.row_status.push_back(json_integer<int>(j.at("failed"), "failed") > 0 ? "fail" : "");
  }
  s.tables.push_back(std::move(models));

  if (!scored) {
    if (Table spread = identification_table(d); !spread.rows.empty()) {
      s.tables.push_back(std::move(spread));
    }

    Table fits;
    fits.id = "impacts_fits";
    fits.title = "Measured impacts: every fit";
    fits.note = "Per model and fold: the parameters found, the objective on the impacts fitted to "
                "(stated above), NLopt's evaluations and why it stopped. Fold \"all\": the whole "
                "file.";
    fits.columns = {"model", "fold", "parameters", "objective", "evaluations", "stop", "wall (s)"};
    for (const auto& m : d.at("models")) {
      if (m.at("parameters").empty()) continue;  // the stored predictions: nothing fitted
      for (const auto& f : m.at("fits")) {
        const int fold = json_integer<int>(f.at("fold"), "fold");
        fits.rows.push_back({m.at("name").get<std::string>(), fold < 0 ? "all" : std::to_string(fold),
                             parameters_text(m, f.at("parameters")), number(f.at("objective")),
                             std::to_string(json_integer<int>(f.at("evaluations"), "evaluations")),
                             f.at("stop").get<std::string>(),
                             fmt::format("{:.1f}", f.at("wall_time_s").get<double>())});
      }
    }
    s.tables.push_back(std::move(fits));
  }

  // figures: the CDF of eps, predicted against measured
  const std::size_t eps_col = metric_index(t, "eps");
  std::map<std::string, std::vector<const CampaignRun*>> rows;
  std::vector<std::string> order;
  for (const auto& r : t.runs) {
    if (rows.find(r.engine) == rows.end()) order.push_back(r.engine);
    rows[r.engine].push_back(&r);
  }
  LinePlot cdf;
  cdf.title = fmt::format("Measured impacts: CDF of eps ({})", scored ? "scored" : "cross-validated");
  cdf.x_label = "eps";
  cdf.y_label = "fraction of impacts with a smaller error";
  std::size_t index = 0;
  for (const std::string& name : order) {
    if (name.rfind("stored_", 0) == 0 && name != "stored_drumwright_shell") continue;  // one stands for six
    std::vector<double> eps;
    for (const CampaignRun* r : rows[name]) {
      const double e = r->metrics[eps_col];
      eps.push_back(std::isfinite(e) ? e : 1e9);  // a failure: off the chart, counted
    }
    std::sort(eps.begin(), eps.end());
    LinePlot::Line line{name, colour_of(name, index++), {}, {}, {}, {}};
    for (std::size_t k = 0; k < eps.size(); ++k) {
      if (eps[k] > 0.6) break;  // beyond 0.6 the models are all wrong: the axis shows the rest
      line.x.push_back(eps[k]);
      line.y.push_back(static_cast<double>(k + 1) / static_cast<double>(eps.size()));
    }
    cdf.lines.push_back(std::move(line));
  }
  s.figures.push_back({"impacts_eps_cdf", cdf.title, line_plot_svg(cdf)});

  const std::array<std::array<const char*, 4>, 3> components = {{
      {"vx", "x'", "meas_vx_mps", "pred_vx_mps"},
      {"vy", "y'", "meas_vy_mps", "pred_vy_mps"},
      {"w", "theta'", "meas_w_radps", "pred_w_radps"},
  }};
  for (const auto& c : components) {
    const std::size_t meas = metric_index(t, c[2]);
    const std::size_t pred = metric_index(t, c[3]);
    LinePlot plot;
    plot.title = fmt::format("Measured impacts: predicted against measured {} after the impact", c[1]);
    plot.x_label = fmt::format("measured {} ({})", c[1], c[0][0] == 'w' ? "rad/s" : "m/s");
    plot.y_label = fmt::format("predicted {}", c[1]);
    double lo = 1e300, hi = -1e300;
    index = 0;
    for (const std::string& name : order) {
      if (name.rfind("stored_", 0) == 0 || name == "naive_bounce") continue;
      LinePlot::Line line{name, colour_of(name, index++), {}, {}, {}, {}, true};
      for (const CampaignRun* r : rows[name]) {
        line.x.push_back(r->metrics[meas]);
        line.y.push_back(r->metrics[pred]);
        if (std::isfinite(r->metrics[meas])) {
          lo = std::min(lo, r->metrics[meas]);
          hi = std::max(hi, r->metrics[meas]);
        }
      }
      plot.lines.push_back(std::move(line));
    }
    if (lo < hi) plot.lines.push_back({"predicted = measured", "#aaaaaa", {lo, hi}, {lo, hi}, {}, {}});
    s.figures.push_back({std::string("impacts_predicted_") + c[0], plot.title, line_plot_svg(plot)});
  }
  return s;
}

}  // namespace

ImpactsSection impacts_section(const CampaignTable& t, const std::string& file) {
  // the description is input: a file edited or of another version names its
  // field (issue 35 item 13: the report printed the raw JSON exception)
  try {
    return section_of(t, file);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, 0, "/campaign description",
                     fmt::format("is not the description of a study of `planarbench impacts fit` "
                                 "or `impacts score` ({})",
                                 e.what()));
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {  // an integer not as written (json_integer.hpp)
    throw InputError(file, 0, "/campaign description", e.what());
  }
}

}  // namespace pb::internal
