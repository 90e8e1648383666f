#include "impact_tasks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "planarbench/errors.hpp"
#include "planarbench/impacts/fit_objective.hpp"

namespace pb::cli {

namespace fs = std::filesystem;

std::string ImpactTask::file_name() const {
  return fold == kWholeFile ? model + ".all.json" : fmt::format("{}.{}.json", model, fold);
}

std::string ImpactTask::label() const {
  return fold == kWholeFile ? model + " whole file" : fmt::format("{} fold {}", model, fold);
}

std::vector<ImpactTask> impact_tasks(const std::vector<std::string>& models, int folds) {
  std::vector<ImpactTask> out;
  for (const std::string& m : models) {
    for (int f = 0; f < folds; ++f) out.push_back({m, f});
    out.push_back({m, kWholeFile});
  }
  return out;
}

std::vector<ImpactTask> shard_tasks(const std::vector<ImpactTask>& all, int k, int n) {
  std::vector<ImpactTask> out;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(n)) == k) out.push_back(all[i]);
  }
  return out;
}

namespace {

nlohmann::json read_json(const fs::path& path) {
  // a FIFO or a device would block the read forever (issue 35): regular files only
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
    throw InputError(path.string(), 0, "", "is not a regular file (a FIFO, a device or a folder)");
  }
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), 0, "", "cannot be read");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string(), 0, "", fmt::format("is not valid JSON ({})", e.what()));
  }
}

void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << text;
    if (!out.flush()) throw InputError(tmp.string(), 0, "", "cannot be written");
  }
  fs::rename(tmp, path);
}

}  // namespace

void prepare_work_folder(const fs::path& work, const nlohmann::ordered_json& study) {
  std::error_code ec;
  fs::create_directories(work / "tasks", ec);
  if (ec) throw InputError(work.string(), 0, "--work", "cannot be made: " + ec.message());
  const fs::path file = work / "study.json";
  if (!fs::exists(file)) {
    write_atomically(file, study.dump(2) + "\n");
    return;
  }
  const nlohmann::json have = read_json(file);
  for (const auto& [key, value] : study.items()) {
    if (!have.contains(key) || have.at(key) != nlohmann::json(value)) {
      throw InputError(file.string(), 0, key,
                       fmt::format("is {} in the folder, {} in this command: the folder holds "
                                   "another study (use a new --work folder)",
                                   have.contains(key) ? have.at(key).dump() : "missing", value.dump()));
    }
  }
}

StudyPins read_study_pins(const fs::path& work) {
  const fs::path path = work / "study.json";
  const nlohmann::json study = read_json(path);
  const std::string file = path.string();
  StudyPins pins;
  try {
    // integers as written, not converted: -1 would become 2^64 - 1, 2.5 would become 2
    for (const char* key : {"folds", "seed"}) {
      if (!study.at(key).is_number_unsigned()) {
        throw InputError(file, 0, key,
                         fmt::format("is {}: must be a non-negative integer", study.at(key).dump()));
      }
    }
    pins.data_sha256 = study.at("data_sha256").get<std::string>();
    const auto folds = study.at("folds").get<std::uint64_t>();
    if (folds < 2 || folds > 20) {
      throw InputError(file, 0, "folds", fmt::format("is {}: must be in [2, 20]", folds));
    }
    pins.folds = static_cast<int>(folds);
    pins.seed = study.at("seed").get<std::uint64_t>();
    pins.models = study.at("models").get<std::vector<std::string>>();
    const std::optional<FitObjective> o = stated_fit_objective(study);
    if (!o) {
      throw InputError(file, 0, "objective",
                       fmt::format("is '{}': must be '{}' or '{}'",
                                   study.at("objective").get<std::string>(),
                                   fit_objective_words(FitObjective::median_plus_mean),
                                   fit_objective_words(FitObjective::median)));
    }
    pins.objective = *o;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, 0, "data_sha256, folds, seed, models",
                     fmt::format("are not what `impacts fit --work` writes ({})", e.what()));
  }
  const auto hex = [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); };
  if (pins.data_sha256.size() != 64 ||
      !std::all_of(pins.data_sha256.begin(), pins.data_sha256.end(), hex)) {
    throw InputError(file, 0, "data_sha256",
                     fmt::format("is {}: must be 64 lowercase hex digits (a sha256)",
                                 echo_value(pins.data_sha256)));
  }
  if (pins.models.empty() || pins.models.size() > kMaxStudyModels) {
    throw InputError(file, 0, "models",
                     fmt::format("has {} names: must have 1 to {}", pins.models.size(), kMaxStudyModels));
  }
  const auto name_char = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; };
  for (std::size_t k = 0; k < pins.models.size(); ++k) {
    const std::string& m = pins.models[k];
    if (m.empty() || m.size() > 64 || !std::all_of(m.begin(), m.end(), name_char)) {
      throw InputError(file, 0, fmt::format("models[{}]", k),
                       fmt::format("is {}: a model name is 1 to 64 of a-z, 0-9, _", echo_value(m)));
    }
    if (std::find(pins.models.begin(), pins.models.begin() + static_cast<std::ptrdiff_t>(k), m) !=
        pins.models.begin() + static_cast<std::ptrdiff_t>(k)) {
      throw InputError(file, 0, fmt::format("models[{}]", k), fmt::format("'{}' is given twice", m));
    }
  }
  return pins;
}

bool task_done(const fs::path& work, const ImpactTask& t) {
  return fs::exists(work / "tasks" / t.file_name());
}

void write_task(const fs::path& work, const ImpactTask& t, const FoldFit& f) {
  write_atomically(work / "tasks" / t.file_name(), fold_fit_json(f).dump() + "\n");
}

FoldFit read_task(const fs::path& work, const ImpactTask& t, std::size_t impacts,
                  std::size_t parameters) {
  const fs::path path = work / "tasks" / t.file_name();
  try {
    const nlohmann::json j = read_json(path);
    // rows as written, not converted (-1 would read as 2^64 - 1)
    if (j.is_object() && j.contains("predicted") && j.at("predicted").is_array()) {
      const auto& p = j.at("predicted");
      for (std::size_t k = 0; k < p.size(); ++k) {
        if (!p[k].is_number_unsigned()) {
          throw InputError(path.string(), 0, fmt::format("predicted[{}]", k),
                           fmt::format("is {}: each must be a row of the study's table, [0, {}), "
                                       "once",
                                       p[k].dump(), impacts));
        }
      }
    }
    // integers as written (2^32 + 1 is refused, not converted to 1: json_integer.hpp)
    FoldFit f = fold_fit_from_json(j);
    if (f.model != t.model || f.fold != t.fold) {
      throw InputError(path.string(), 0, "model, fold",
                       fmt::format("are {} and {}; the file is named for {} (a task file moved or "
                                   "edited: run its shard again)",
                                   f.model, j.at("fold").dump(), t.label()));
    }
    std::vector<bool> seen(impacts, false);
    for (std::size_t k = 0; k < f.predicted.size(); ++k) {
      const std::size_t i = f.predicted[k];
      if (i >= impacts || seen[i]) {
        throw InputError(path.string(), 0, fmt::format("predicted[{}]", k),
                         fmt::format("is {}: each must be a row of the study's table, [0, {}), "
                                     "once",
                                     i, impacts));
      }
      seen[i] = true;
    }
    if (f.fit.parameters.size() != parameters) {
      throw InputError(path.string(), 0, "parameters",
                       fmt::format("has {} values; model {} has {}", f.fit.parameters.size(),
                                   f.model, parameters));
    }
    return f;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string(), 0, "", fmt::format("is not a task of `impacts fit` ({})", e.what()));
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e) != nullptr) throw;
    throw InputError(path.string(), 0, "", e.what());
  }
}

}  // namespace pb::cli
