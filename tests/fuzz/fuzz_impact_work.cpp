// Fuzz target for the files of an `impacts fit --work` folder that `impacts
// merge` and a resumed fit read back (apps/impact_tasks.cpp): the first byte
// chooses the file (even: WORK/study.json, read by read_study_pins; odd: the
// task file WORK/tasks/mujoco.1.json, read by read_task for a study of 40
// impacts and a model of 3 parameters), the rest is its text. Issue 35: a
// task predicting row 999999 crashed merge, -1 read outside the table,
// folds 2e9 in study.json ended in bad_alloc.
//
// The contract fuzzed (impact_tasks.hpp): each file either gives what it
// promises, checked below apart from the reader's code, or throws
// pb::InputError naming the file. Any other exception, a crash or a sanitizer
// report is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "fuzz_check.hpp"
#include "impact_tasks.hpp"
#include "planarbench/errors.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kImpacts = 40;
constexpr std::size_t kParameters = 3;

bool model_name(const std::string& s) {
  if (s.empty() || s.size() > 64) return false;
  for (const char c : s) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return true;
}

void check_pins(const pb::cli::StudyPins& p) {
  PB_FUZZ_CHECK(p.folds >= 2 && p.folds <= 20);
  PB_FUZZ_CHECK(p.data_sha256.size() == 64);
  PB_FUZZ_CHECK(!p.models.empty() && p.models.size() <= pb::cli::kMaxStudyModels);
  for (std::size_t k = 0; k < p.models.size(); ++k) {
    PB_FUZZ_CHECK(model_name(p.models[k]));
    for (std::size_t j = 0; j < k; ++j) PB_FUZZ_CHECK(p.models[j] != p.models[k]);
  }
}

void check_task(const pb::FoldFit& f, const pb::cli::ImpactTask& t) {
  PB_FUZZ_CHECK(f.model == t.model && f.fold == t.fold);
  PB_FUZZ_CHECK(f.fit.parameters.size() == kParameters);
  PB_FUZZ_CHECK(f.outcomes.size() == f.predicted.size());
  std::vector<bool> seen(kImpacts, false);
  for (const std::size_t i : f.predicted) {
    PB_FUZZ_CHECK(i < kImpacts && !seen[i]);
    seen[i] = true;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fs::path work =
      fs::temp_directory_path() / ("pb_fuzz_impact_work_" + std::to_string(::getpid()));
  static const bool made = fs::create_directories(work / "tasks") || fs::is_directory(work / "tasks");
  PB_FUZZ_CHECK(made);
  if (size == 0) return 0;
  const bool study = (data[0] & 1) == 0;
  const pb::cli::ImpactTask task{"mujoco", 1};
  const fs::path file = study ? work / "study.json" : work / "tasks" / task.file_name();
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  static const bool verbose = std::getenv("PB_FUZZ_VERBOSE") != nullptr;
  try {
    if (study) {
      check_pins(pb::cli::read_study_pins(work));
    } else {
      check_task(pb::cli::read_task(work, task, kImpacts, kParameters), task);
    }
    if (verbose) std::fprintf(stderr, "read %s\n", file.c_str());
  } catch (const pb::InputError& e) {
    if (verbose) std::fprintf(stderr, "InputError: %s\n", e.what());
    PB_FUZZ_CHECK(std::string(e.what()).size() > 0);
    PB_FUZZ_CHECK(e.file() == file.string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception %s: %s\n", typeid(e).name(), e.what());
    __builtin_trap();
  }
  return 0;
}
