#include "report_markdown.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

#include "markdown_text.hpp"
#include "report_mapping.hpp"
#include "report_work_precision.hpp"

namespace pb::internal {

namespace {

std::string cell(const std::string& text) { return md_text(text); }

// a GitHub anchor for a heading: lower case, spaces to '-', punctuation dropped
std::string anchor(const std::string& heading) {
  std::string out;
  for (const char ch : heading) {
    if ((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-') {
      out += ch;
    } else if (ch >= 'A' && ch <= 'Z') {
      out += static_cast<char>(ch - 'A' + 'a');
    } else if (ch == ' ') {
      out += '-';
    }
  }
  return out;
}

void section_table(std::string& md, const Table& t) {
  md += "## " + md_text(t.title) + "\n\n";
  if (!t.note.empty()) md += t.note + "\n\n";
  md += t.rows.empty() ? "(none)\n\n" : markdown_table(t) + "\n";
}

}  // namespace

std::string work_precision_markdown(const Report& report) {
  std::string md = "## Work-precision\n\n" + report.work_precision_note + "\n\n";
  for (const auto& w : report.work_precision) {
    md += "### " + md_text(w.name) + "\n\n";
    md += "Truth: " + w.truth + (w.truth_note.empty() ? "" : " (" + w.truth_note + ")") + ".\n\n";
    md += fmt::format("![{}: position error vs wall time]({})\n\n", md_text(w.name),
                      work_precision_file(w));
    if (!w.summary.note.empty()) md += w.summary.note + "\n\n";
    md += markdown_table(w.summary) + "\n";
    if (!w.not_plotted.empty()) {
      md += "Not plotted:\n";
      for (const auto& n : w.not_plotted) md += "- " + cell(n) + "\n";
      md += "\n";
    }
    md +=
        "<details><summary>every rung</summary>\n\n" + markdown_table(w.rungs) + "\n</details>\n\n";
  }
  if (!report.sweep_provenance.rows.empty()) {
    md += "### " + report.sweep_provenance.title + "\n\n" + report.sweep_provenance.note + "\n\n" +
          markdown_table(report.sweep_provenance) + "\n";
  }
  return md;
}

std::string campaign_markdown(const Report& report) {
  // the notes are plain text holding the campaign's own names (its file, its
  // axes' names and keys: issue 49, an axis named <img src=x onerror=...>
  // reached report.md as HTML): shown as text
  std::string md = "## Campaign\n\n" + md_block(report.campaign.note) + "\n\n";
  for (const auto& c : report.campaign.cases) {
    md += "### " + md_text(c.name) + "\n\nTruth of position_error_m: " + md_text(c.truth) + ".\n\n";
    for (const auto& f : c.figures) {
      md += fmt::format("![{}](figures/{}.svg)\n\n", md_text(f.title), f.id);
    }
    for (const auto& t : c.tables) {
      md += "#### " + md_text(t.title) + "\n\n";
      if (!t.note.empty()) md += md_block(t.note) + "\n\n";
      md += (t.rows.empty() ? std::string("(none)\n") : markdown_table(t)) + "\n";
    }
  }
  return md;
}

std::string friction_markdown(const Report& report) {
  const FrictionSection& f = report.friction;
  std::string md = "## Friction\n\n" + f.note + "\n\n";
  for (const auto& fig : f.figures) md += fmt::format("![{}](figures/{}.svg)\n\n", md_text(fig.title), fig.id);
  if (!f.curve.rows.empty()) {
    md += "### " + f.curve.title + "\n\n" + f.curve.note + "\n\n" + markdown_table(f.curve) + "\n";
  }
  if (!f.family.rows.empty()) {
    md += "### " + f.family.title + "\n\n" + f.family.note + "\n\n" + markdown_table(f.family) + "\n";
  }
  return md;
}

std::string impacts_markdown(const Report& report) {
  const ImpactsSection& s = report.impacts;
  std::string md = "## Measured impacts\n\n" + s.note + "\n\n";
  for (const auto& t : s.tables) {
    md += "### " + t.title + "\n\n" + t.note + "\n\n" + markdown_table(t) + "\n";
  }
  for (const auto& fig : s.figures) md += fmt::format("![{}](figures/{}.svg)\n\n", md_text(fig.title), fig.id);
  return md;
}

std::string validity_markdown(const Report& report) {
  const ValiditySection& v = report.validity;
  std::string md = "## Physical validity\n\n" + v.note + "\n\n";
  for (const auto& line : v.readings) md += "- " + md_text(line) + "\n";
  md += "\n### " + v.table.title + "\n\n" + v.table.note + "\n\n" + markdown_table(v.table) + "\n";
  for (const auto& fig : v.figures) md += fmt::format("![{}](figures/{}.svg)\n\n", md_text(fig.title), fig.id);
  return md;
}

std::string scenes_markdown(const Report& report) {
  const ScenesSection& sc = report.scenes;
  std::string md = "## Scenes\n\n" + sc.note + "\n\n";
  for (const auto& t : sc.tables) md += "### " + t.title + "\n\n" + markdown_table(t) + "\n";
  for (const auto& fig : sc.figures) md += fmt::format("![{}](figures/{}.svg)\n\n", md_text(fig.title), fig.id);
  return md;
}

std::vector<FigureView> figure_views(const Figure& f) {
  std::vector<FigureView> views;
  views.push_back(FigureView{"figures/" + f.id + ".svg", f.title, 0.0, f.t_end_s});
  if (f.quantity == Quantity::force && !f.episodes.empty()) {
    const auto& e = f.episodes.front();
    views.push_back(FigureView{
        "figures/" + f.id + "_episode0.svg",
        f.title + fmt::format(" (zoom: {}, t = {:.4g} to {:.4g} s)", e.label, e.t0_s, e.t1_s), e.t0_s,
        e.t1_s});
  }
  return views;
}

std::string markdown_table(const Table& t) {
  // appends only: GCC 12 at -O3 warns falsely (-Wrestrict) on "literal" + string
  std::string md = "|";
  for (const auto& c : t.columns) md.append(" ").append(cell(c)).append(" |");
  md.append("\n|");
  for (std::size_t i = 0; i < t.columns.size(); ++i) md.append("---|");
  md.append("\n");
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    // a failed check stands out in plain text too
    const bool failed = r < t.row_status.size() && t.row_status[r] == "fail";
    md.append("|");
    for (std::size_t i = 0; i < t.columns.size(); ++i) {
      const std::string text = i < t.rows[r].size() ? cell(t.rows[r][i]) : "";
      const char* mark = (i == 0 && failed) ? "**" : "";
      md.append(" ").append(mark).append(text).append(mark).append(" |");
    }
    md.append("\n");
  }
  return md;
}

std::string report_markdown(const Report& report) {
  std::string md = "# planarbench report\n\n";
  std::string files;
  if (!report.results_file.empty()) files += "Results file: " + md_code(report.results_file);
  if (!report.thresholds_file.empty()) files += "; thresholds: " + md_code(report.thresholds_file);
  if (!report.sweep_file.empty()) {
    files += fmt::format("{}weep file: {}", files.empty() ? "S" : "; s", md_code(report.sweep_file));
  }
  if (!report.campaign.file.empty()) {
    files += fmt::format("{}ampaign file: {}", files.empty() ? "C" : "; c", md_code(report.campaign.file));
  }
  if (!report.impacts.file.empty()) {
    files += fmt::format("{}easured impacts: {}", files.empty() ? "M" : "; m",
                         md_code(report.impacts.file));
  }
  md += files + ".\n\n";
  if (!report.check_summary.empty()) md += "**Check:** " + report.check_summary + "\n\n";
  md +=
      "The interactive page `report.html` (same folder) has zoomable figures; here they are "
      "static SVG files in `figures/`, each series min-max decimated to the plot's pixel "
      "columns so that peaks survive.\n\n";

  if (!report.verdict.rows.empty()) section_table(md, report.verdict);

  // contents
  md += "Contents:\n";
  for (const auto& c : report.cases) md += fmt::format("- [{}](#{})\n", md_text(c.name), anchor(c.name));
  if (!report.work_precision.empty()) md += "- [Work-precision](#work-precision)\n";
  if (!report.campaign.cases.empty()) md += "- [Campaign](#campaign)\n";
  if (!report.friction.figures.empty()) md += "- [Friction](#friction)\n";
  if (!report.impacts.file.empty()) md += "- [Measured impacts](#measured-impacts)\n";
  if (!report.validity.table.rows.empty()) md += "- [Physical validity](#physical-validity)\n";
  if (!report.scenes.tables.empty()) md += "- [Scenes](#scenes)\n";
  for (const auto& t : report.tables) md += fmt::format("- [{}](#{})\n", md_text(t.title), anchor(t.title));
  if (!report.results_file.empty()) md += "- [Parameter mapping](#parameter-mapping)\n";
  md += "\n";

  for (const auto& c : report.cases) {
    // the case's own text (its file's name, description, paper, assumptions,
    // --set values): shown as text, never as Markdown or HTML
    md.append("## ").append(md_text(c.name)).append("\n\n").append(md_block(c.description));
    md.append("\n\n");
    if (!c.paper.empty()) md.append("Paper: ").append(md_text(c.paper)).append(". ");
    md += "Truth: " + c.truth + ".\n\n";
    if (!c.overrides.empty()) {
      md += "Overrides (`--set`):";
      for (const auto& [k, v] : c.overrides) md.append(" ").append(md_code(k + "=" + v));
      md += "\n\n";
    }
    if (!c.assumptions.empty()) {
      md += "Assumptions:\n";
      for (const auto& a : c.assumptions) md.append("- ").append(md_block(a)).append("\n");
      md += "\n";
    }
    for (const auto& f : c.figures) {
      for (const auto& v : figure_views(f)) {
        md += fmt::format("![{}]({})\n\n", md_text(v.title), v.file);
      }
      std::string notes;
      for (const auto& s : f.series) {
        if (!s.note.empty())
          notes += fmt::format("{}{}: {}", notes.empty() ? "" : "; ", s.engine, s.note);
      }
      if (!notes.empty()) md.append("Notes: ").append(notes).append(".\n\n");
    }
    if (c.figures.empty() || c.figures.front().series.empty()) {
      md += "(no run of this case is ok: nothing to plot)\n\n";
    }
  }

  if (!report.work_precision.empty()) md += work_precision_markdown(report);
  if (!report.campaign.cases.empty()) md += campaign_markdown(report);
  if (!report.friction.figures.empty()) md += friction_markdown(report);
  if (!report.impacts.file.empty()) md += impacts_markdown(report);
  if (!report.validity.table.rows.empty()) md += validity_markdown(report);
  if (!report.scenes.tables.empty()) md += scenes_markdown(report);
  for (const auto& t : report.tables) section_table(md, t);
  // a sweep-only report has no runs to map
  if (report.results_file.empty()) return md;

  md +=
      "## Parameter mapping\n\nHow each engine expressed each case's contact law, and what it "
      "could not express (each adapter's `mapping` attribute).\n\n";
  for (const auto& m : report.mappings) {
    md += fmt::format("### {} / {} ({})\n\n", md_text(m.case_name), m.engine, m.status);
    if (m.not_expressed.empty()) {
      md += "Could not express: nothing recorded.\n\n";
    } else {
      md += "Could not express:\n";
      for (const auto& n : m.not_expressed) md += "- " + cell(n) + "\n";
      md += "\n";
    }
    const auto flat = flatten_mapping(m.mapping);
    if (!flat.empty() && !(flat.size() == 1 && flat.front().second == "{}")) {
      md += "<details><summary>full mapping</summary>\n\n| key | value |\n|---|---|\n";
      for (const auto& [k, v] : flat) md += "| " + cell(k) + " | " + cell(v) + " |\n";
      md += "\n</details>\n\n";
    }
  }
  return md;
}

}  // namespace pb::internal
