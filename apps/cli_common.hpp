// What the subcommands of the command line share: the cases folder, --set
// parsing and provenance.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "planarbench/settings.hpp"

namespace pb::cli {

// the cases folder: --cases-dir, else $PLANARBENCH_CASES_DIR, else the source tree's cases/
[[nodiscard]] std::filesystem::path cases_dir(const std::string& option);

// --set KEY=VALUE pairs split into those that address the case and those for
// engines; an unknown key is an InputError with a "did you mean".
struct Overrides {
  SettingsOverrides case_keys;
  SettingsOverrides engine_keys;
  std::vector<std::pair<std::string, std::string>> as_given;
};
[[nodiscard]] Overrides parse_overrides(const std::vector<std::string>& assignments);

// a case's own [settings] table under the --set engine keys (--set wins)
[[nodiscard]] SettingsOverrides engine_settings_for(const Case& c, const SettingsOverrides& given);

[[nodiscard]] ResultsProvenance provenance(int argc, char** argv);

}  // namespace pb::cli
