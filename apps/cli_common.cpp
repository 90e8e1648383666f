#include "cli_common.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <memory>
#include <toml++/toml.h>

#include "planarbench/case_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"

namespace pb::cli {

namespace fs = std::filesystem;

std::filesystem::path cases_dir(const std::string& option) {
  if (!option.empty()) return option;
  if (const char* env = std::getenv("PLANARBENCH_CASES_DIR"); env && *env) return env;
  return PB_CASES_DIR;
}

namespace {

// one engine of each name, made once: their settings binders say which keys
// they take and check values
const std::vector<std::unique_ptr<Engine>>& all_engines() {
  static const auto engines = [] {
    std::vector<std::unique_ptr<Engine>> out;
    for (const auto& name : engine_names()) out.push_back(make_engine(name));
    return out;
  }();
  return engines;
}

// every key --set accepts for engines, prefixed and shared
std::vector<std::string> engine_keys() {
  std::vector<std::string> keys;
  for (const auto& engine : all_engines()) {
    for (const auto& spec : engine->settings().specs()) {
      keys.push_back(engine->name() + "." + spec.key);
      keys.push_back(spec.key);
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

// the engine an "engine.key" names, or empty for a shared key
std::string engine_prefix(const std::string& key) {
  const auto dot = key.find('.');
  if (dot == std::string::npos) return {};
  const std::string prefix = key.substr(0, dot);
  const auto& names = engine_names();
  return std::find(names.begin(), names.end(), prefix) != names.end() ? prefix : std::string();
}

// applies one setting to the engines named (all that bind it when empty)
void check_setting(const std::string& key, const SettingValue& value,
                   const std::vector<std::string>& only) {
  SettingsOverrides one;
  one.set(key, value.text, value.source);
  for (const auto& engine : all_engines()) {
    const bool wanted =
        only.empty() || std::find(only.begin(), only.end(), engine->name()) != only.end();
    if (wanted && engine->settings().knows(key)) engine->settings().apply(one);
  }
}

// ---- one-line CLI11 errors ---------------------------------------------------

// what an option takes, for options whose type alone does not say it
std::string allowed_for(const std::string& option, const std::string& type_name) {
  if (option == "--jobs") return fmt::format("an integer in [1, {}]", kMaxJobs);
  if (type_name == "INT") return "an integer";
  if (type_name == "UINT") return "an integer >= 0";
  if (type_name == "FLOAT") return "a number";
  return "a value of type " + type_name;
}

// the subcommand being parsed when the error came, or the root
const CLI::App* parsed_command(const CLI::App* app) {
  const auto subs = app->get_subcommands();
  return subs.empty() ? app : subs.back();
}

// "--case, --engine, ..." of a command
std::vector<std::string> option_names(const CLI::App* app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app->get_options()) {
    for (const auto& l : o->get_lnames()) names.push_back("--" + l);
  }
  return names;
}

std::vector<std::string> subcommand_names(const CLI::App* app) {
  std::vector<std::string> names;
  for (const CLI::App* s : app->get_subcommands({})) names.push_back(s->get_name());
  return names;
}

// CLI11's message, reworded where it does not say what is allowed
std::string parse_error_text(const CLI::App* app, const CLI::Error& e) {
  std::string what = e.what();
  const CLI::App* cmd = parsed_command(app);
  const std::string usage =
      cmd == app ? "planarbench --help" : fmt::format("planarbench {} --help", cmd->get_name());

  // "Could not convert: --jobs = abc"
  const std::string convert = "Could not convert: ";
  if (what.rfind(convert, 0) == 0) {
    const auto eq = what.find(" = ", convert.size());
    if (eq != std::string::npos) {
      const std::string name = what.substr(convert.size(), eq - convert.size());
      const std::string value = what.substr(eq + 3);
      const CLI::Option* o = cmd->get_option_no_throw(name);
      const std::string type = o != nullptr ? o->get_type_name() : std::string("INT");
      return fmt::format("{}: must be {} (got {})", name, allowed_for(name, type), echo_value(value));
    }
  }
  // an unknown option is the cause even when CLI11 first finds a required
  // option missing (`--engin x` leaves --engine unset)
  if (cmd != app) {
    for (const auto& arg : cmd->remaining()) {
      if (arg.rfind("--", 0) != 0) continue;
      const auto names = option_names(cmd);
      return fmt::format("unknown option {}{}; options: {} (see `{}`)", echo_value(arg),
                         did_you_mean(arg, names), join_words(names), usage);
    }
  }
  // "The following argument was not expected: --frob"
  const std::string extra = "not expected: ";
  if (const auto at = what.find(extra); at != std::string::npos) {
    const std::string arg = what.substr(at + extra.size());
    const bool is_option = arg.rfind('-', 0) == 0;
    const auto names = is_option || cmd != app ? option_names(cmd) : subcommand_names(app);
    return fmt::format("{}{}{}; {}: {} (see `{}`)", what.substr(0, at + extra.size()),
                       echo_value(arg, '\0', 200), did_you_mean(arg, names),
                       is_option || cmd != app ? "options" : "commands", join_words(names), usage);
  }
  // "A subcommand is required", also when the word given is not a command
  if (cmd == app && what.find("subcommand") != std::string::npos) {
    const auto names = subcommand_names(app);
    const auto rest = app->remaining();
    if (!rest.empty() && rest.front().rfind('-', 0) != 0) {
      return fmt::format("unknown command {}{}; commands: {} (see `{}`)", echo_value(rest.front()),
                         did_you_mean(rest.front(), names), join_words(names), usage);
    }
    return fmt::format("{}: one of {} (see `{}`)", what, join_words(names), usage);
  }
  return fmt::format("{} (see `{}`)", what, usage);
}

// one line: newlines of a message would break the "one line" rule, other
// control characters (a NUL ends the printed line) are escaped
std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return printable(s);
}

// ---- [settings] lines of a case file -----------------------------------------

// the node of flattened key `key` in [settings] (keys "a.b" or tables [settings.a])
const toml::node* find_setting(const toml::table& t, const std::string& prefix,
                               const std::string& key) {
  for (auto&& [k, v] : t) {
    const std::string full = prefix + std::string(k.str());
    if (const auto* sub = v.as_table()) {
      if (const auto* n = find_setting(*sub, full + ".", key)) return n;
    } else if (full == key) {
      return &v;
    }
  }
  return nullptr;
}

// line of a [settings] key in the case text, 0 when unknown (--set)
int setting_line(const Case& c, const std::string& key) {
  try {
    const toml::table root = toml::parse(c.source_text, c.source_path);
    if (const auto* s = root.get_as<toml::table>("settings")) {
      if (const auto* n = find_setting(*s, "", key)) return static_cast<int>(n->source().begin.line);
    }
  } catch (const toml::parse_error&) {
    // the loader parsed this text already; no line is better than no message
  }
  return 0;
}

}  // namespace

void use_one_line_errors(CLI::App& app) {
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    return "planarbench: error: " + one_line(parse_error_text(a, e)) + "\n";
  });
}

Overrides parse_overrides(const std::vector<std::string>& assignments) {
  Overrides out;
  const std::vector<std::string> known = engine_keys();
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw InputError("--set", 0, echo_value(a, '\0', 200), "expected KEY=VALUE, e.g. duration=2 or dt=1e-4");
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
      throw InputError(
          "--set", 0, echo_value(key, '\0', 200),
          fmt::format("unknown key{}; case keys: duration, output_interval, gravity, "
                      "outline_points, truth, contact.<field>, contacts.<name>.<field>, "
                      "bodies.<name>.<field>; engine keys: `planarbench list --settings`",
                      did_you_mean(key, all)));
    }
    out.as_given.emplace_back(key, value);
  }
  return out;
}

void check_jobs(int jobs) {
  if (jobs < 1 || jobs > kMaxJobs) {
    throw InputError("--jobs", 0, "",
                     fmt::format("must be an integer in [1, {}] (got '{}')", kMaxJobs, jobs));
  }
}

CLI::Option* check_unsigned_64_text(CLI::Option* option) {
  return option->check(CLI::Validator(
      [](const std::string& text) -> std::string {
        std::uint64_t v = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, v);
        if (text.empty() || ec != std::errc() || ptr != end) {
          return fmt::format("must be an integer in [0, {}] (got {})",
                             std::numeric_limits<std::uint64_t>::max(), echo_value(text));
        }
        return {};
      },
      "UINT64"));
}

void check_repeat(int repeat) {
  if (repeat < 1 || repeat > 100) {
    throw InputError("--repeat", 0, "", fmt::format("must be in [1, 100] (got {})", repeat));
  }
}

void check_output_file(const std::string& option, const fs::path& path) {
  (void)output_target(option, path);
}

bool same_file(const fs::path& a, const fs::path& b) {
  // the same file (also through links), or the same name when neither exists yet
  std::error_code ec, ec2;
  if (fs::equivalent(a, b, ec) && !ec) return true;
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec2) && !ec && !ec2;
}

void check_spares_inputs(const std::string& option, const fs::path& output,
                         const std::vector<NamedInput>& inputs, const std::string& allowed) {
  for (const auto& in : inputs) {
    if (in.path.empty() || !same_file(output, in.path)) continue;
    throw InputError(option, 0, output.string(),
                     fmt::format("names a file this command also reads or writes ({} '{}'); {}",
                                 in.what, in.path.string(), allowed));
  }
}

void check_not_an_input(const std::string& option, const fs::path& output,
                        const std::vector<fs::path>& inputs) {
  for (const auto& in : inputs) {
    if (same_file(output, in)) {
      throw InputError(option, 0, output.string(),
                       fmt::format("names a file this command also reads or writes ('{}'); "
                                   "give another file",
                                   in.string()));
    }
  }
}

void check_engine_spec(const std::string& spec) {
  const auto& names = engine_names();
  if (spec == "all") return;
  for (std::size_t start = 0; start <= spec.size();) {
    const auto comma = spec.find(',', start);
    const std::string item =
        spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (std::find(names.begin(), names.end(), item) == names.end()) {
      throw InputError("--engine", 0, "",
                       fmt::format("unknown engine {}{}; allowed: {}, all, or a comma-separated "
                                   "list of engines",
                                   echo_value(item), did_you_mean(item, names), join_words(names)));
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
}

void check_engine_settings(const SettingsOverrides& given, const std::vector<std::string>& selected) {
  for (const auto& [key, value] : given.all()) {
    const std::string prefix = engine_prefix(key);
    if (!prefix.empty()) {
      check_setting(key, value, {prefix});
      continue;
    }
    std::vector<std::string> binding;
    for (const auto& engine : all_engines()) {
      const bool is_selected =
          std::find(selected.begin(), selected.end(), engine->name()) != selected.end();
      if (is_selected && engine->settings().knows(key)) binding.push_back(engine->name());
    }
    // a key no selected engine takes is still checked, against all that take it
    check_setting(key, value, binding);
  }
}

SettingsOverrides engine_settings_for(const Case& c, const SettingsOverrides& given) {
  SettingsOverrides merged;
  for (const auto& [key, text] : c.settings) {
    const int line = setting_line(c, key);
    if (!is_engine_setting_key(key)) {
      throw InputError(c.source_path, line, "settings." + key,
                       fmt::format("unknown engine setting{}; engine settings: `planarbench list "
                                   "--settings`",
                                   did_you_mean(key, engine_keys())));
    }
    const SettingSource source{c.source_path, line};
    // every engine that takes the key: the case may be run on any of them
    check_setting(key, SettingValue{text, source}, {});
    merged.set(key, text, source);
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
