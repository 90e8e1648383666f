#include "check_scope.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "cli_common.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/reports/thresholds.hpp"

namespace pb::cli {

namespace {

bool covered(const std::vector<std::string>& covers, const std::string& engine,
             const std::string& key) {
  return std::find(covers.begin(), covers.end(), key) != covers.end() ||
         std::find(covers.begin(), covers.end(), engine + "." + key) != covers.end();
}

// the case the bands were derived from: the file beside the thresholds, if any
std::optional<Case> derived_case(const std::filesystem::path& thresholds_file,
                                 const std::string& case_name) {
  const auto path = thresholds_file.parent_path() / (case_name + ".toml");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  return load_case(path);
}

// outline resolutions that differ, body by body
void outline_differences(const Case& run, const Case& derived, std::vector<std::string>& out) {
  for (const Body& b : run.bodies) {
    const int i = derived.body_index(b.name);
    if (i < 0) continue;
    const int d = derived.bodies[static_cast<std::size_t>(i)].outline_points;
    if (b.outline_points != d) {
      out.push_back(fmt::format("bodies.{}.outline_points = {} (derived for {})", b.name,
                                b.outline_points, d));
    }
  }
}

// the engine's settings as the bands assume them: its defaults under the
// derived case's own [settings] table
nlohmann::json derived_settings(const std::string& engine, const Case& derived) {
  auto e = make_engine(engine);
  e->settings().apply(engine_settings_for(derived, {}));
  return e->settings().to_json();
}

// what `covers` may hold besides setting and case keys
const std::vector<std::string>& cover_words() {
  static const std::vector<std::string> words = {"foreknowledge", "outline_points", "case_file",
                                                 "truth"};
  return words;
}

}  // namespace

void check_covers(const std::filesystem::path& thresholds_file, const std::vector<std::string>& covers,
                  const std::vector<int>& lines) {
  for (std::size_t i = 0; i < covers.size(); ++i) {
    const std::string& c = covers[i];
    const auto& words = cover_words();
    if (std::find(words.begin(), words.end(), c) != words.end() || is_case_key(c) ||
        is_engine_setting_key(c)) {
      continue;
    }
    // the candidates a typo is likely of: every engine's keys, bare and prefixed
    std::vector<std::string> candidates = words;
    for (const auto& engine : engine_names()) {
      const nlohmann::json settings = make_engine(engine)->settings().to_json();
      for (auto it = settings.begin(); it != settings.end(); ++it) {
        candidates.push_back(it.key());
        candidates.push_back(engine + "." + it.key());
      }
    }
    throw InputError(thresholds_file.string(), i < lines.size() ? lines[i] : 0, "covers",
                     fmt::format("'{}' is no engine setting key (`planarbench list --settings`), "
                                 "case key, or one of {}{}",
                                 c, join_words(words), did_you_mean(c, candidates)));
  }
}

std::vector<RunOutOfScope> runs_out_of_scope(const ResultsFile& results,
                                             const std::vector<Case>& cases,
                                             const std::filesystem::path& thresholds_file,
                                             const std::vector<std::string>& covers,
                                             const std::map<std::string, std::string>& truths) {
  std::vector<RunOutOfScope> out;
  for (std::size_t ci = 0; ci < results.cases.size() && ci < cases.size(); ++ci) {
    const CaseRuns& cr = results.cases[ci];
    const Case& as_run = cases[ci];
    const std::optional<Case> beside = derived_case(thresholds_file, cr.case_name);
    const Case derived = beside ? *beside : parse_case(cr.case_text, cr.case_path, cr.case_name);
    std::vector<std::string> case_differences;
    if (!covered(covers, "", "outline_points")) outline_differences(as_run, derived, case_differences);
    // the whole case (issue 31): a case key given with --set, or a case file
    // edited since the run, makes another case than the bands were derived for
    for (const auto& [key, value] : cr.overrides) {
      if (!is_case_key(key) || key.find("outline_points") != std::string::npos) continue;
      if (covered(covers, "", key)) continue;
      case_differences.push_back(
          fmt::format("{} = {} given with --set (derived for the case file's)", key, value));
    }
    if (beside && !covered(covers, "", "case_file")) {
      const auto path = thresholds_file.parent_path() / (cr.case_name + ".toml");
      std::ifstream in(path, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      if (text.str() != cr.case_text) {
        case_differences.push_back(fmt::format(
            "the case text it was run from differs from {} (the file was edited after the run, "
            "or the run was made from another file of that name)",
            path.string()));
      }
    }
    for (const auto& r : cr.runs) {
      // the truth is judged by no band, but its kind is what the bands assumed
      // (issue 31: the independent truth failing at run time made the
      // converged reference the truth, silently)
      if (r.engine_name == "analytic") {
        const auto want = truths.find(cr.case_name);
        if (want == truths.end() || r.status != RunStatus::ok || covered(covers, "", "truth")) {
          continue;
        }
        // what a file holds is read as it is: a mode that is not a string
        // (an edited file) names no kind, shown as its JSON (issue 49: a
        // number ended `check` in nlohmann's type_error)
        const auto physics = r.mapping.find("physics");
        std::string mode;
        if (physics != r.mapping.end() && physics->is_object()) {
          const auto m = physics->find("mode");
          if (m != physics->end()) mode = m->is_string() ? m->get<std::string>() : m->dump();
        }
        const std::string kind = truth_kind_of_mode(mode);
        if (kind != want->second) {
          out.push_back(RunOutOfScope{
              fmt::format("{}.analytic", cr.case_name),
              {fmt::format("the truth is {} (physics.mode \"{}\"; derived for {})",
                           kind.empty() ? std::string("of no known kind") : "\"" + kind + "\"",
                           mode, "\"" + want->second + "\"")}});
        }
        continue;
      }
      // an unsupported run too: unsupported in the settings the bands were
      // derived for, its metrics are missing (a breach); in others, it is out
      // of scope (issue 35 item 12: mode inject on a friction case said "not
      // computed" instead of naming the setting)
      RunOutOfScope s{fmt::format("{}.{}", cr.case_name, r.engine_name), case_differences};
      const nlohmann::json want = derived_settings(r.engine_name, derived);
      for (const auto& [key, value] : want.items()) {
        if (covered(covers, r.engine_name, key)) continue;
        const auto got = r.settings.find(key);
        if (got == r.settings.end()) {
          s.differences.push_back(fmt::format("{}.{} not recorded (derived for {})",
                                              r.engine_name, key, value.dump()));
        } else if (*got != value) {
          s.differences.push_back(fmt::format("{}.{} = {} (derived for {})", r.engine_name, key,
                                              got->dump(), value.dump()));
        }
      }
      // a look-ahead before the run (SPEC §5b), whatever the mapping says
      const auto ahead = r.extra.find("steps_before_start");
      if (ahead != r.extra.end() && ahead->is_number() && ahead->get<double>() > 0 &&
          !covered(covers, "", "foreknowledge")) {
        s.differences.push_back(fmt::format(
            "steps_before_start = {} (the library stepped before the run: a look-ahead)",
            ahead->dump()));
      }
      const auto physics = r.mapping.find("physics");
      if (physics != r.mapping.end() && physics->is_object() &&
          physics->value("foreknowledge", false) && !covered(covers, "", "foreknowledge")) {
        s.differences.push_back("foreknowledge (a probe run of the case before the run)");
      }
      if (!s.differences.empty()) out.push_back(std::move(s));
    }
  }
  return out;
}

}  // namespace pb::cli
