// Shared by the fault tests: a shipped case run on a real engine with the
// `--set` pairs a user would give, split into case keys (applied when the
// case is loaded) and engine keys (given to the runner), as the command line
// does it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/runner.hpp"

namespace pb::faults_test {

using Sets = std::vector<std::pair<std::string, std::string>>;

inline Case shipped_case(const std::string& name, const Sets& sets) {
  SettingsOverrides case_keys;
  for (const auto& [key, value] : sets) {
    if (is_case_key(key)) case_keys.set(key, value, SettingSource{"--set", 0});
  }
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml", case_keys);
}

inline SettingsOverrides engine_keys(const Sets& sets) {
  SettingsOverrides o;
  for (const auto& [key, value] : sets) {
    if (!is_case_key(key)) o.set(key, value, SettingSource{"--set", 0});
  }
  return o;
}

// `planarbench run --case NAME --engine ENGINE --set k=v ...` without the file
inline RunResult run_shipped(const std::string& name, const std::string& engine, const Sets& sets) {
  const Case c = shipped_case(name, sets);
  auto e = make_engine(engine);
  return run_engine(*e, c, engine_keys(sets));
}

}  // namespace pb::faults_test
