// A stand-in for reports/web (the page template, its script and style, a
// uPlot folder) for report tests that read the pages, not run them: small
// files with the placeholders the report fills in. `uplot_license` goes into
// uPlot's LICENSE, `uplot_version` into its package.json.
#pragma once

#include <filesystem>
#include <string>

#include "report_files.hpp"

namespace pb::test {

inline void write_fake_web_dir(const std::filesystem::path& web, const std::string& uplot_license,
                               const std::string& uplot_version) {
  const std::filesystem::path u = web / "node_modules" / "uplot";
  internal::ensure_directory(u / "dist");
  internal::write_text_atomically(u / "dist" / "uPlot.iife.min.js", "var uPlot = {};");
  internal::write_text_atomically(u / "dist" / "uPlot.min.css", ".uplot{}");
  internal::write_text_atomically(u / "LICENSE", uplot_license);
  internal::write_text_atomically(u / "package.json", R"({"version": ")" + uplot_version + "\"}");
  internal::write_text_atomically(
      web / "report_template.html",
      "<title>@@TITLE@@</title><style>@@UPLOT_CSS@@@@PAGE_CSS@@</style>"
      "<script type=\"application/json\" id=\"pb-data\">@@DATA@@</script>"
      "<script>/*! uPlot @@UPLOT_VERSION@@ @@UPLOT_LICENSE@@ */@@UPLOT_JS@@</script>"
      "<script>@@PAGE_JS@@</script>");
  internal::write_text_atomically(web / "report.js", "var page = 1;");
  internal::write_text_atomically(web / "report.css", "body{}");
}

}  // namespace pb::test
