#include "report_html.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "report_svg.hpp"
#include "report_work_precision_svg.hpp"

namespace pb::internal {

namespace {

// v to `digits` significant digits, as the double nearest that decimal text,
// so that the JSON holds the short text; NaN and infinities become null
nlohmann::json rounded(double v, int digits) {
  if (!std::isfinite(v)) return nullptr;
  const std::string text = fmt::format("{:.{}g}", v, digits);
  return std::strtod(text.c_str(), nullptr);
}

nlohmann::json rounded_array(const std::vector<double>& v, int digits) {
  nlohmann::json a = nlohmann::json::array();
  for (const double x : v) a.push_back(rounded(x, digits));
  return a;
}

const char* quantity_key(Quantity q) {
  switch (q) {
    case Quantity::force:
      return "force";
    case Quantity::x:
      return "x";
    case Quantity::y:
      return "y";
    case Quantity::vx:
      return "vx";
    case Quantity::vy:
      return "vy";
  }
  return "";
}

nlohmann::json table_json(const Table& t) {
  return nlohmann::json{{"id", t.id},           {"title", t.title}, {"note", t.note},
                        {"columns", t.columns}, {"rows", t.rows},   {"row_status", t.row_status}};
}

// figures drawn as SVG text (campaign, friction, impacts, validity sections)
nlohmann::json figures_json(const std::vector<CampaignFigure>& figures) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& f : figures) out.push_back({{"id", f.id}, {"title", f.title}, {"svg", f.svg}});
  return out;
}

// text placed in a <script> or <style> element must not close it early
std::string script_safe(std::string text, const char* closing) {
  const std::string needle = std::string("</") + closing;
  const std::string replacement = std::string("<\\/") + closing;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + replacement.size())) {
    text.replace(at, needle.size(), replacement);
  }
  return text;
}

// text placed in a /* */ comment must not close it early
std::string comment_safe(std::string text) {
  for (std::size_t at = text.find("*/"); at != std::string::npos; at = text.find("*/", at)) {
    text.replace(at, 2, "* /");
  }
  return text;
}

// JSON inside <script type="application/json">: '<' appears only inside JSON
// strings, where \u003c is the same character
std::string json_for_script(const nlohmann::json& j) {
  const std::string text = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    if (ch == '<') {
      out += "\\u003c";
    } else {
      out += ch;
    }
  }
  return out;
}

}  // namespace

nlohmann::json report_data_json(const Report& report) {
  nlohmann::json data;
  data["title"] = "planarbench report";
  data["results_file"] = report.results_file;
  data["thresholds_file"] = report.thresholds_file;
  data["check_summary"] = report.check_summary;
  data["downsampling"] = report.downsampling_note;
  data["provenance"] = report.provenance;

  // shared time grids, in order of first use
  std::map<std::vector<double>, std::size_t> grid_index;
  nlohmann::json grids = nlohmann::json::array();
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& c : report.cases) {
    nlohmann::json figures = nlohmann::json::array();
    for (const auto& f : c.figures) {
      nlohmann::json series = nlohmann::json::array();
      for (std::size_t k = 0; k < f.series.size(); ++k) {
        const auto& s = f.series[k];
        auto [it, added] = grid_index.emplace(s.time_s, grid_index.size());
        if (added) grids.push_back(rounded_array(s.time_s, 9));
        series.push_back({{"engine", s.engine},
                          {"colour", engine_colour(s.engine, k)},
                          {"grid", it->second},
                          {"y", rounded_array(s.value, 7)},
                          {"full_points", s.full_points},
                          {"shown_points", s.time_s.size()},
                          {"off_scale", s.off_scale},
                          {"note", s.note}});
      }
      nlohmann::json episodes = nlohmann::json::array();
      for (const auto& e : f.episodes) {
        episodes.push_back(
            {{"label", e.label}, {"t0", rounded(e.t0_s, 9)}, {"t1", rounded(e.t1_s, 9)}});
      }
      figures.push_back({{"id", f.id},
                         {"title", f.title},
                         {"paper_figure", f.paper_figure},
                         {"y_label", f.y_label},
                         {"quantity", quantity_key(f.quantity)},
                         {"t_end", f.t_end_s},
                         {"y_clip", rounded(f.y_clip, 7)},
                         {"episodes", episodes},
                         {"series", series}});
    }
    cases.push_back({{"name", c.name},
                     {"description", c.description},
                     {"paper", c.paper},
                     {"truth", c.truth},
                     {"assumptions", c.assumptions},
                     {"overrides", c.overrides},
                     {"figures", figures}});
  }
  data["grids"] = grids;
  data["cases"] = cases;

  if (!report.verdict.rows.empty()) data["verdict"] = table_json(report.verdict);
  nlohmann::json tables = nlohmann::json::array();
  for (const auto& t : report.tables) tables.push_back(table_json(t));
  data["tables"] = tables;

  nlohmann::json mappings = nlohmann::json::array();
  for (const auto& m : report.mappings) {
    mappings.push_back({{"case", m.case_name},
                        {"engine", m.engine},
                        {"status", m.status},
                        {"not_expressed", m.not_expressed},
                        {"mapping", m.mapping}});
  }
  data["mappings"] = mappings;

  // the work-precision section: each case's plot as SVG text, its tables
  data["sweep_file"] = report.sweep_file;
  nlohmann::json wp = nlohmann::json::array();
  for (const auto& w : report.work_precision) {
    wp.push_back({{"name", w.name},
                  {"id", w.id},
                  {"truth", w.truth},
                  {"truth_note", w.truth_note},
                  {"svg", work_precision_svg(w)},
                  {"not_plotted", w.not_plotted},
                  {"summary", table_json(w.summary)},
                  {"rungs", table_json(w.rungs)}});
  }
  data["work_precision"] = {{"note", report.work_precision_note},
                            {"cases", wp},
                            {"provenance", table_json(report.sweep_provenance)}};

  // the campaign section: per case its figures (SVG text) and tables
  nlohmann::json campaign_cases = nlohmann::json::array();
  for (const auto& c : report.campaign.cases) {
    const nlohmann::json figures = figures_json(c.figures);
    nlohmann::json case_tables = nlohmann::json::array();
    for (const auto& t : c.tables) case_tables.push_back(table_json(t));
    campaign_cases.push_back(
        {{"name", c.name}, {"truth", c.truth}, {"figures", figures}, {"tables", case_tables}});
  }
  data["campaign"] = {{"file", report.campaign.file},
                      {"note", report.campaign.note},
                      {"cases", campaign_cases}};

  // the friction section: figures (SVG text) and the curve's table
  data["friction"] = {{"note", report.friction.note},
                      {"curve_file", report.friction.curve_file},
                      {"figures", figures_json(report.friction.figures)},
                      {"curve", table_json(report.friction.curve)},
                      {"family", table_json(report.friction.family)}};

  // the measured-impacts section: figures (SVG text) and tables
  nlohmann::json impact_tables = nlohmann::json::array();
  for (const auto& t : report.impacts.tables) impact_tables.push_back(table_json(t));
  data["impacts"] = {{"file", report.impacts.file},
                     {"note", report.impacts.note},
                     {"figures", figures_json(report.impacts.figures)},
                     {"tables", impact_tables}};
  // the physical-validity section: readings, table, figures (SVG text)
  data["scenes"] = {{"note", report.scenes.note},
                    {"tables", nlohmann::json::array()},
                    {"figures", figures_json(report.scenes.figures)}};
  for (const auto& t : report.scenes.tables) data["scenes"]["tables"].push_back(table_json(t));
  data["validity"] = {{"note", report.validity.note},
                      {"readings", report.validity.readings},
                      {"table", table_json(report.validity.table)},
                      {"figures", figures_json(report.validity.figures)}};
  return data;
}

std::string fill_template(const std::string& page,
                          const std::vector<std::pair<std::string, std::string>>& values) {
  std::map<std::string, const std::string*> lookup;
  for (const auto& [name, value] : values) lookup[name] = &value;
  std::map<std::string, bool> used;
  std::string out;
  out.reserve(page.size());
  std::size_t pos = 0;
  while (true) {
    const std::size_t open = page.find("@@", pos);
    if (open == std::string::npos) break;
    const std::size_t close = page.find("@@", open + 2);
    if (close == std::string::npos) break;
    const std::string name = page.substr(open + 2, close - open - 2);
    const auto it = lookup.find(name);
    if (it == lookup.end()) {
      // not a token of ours: keep the text as it is
      out.append(page, pos, open + 2 - pos);
      pos = open + 2;
      continue;
    }
    out.append(page, pos, open - pos);
    out += *it->second;
    used[name] = true;
    pos = close + 2;
  }
  out.append(page, pos, std::string::npos);
  for (const auto& [name, value] : values) {
    if (!used[name]) {
      throw std::invalid_argument("report template has no @@" + name + "@@ token");
    }
  }
  return out;
}

std::string report_html(const Report& report, const WebAssets& assets) {
  return fill_template(
      assets.page_template,
      {{"TITLE",
        xml_escape("planarbench report: " +
                   (!report.results_file.empty() ? report.results_file
                    : !report.campaign.file.empty() ? report.campaign.file
                    : !report.impacts.file.empty()  ? report.impacts.file
                                                    : report.sweep_file))},
       {"UPLOT_VERSION", assets.uplot_version},
       {"UPLOT_LICENSE", script_safe(comment_safe(assets.uplot_license), "script")},
       {"UPLOT_CSS", script_safe(assets.uplot_css, "style")},
       {"PAGE_CSS", script_safe(assets.page_css, "style")},
       {"UPLOT_JS", script_safe(assets.uplot_js, "script")},
       {"PAGE_JS", script_safe(assets.page_js, "script")},
       {"DATA", json_for_script(report_data_json(report))}});
}

}  // namespace pb::internal
