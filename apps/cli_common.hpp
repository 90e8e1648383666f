// What the subcommands of the command line share: the cases folder, --set
// parsing, the validation of options before anything runs, one-line error
// messages and provenance.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "planarbench/settings.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace pb::cli {

// --jobs: worker threads of the case x engine matrix
inline constexpr int kMaxJobs = 64;

// the cases folder: --cases-dir, else $PLANARBENCH_CASES_DIR, else the source tree's cases/
[[nodiscard]] std::filesystem::path cases_dir(const std::string& option);

// Every error of the command line is one line on stderr,
// "planarbench: error: WHERE: FIELD: what is allowed", also those CLI11 finds
// while parsing (unknown options, bad numbers, missing options). Installs
// that format on the root app.
void use_one_line_errors(CLI::App& app);

// --set KEY=VALUE pairs split into those that address the case and those for
// engines; an unknown key is an InputError with a "did you mean".
struct Overrides {
  SettingsOverrides case_keys;
  SettingsOverrides engine_keys;
  std::vector<std::pair<std::string, std::string>> as_given;
};
[[nodiscard]] Overrides parse_overrides(const std::vector<std::string>& assignments);

// ---- fail-fast checks of options (InputError naming the option) -------------

// --jobs in [1, kMaxJobs]
void check_jobs(int jobs);
// a whole decimal integer in [0, 2^64 - 1], checked on the text: CLI11 reads
// "-1" into an unsigned as 2^64 - 1 and clamps 2^64 to it (issue 35 item 11)
// Returns `option`.
CLI::Option* check_unsigned_64_text(CLI::Option* option);
// --repeat in [1, 100] (run and sweep)
void check_repeat(int repeat);

// a file can be made at `path`: its folder exists, is a folder and accepts a
// new file (tried by creating and removing a probe file, which catches what
// permission bits miss: read-only mounts, /proc, root); `path` is no folder
void check_output_file(const std::string& option, const std::filesystem::path& path);

// `output` is none of `others` (inputs, other outputs): writing it would
// destroy an input or clash with another output
void check_not_an_input(const std::string& option, const std::filesystem::path& output,
                        const std::vector<std::filesystem::path>& inputs);

// An input of a command, as messages name it: `what` ("the results file",
// "--thresholds") and its path.
struct NamedInput {
  std::string what;
  std::filesystem::path path;
};

// `a` and `b` are one file: the same file (also through links: writing one
// through a link replaces the file it names) or the same name once resolved
[[nodiscard]] bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Writing `output` (for `option`) replaces none of `inputs`; else an
// InputError "OPTION: OUTPUT: names a file this command also reads or writes
// (WHAT 'PATH'); ALLOWED". Every command checks each output it writes, the
// files inside an --out folder included, against each of its inputs before
// any work (issue 24).
void check_spares_inputs(const std::string& option, const std::filesystem::path& output,
                         const std::vector<NamedInput>& inputs,
                         const std::string& allowed = "give another file");

// NAME, all or a comma-separated list of engine names, with a "did you mean"
void check_engine_spec(const std::string& spec);

// Engine settings given with --set are valid: an "engine.key" for that engine,
// a shared "key" for every selected engine that binds it or, when none does,
// for every engine that binds it (so a bad value is never silently unused).
void check_engine_settings(const SettingsOverrides& given, const std::vector<std::string>& selected);

// a case's own [settings] table under the --set engine keys (--set wins).
// The case's keys must be engine settings, valid for every engine that binds
// them (a case may be run on any engine); errors name the case file's line.
[[nodiscard]] SettingsOverrides engine_settings_for(const Case& c, const SettingsOverrides& given);

[[nodiscard]] ResultsProvenance provenance(int argc, char** argv);

}  // namespace pb::cli
