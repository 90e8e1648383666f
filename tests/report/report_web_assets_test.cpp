// Tests for reports/src/report_web_assets.cpp
#include "report_web_assets.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include "planarbench/errors.hpp"
#include "report_files.hpp"

namespace pb::internal {
namespace {

namespace fs = std::filesystem;

// a web folder laid out as scripts/setup_web.sh leaves it, with stand-in files
fs::path fake_web_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("pb_web_assets_test_" + name);
  fs::remove_all(d);
  ensure_directory(d / "node_modules" / "uplot" / "dist");
  write_text_atomically(d / "node_modules" / "uplot" / "dist" / "uPlot.iife.min.js", "var uPlot;");
  write_text_atomically(d / "node_modules" / "uplot" / "dist" / "uPlot.min.css", ".u{}");
  write_text_atomically(d / "node_modules" / "uplot" / "LICENSE", "MIT");
  write_text_atomically(d / "node_modules" / "uplot" / "package.json", R"({"version": "1.2.3"})");
  write_text_atomically(d / "report_template.html", "@@DATA@@");
  write_text_atomically(d / "report.js", "js");
  write_text_atomically(d / "report.css", "css");
  return d;
}

TEST(LoadWebAssets, ReadsEveryFile) {
  const fs::path d = fake_web_dir("ok");
  const WebAssets a = load_web_assets(d);
  EXPECT_EQ(a.uplot_version, "1.2.3");
  EXPECT_EQ(a.uplot_js, "var uPlot;");
  EXPECT_EQ(a.uplot_license, "MIT");
  EXPECT_EQ(a.page_template, "@@DATA@@");
  fs::remove_all(d);
}

TEST(LoadWebAssets, MissingPackagesSayToRunSetupWeb) {
  const fs::path d = fake_web_dir("missing");
  fs::remove_all(d / "node_modules");
  try {
    (void)load_web_assets(d);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scripts/setup_web.sh"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("uPlot.iife.min.js"), std::string::npos);
  }
  fs::remove_all(d);
}

TEST(WebDir, GivenBeatsEnvironmentBeatsCompiledIn) {
  ::setenv("PLANARBENCH_WEB_DIR", "/from/env", 1);
  EXPECT_EQ(web_dir("/given"), fs::path("/given"));
  EXPECT_EQ(web_dir(""), fs::path("/from/env"));
  ::unsetenv("PLANARBENCH_WEB_DIR");
  // the compiled-in default is the source tree's reports/web
  EXPECT_EQ(web_dir("").filename(), "web");
}

}  // namespace
}  // namespace pb::internal
