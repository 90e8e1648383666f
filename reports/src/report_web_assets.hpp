// The web assets a report page inlines: uPlot's JS, CSS and licence (npm
// package `uplot`, installed by scripts/setup_web.sh into
// reports/web/node_modules) and the page's own template, script and style
// (reports/web). Read at run time, so the binary needs no copy of them.
#pragma once

#include <filesystem>
#include <string>

namespace pb::internal {

struct WebAssets {
  std::filesystem::path dir;  // the web folder they came from
  std::string uplot_version;  // from node_modules/uplot/package.json
  std::string uplot_js;       // dist/uPlot.iife.min.js
  std::string uplot_css;      // dist/uPlot.min.css
  std::string uplot_license;  // LICENSE (MIT)
  std::string page_template;  // report_template.html
  std::string page_js;        // report.js
  std::string page_css;       // report.css
};

// The web folder: `given` when not empty, else $PLANARBENCH_WEB_DIR, else the
// source tree's reports/web compiled in (PB_WEB_DIR).
[[nodiscard]] std::filesystem::path web_dir(const std::filesystem::path& given);

// Loads every asset. A missing file is an InputError that names it and says
// to run scripts/setup_web.sh.
[[nodiscard]] WebAssets load_web_assets(const std::filesystem::path& dir);

}  // namespace pb::internal
