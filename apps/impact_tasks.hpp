// The units of work of `planarbench impacts fit` and their folder (SPEC §8):
// per model, one fit per cross-validation fold and one on the whole file.
// A shard (--shard K/N, one Slurm array task) runs its tasks and leaves each
// finished one as WORK/tasks/<model>.<fold>.json (written to a temporary
// name and renamed: a killed shard leaves only whole tasks, and running it
// again runs only the missing ones); `impacts merge` assembles the fit file
// from the folder once every task is there. WORK/study.json pins what the
// tasks were made for (the data's sha256, folds, seed, evaluations, models):
// a shard of another study refuses the folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planarbench/impacts/impact_study.hpp"

namespace pb::cli {

struct ImpactTask {
  std::string model;
  int fold = kWholeFile;
  [[nodiscard]] std::string file_name() const;  // "<model>.<fold|all>.json"
  [[nodiscard]] std::string label() const;      // "mujoco fold 2", "mujoco whole file"
};

// every task of the study: per model its folds, then its whole-file fit
[[nodiscard]] std::vector<ImpactTask> impact_tasks(const std::vector<std::string>& models, int folds);

// tasks of shard k of n: dealt round-robin in impact_tasks' order (every
// engine task costs about the same: the same impacts, the same evaluations)
[[nodiscard]] std::vector<ImpactTask> shard_tasks(const std::vector<ImpactTask>& all, int k, int n);

// Makes WORK (and WORK/tasks) or checks that its study.json is `study`;
// InputError naming the folder and the first field that differs.
void prepare_work_folder(const std::filesystem::path& work, const nlohmann::ordered_json& study);

// What WORK/study.json pins, checked as the command line's options are (it is
// input, issue 35): folds in [2, 20], a seed, the data's sha256 (64 hex
// digits), and 1 to kMaxStudyModels distinct model names of [a-z0-9_] (each
// names task files: no path in it); InputError naming the file and the field.
struct StudyPins {
  std::string data_sha256;
  int folds = 0;
  std::uint64_t seed = 0;
  FitObjective objective = FitObjective::median_plus_mean;
  std::vector<std::string> models;
};
inline constexpr std::size_t kMaxStudyModels = 64;
[[nodiscard]] StudyPins read_study_pins(const std::filesystem::path& work);

[[nodiscard]] bool task_done(const std::filesystem::path& work, const ImpactTask& t);
void write_task(const std::filesystem::path& work, const ImpactTask& t, const FoldFit& f);
// A task file is input (issue 35): it must be the task it is named for (its
// model and fold), predict only rows of the study's table (< impacts), each
// once, and carry as many parameters as the model has; else an InputError
// naming the file and the field, before anything is indexed.
[[nodiscard]] FoldFit read_task(const std::filesystem::path& work, const ImpactTask& t,
                                std::size_t impacts, std::size_t parameters);

}  // namespace pb::cli
