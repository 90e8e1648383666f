// Tests for the determinism of `planarbench run` as a whole (case loader,
// reference solver, adapters, runner, results file): the same command gives
// the same bits, run to run and build to build, through the real binary.
//
// Truth: SHA-256 digests of every dataset, computed by an independent h5py
// script (tests/python/dataset_hashes.py), pinned per case x engine in
// tests/data/determinism/hashes.json. Provenance: blessed from a Release build
// with scripts/bless_hashes.sh; the same file must match in the Debug and
// asan-ubsan builds, since every engine is bitwise reproducible on x86-64
// (SSE2 doubles, no fast-math, no threads inside a run).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "child_process.hpp"

namespace {

namespace fs = std::filesystem;
using namespace pb::test;

const fs::path kPinned = fs::path(PB_SOURCE_DIR) / "tests/data/determinism/hashes.json";

// the pinned command's arguments (everything but --out)
std::vector<std::string> pinned_args() {
  std::ifstream f(kPinned);
  const auto j = nlohmann::json::parse(f);
  return words(j.at("args").get<std::string>());
}

// runs `args --out out`; a diverged run (exit 3) still writes its file and is
// as reproducible as any other, so only bad input or a crash fails here
void run_into(std::vector<std::string> args, const fs::path& out) {
  args.insert(args.end(), {"--out", out.string()});
  const auto r = run_planarbench(args);
  ASSERT_FALSE(r.exit.signaled) << "killed by signal " << r.exit.code << "\n" << r.err;
  ASSERT_TRUE(r.exit.code == 0 || r.exit.code == 3) << "exit " << r.exit.code << "\n" << r.err;
  ASSERT_TRUE(fs::exists(out));
}

// The full matrix against the pinned digests: a mismatch names each changed
// case x engine and says how to re-bless. The digests were blessed by another
// run of the same command on another build (scripts/bless_hashes.sh, Release;
// this runs under the sanitizers too), with two threads taking the tasks in
// whatever order they come: matching them is the same bits run after run and
// build to build (a second matrix here, compared with the first, cost CI
// ~45 s and caught nothing this comparison does not). The same file through
// the CI gate: every case on every engine against the committed thresholds
// (cases/thresholds.toml, each tolerance derived in its `why`), failing when
// any engine or the reference solver drifts out of tolerance. One matrix
// serves both (CI time: ~70 s of both cores under the sanitizers).
TEST(PinnedHashes, FullMatrixMatchesTheBlessedDatasetsAndPassesTheGate) {
  const fs::path dir = fresh_dir("determinism_pinned");
  const std::vector<std::string> args = pinned_args();
  run_into(args, dir / "first.h5");
  const auto c = dataset_hashes("compare " + kPinned.string() + " " + (dir / "first.h5").string());
  EXPECT_EQ(c.exit.code, 0) << c.err;
  std::printf("%s", c.err.c_str());
  // the gate (the pinned command is `run --case all --engine all`)
  ASSERT_NE(std::find(args.begin(), args.end(), "all"), args.end());
  const auto gate = run_shell(std::string(PB_EXE) + " check --thresholds " + PB_SOURCE_DIR +
                              "/cases/thresholds.toml " + (dir / "first.h5").string());
  EXPECT_EQ(gate.exit.code, 0) << gate.err;
  EXPECT_NE(gate.err.find(" 0 breached"), std::string::npos) << gate.err;
  // the JUnit XML and the Markdown summary land beside the results
  EXPECT_TRUE(fs::exists(dir / "first.junit.xml"));
  EXPECT_TRUE(fs::exists(dir / "first.summary.md"));
}

}  // namespace
