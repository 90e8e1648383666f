// Fuzz target for core/impacts/src/impact_data.cpp (pb::read_impacts, through
// Debian's libmatio) and the angle-convention check it feeds: the bytes are
// a file given as `impacts fit --data` (issue 35: a 416-byte header claiming
// 5e7 x 6 doubles ended in bad_alloc, a file cut short was read as zeros).
//
// The contract fuzzed (impact_data.hpp): every file either gives an
// ImpactSet or throws pb::InputError naming the file. Any other exception, a
// crash, a sanitizer report, an allocation past libFuzzer's -rss_limit_mb, or
// a set that breaks what the reader promises (checked below, apart from the
// reader's code) is a bug. libmatio is Debian's (not instrumented): ASan sees
// what it hands back, not its inside.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>

#include "fuzz_check.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/impacts/impact_convention.hpp"
#include "planarbench/impacts/impact_data.hpp"

namespace {

// the reader's documented limits (impact_data.cpp, SPEC §8): at most 1e5
// impacts; positions within 100 m, angles 1000 rad, speeds 100 m/s, spins
// 1e4 rad/s, every value finite
constexpr std::size_t kMaxImpacts = 100000;
constexpr double kLimits[6] = {100.0, 100.0, 1000.0, 100.0, 100.0, 1e4};

bool hex64(const std::string& s) {
  if (s.size() != 64) return false;
  for (const char c : s) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

void check_set(const pb::ImpactSet& set, const std::string& path) {
  const std::size_t n = set.size();
  PB_FUZZ_CHECK(n >= 1 && n <= kMaxImpacts);
  PB_FUZZ_CHECK(set.post.size() == n && set.drop.size() == n);
  PB_FUZZ_CHECK(set.models.empty() || set.models.size() == n);
  PB_FUZZ_CHECK(set.path == path && hex64(set.sha256));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < 6; ++j) {
      PB_FUZZ_CHECK(std::isfinite(set.pre[i][j]) && std::abs(set.pre[i][j]) <= kLimits[j]);
      PB_FUZZ_CHECK(std::isfinite(set.post[i][j]) && std::abs(set.post[i][j]) <= kLimits[j]);
    }
    // the impact changes the velocity
    PB_FUZZ_CHECK(set.pre[i][3] != set.post[i][3] || set.pre[i][4] != set.post[i][4] ||
                  set.pre[i][5] != set.post[i][5]);
    for (std::size_t j = 0; j < (set.models.empty() ? 0 : 18); ++j) {
      PB_FUZZ_CHECK(std::isfinite(set.models[i][j]) && std::abs(set.models[i][j]) <= kLimits[3 + j % 3]);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // libmatio reads files: one per process, rewritten for every input
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("pb_fuzz_impact_data_" + std::to_string(::getpid()) + ".mat"))
          .string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  static const bool verbose = std::getenv("PB_FUZZ_VERBOSE") != nullptr;
  try {
    const pb::ImpactSet set = pb::read_impacts(path);
    check_set(set, path);
    // what `impacts fit` does next: the convention, decided or refused
    const pb::ConventionCheck c = pb::check_convention(set, pb::ImpactObject{});
    PB_FUZZ_CHECK(c.chosen >= 0 && c.chosen < 4);
    PB_FUZZ_CHECK(c.best().correlation >= pb::kMinCorrelation);
    if (verbose) std::fprintf(stderr, "read: %zu impacts\n", set.size());
  } catch (const pb::InputError& e) {
    if (verbose) std::fprintf(stderr, "InputError: %s\n", e.what());
    PB_FUZZ_CHECK(std::string(e.what()).size() > 0);
    PB_FUZZ_CHECK(e.file() == path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception %s: %s\n", typeid(e).name(), e.what());
    __builtin_trap();
  }
  return 0;
}
