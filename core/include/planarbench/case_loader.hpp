// Reads and validates a case file (TOML). Every error is an InputError naming
// the file, the line, the field and what is allowed.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "planarbench/settings.hpp"

namespace pb {

// true when `key` of `--set KEY=VALUE` addresses the case itself rather than
// an engine: duration, output_interval, gravity, outline_points, truth,
// contact.<field> (every contact pair), contacts.<name>.<field>,
// bodies.<name>.<field>.
[[nodiscard]] bool is_case_key(const std::string& key);

// Parses case text. `source` names the file in messages; `case_overrides`
// holds only case keys (is_case_key) and is applied before validation, so an
// override is validated exactly like the file's own value.
[[nodiscard]] Case parse_case(std::string_view text, const std::string& source,
                              const std::string& case_name,
                              const SettingsOverrides& case_overrides = {});

// The case a run of a results file was made of: its stored text under the
// case keys of the --set pairs stored with it (the others address engines).
[[nodiscard]] Case case_as_run(const CaseRuns& runs);

// Loads a case by path. The case name is the file stem.
[[nodiscard]] Case load_case(const std::filesystem::path& path,
                             const SettingsOverrides& case_overrides = {});

// Resolves NAME|FILE|all to case file paths: a name looks in `cases_dir`
// (stem.toml); "all" gives every *.toml of cases_dir that is a case, sorted.
[[nodiscard]] std::vector<std::filesystem::path> resolve_cases(
    const std::string& spec, const std::filesystem::path& cases_dir);

}  // namespace pb
