#include "threshold_names.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>

#include "cli_common.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"

namespace pb::cli {

namespace {

// the line of threshold[index].key in the thresholds file (0 when unknown)
int key_line(const toml::table& doc, std::size_t index, const char* key) {
  const toml::node* n = doc["threshold"][index][key].node();
  return n != nullptr ? static_cast<int>(n->source().begin.line) : 0;
}

}  // namespace

void check_threshold_names(const std::string& file, const std::vector<Threshold>& thresholds,
                           const ResultsFile& results) {
  std::vector<std::string> cases;
  for (const auto& cr : results.cases) cases.push_back(cr.case_name);
  for (const char* folder : {"all", "scenes"}) {
    try {
      for (const auto& p : resolve_cases(folder, cases_dir(""))) cases.push_back(p.stem().string());
    } catch (const InputError&) {
      // no cases (or scenes) folder: the results file's cases are all there is
    }
  }
  std::sort(cases.begin(), cases.end());
  cases.erase(std::unique(cases.begin(), cases.end()), cases.end());
  const std::vector<std::string>& engines = engine_names();
  std::vector<std::string> against = {"truth", "self"};
  against.insert(against.end(), engines.begin(), engines.end());

  toml::table doc;
  try {
    doc = toml::parse_file(file);
  } catch (const toml::parse_error&) {
    // load_thresholds parsed it already; lines then fall back to the entry's
  }
  auto fail = [&](std::size_t i, const Threshold& t, const char* key, const std::string& value,
                  const std::vector<std::string>& allowed, const char* what) {
    const int line = key_line(doc, i, key);
    throw InputError(file, line > 0 ? line : t.line, fmt::format("threshold[{}].{}", i, key),
                     fmt::format("unknown {} '{}'{}; allowed: {}", what, value,
                                 did_you_mean(value, allowed), join_words(allowed)));
  };
  auto known = [](const std::vector<std::string>& names, const std::string& s) {
    return std::find(names.begin(), names.end(), s) != names.end();
  };
  for (std::size_t i = 0; i < thresholds.size(); ++i) {
    const Threshold& t = thresholds[i];
    if (!known(cases, t.case_name)) fail(i, t, "case", t.case_name, cases, "case");
    if (!known(engines, t.engine)) fail(i, t, "engine", t.engine, engines, "engine");
    if (!known(against, t.against)) fail(i, t, "against", t.against, against, "baseline");
  }
}

}  // namespace pb::cli
