#include "report_web_assets.hpp"

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "planarbench/errors.hpp"
#include "report_files.hpp"

#ifndef PB_WEB_DIR
#define PB_WEB_DIR ""
#endif

namespace pb::internal {

namespace fs = std::filesystem;

namespace {

std::string read_asset(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw InputError(
        "report: web asset '" + path.string() +
        "' is missing: run scripts/setup_web.sh (it installs the pinned npm packages into "
        "reports/web/node_modules), or point PLANARBENCH_WEB_DIR at a folder that has them");
  }
  return read_text_file(path);
}

}  // namespace

fs::path web_dir(const fs::path& given) {
  if (!given.empty()) return given;
  if (const char* env = std::getenv("PLANARBENCH_WEB_DIR"); env != nullptr && *env != '\0') {
    return fs::path(env);
  }
  return fs::path(PB_WEB_DIR);
}

WebAssets load_web_assets(const fs::path& dir) {
  if (dir.empty()) {
    throw InputError(
        "report: no web folder known: set PLANARBENCH_WEB_DIR to planarbench's reports/web and "
        "run scripts/setup_web.sh");
  }
  WebAssets a;
  a.dir = dir;
  const fs::path uplot = dir / "node_modules" / "uplot";
  a.uplot_js = read_asset(uplot / "dist" / "uPlot.iife.min.js");
  a.uplot_css = read_asset(uplot / "dist" / "uPlot.min.css");
  a.uplot_license = read_asset(uplot / "LICENSE");
  try {
    a.uplot_version = nlohmann::json::parse(read_asset(uplot / "package.json"))
                          .value("version", std::string("unknown"));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(
        (uplot / "package.json").string(), 0, "version",
        std::string("is not valid JSON: ") + e.what() + "; run scripts/setup_web.sh again");
  }
  a.page_template = read_asset(dir / "report_template.html");
  a.page_js = read_asset(dir / "report.js");
  a.page_css = read_asset(dir / "report.css");
  return a;
}

}  // namespace pb::internal
