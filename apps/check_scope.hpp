// What a thresholds file's bands were derived for (issue 25): each engine at
// its default settings (under the case's own [settings] table), without
// foreknowledge, at the case's own outline resolution. The whys derive their
// numbers from exactly that (the step h, the native mapping, the outline
// sag): a run made otherwise would be judged by bounds that do not hold for
// it, so `check` refuses it unless the thresholds file states, in `covers`,
// what else its bands hold for.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/results_file.hpp"

namespace pb::cli {

// A run made outside what the bands were derived for, and how.
struct RunOutOfScope {
  std::string run;                        // "case.engine"
  std::vector<std::string> differences;   // "mujoco.mode = \"oracle\" (derived for \"native\")"
};

// The runs of `results` that the thresholds in `thresholds_file` were not
// derived for; cases[i] is results.cases[i]'s case as it was run (its text
// under the case keys given with --set). The baseline case of a run is the case file of the same name
// beside the thresholds file when there is one (the case the bands were
// derived from), else the case text stored with the run. `covers` lists what
// the file states its bands also hold for: a setting key ("dt" for every
// engine, "mujoco.mode" for one), a case key given with --set
// ("contact.stiffness", "gravity"), "foreknowledge" (which also admits
// steps_before_start > 0), "outline_points" or "case_file" (a case file that
// differs from the case text stored with the run).
// `truths` (the thresholds file's [truths], case -> kind) refuses a truth run
// (the analytic engine's) of another kind than its case's bands assumed,
// unless `covers` holds "truth".
// Throws InputError naming the thresholds file, the line and the entry when
// an entry of `covers` is none of what runs_out_of_scope reads (a setting key
// of some engine, a case key, "foreknowledge", "outline_points", "case_file",
// "truth"): a typo ("mujoco.dtt") covered nothing and was accepted.
void check_covers(const std::filesystem::path& thresholds_file, const std::vector<std::string>& covers,
                  const std::vector<int>& lines);

[[nodiscard]] std::vector<RunOutOfScope> runs_out_of_scope(
    const ResultsFile& results, const std::vector<Case>& cases,
    const std::filesystem::path& thresholds_file,
    const std::vector<std::string>& covers,
    const std::map<std::string, std::string>& truths = {});

}  // namespace pb::cli
