#include "cli_common.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>

#include "planarbench/case_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"

namespace pb::cli {

std::filesystem::path cases_dir(const std::string& option) {
  if (!option.empty()) return option;
  if (const char* env = std::getenv("PLANARBENCH_CASES_DIR"); env && *env) return env;
  return PB_CASES_DIR;
}

namespace {

// every key --set accepts for engines, prefixed and shared
std::vector<std::string> engine_keys() {
  std::vector<std::string> keys;
  for (const auto& name : engine_names()) {
    const auto engine = make_engine(name);
    for (const auto& spec : engine->settings().specs()) {
      keys.push_back(name + "." + spec.key);
      keys.push_back(spec.key);
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace

Overrides parse_overrides(const std::vector<std::string>& assignments) {
  Overrides out;
  const std::vector<std::string> known = engine_keys();
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw InputError("--set", 0, a, "expected KEY=VALUE");
    }
    const std::string key = a.substr(0, eq);
    const std::string value = a.substr(eq + 1);
    const SettingSource src{"--set", 0};
    if (is_case_key(key)) {
      out.case_keys.set(key, value, src);
    } else if (is_engine_setting_key(key)) {
      out.engine_keys.set(key, value, src);
    } else {
      std::vector<std::string> all = known;
      for (const char* k : {"duration", "output_interval", "gravity", "outline_points", "truth"}) {
        all.emplace_back(k);
      }
      const std::string hint = closest_word(key, all);
      throw InputError(
          "--set", 0, key,
          fmt::format("unknown key{}; case keys: duration, output_interval, gravity, "
                      "outline_points, truth, contact.<field>, contacts.<name>.<field>, "
                      "bodies.<name>.<field>; engine keys: `planarbench list --settings`",
                      hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
    }
    out.as_given.emplace_back(key, value);
  }
  return out;
}

SettingsOverrides engine_settings_for(const Case& c, const SettingsOverrides& given) {
  SettingsOverrides merged;
  for (const auto& [key, text] : c.settings) {
    if (!is_engine_setting_key(key)) {
      const std::string hint = closest_word(key, engine_keys());
      throw InputError(c.source_path, 0, "settings." + key,
                       fmt::format("unknown engine setting{}",
                                   hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
    }
    merged.set(key, text, SettingSource{c.source_path, 0});
  }
  for (const auto& [key, v] : given.all()) merged.set(key, v.text, v.source);
  return merged;
}

ResultsProvenance provenance(int argc, char** argv) {
  ResultsProvenance p;
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.find_first_of(" \t\"'") != std::string::npos) arg = "'" + arg + "'";
    p.command_line += (i ? " " : "") + arg;
  }
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  p.utc_time = buf;
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) == 0) p.host = host;
  return p;
}

}  // namespace pb::cli
