#include "impact_tasks.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <vector>

#include "planarbench/errors.hpp"

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

nlohmann::json read_study(const fs::path& work) { return read_json(work / "study.json"); }

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
    FoldFit f = fold_fit_from_json(read_json(path));
    if (f.model != t.model || f.fold != t.fold) {
      throw InputError(path.string(), 0, "model, fold",
                       fmt::format("are {} and {}; the file is named for {} (a task file moved or "
                                   "edited: run its shard again)",
                                   f.model, f.fold, t.label()));
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
