// Fuzz target for what engine mujoco3 reads from its other process: a BATCH
// message (adapters/mujoco3/mujoco3_batch.cpp, read_batch; issue 49). The
// first three bytes choose the model's sizes (nq, nv in [0, 7], ngeom in
// [0, 15]); the rest are the message's float64 numbers as the pipe carries
// them (little-endian, any bit pattern: NaN, inf, subnormals).
//
// Checked: read_batch returns or throws EngineError, nothing else; what it
// returns is what its callers index with: every view inside the message,
// each step's qpos and qvel of nq and nv numbers, 2 x 8 warning counters that
// are integers, ncon contacts of the record's or the question's stride, each
// contact's geoms in [0, ngeom), exclude in [0, 4], a record's efc row >= -1.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_check.hpp"
#include "mujoco3_batch.hpp"
#include "planarbench/errors.hpp"

namespace {

using namespace pb::internal::mujoco3;

bool inside(std::span<const double> part, const std::vector<double>& all) {
  return part.empty() ||
         (part.data() >= all.data() && part.data() + part.size() <= all.data() + all.size());
}

void check_step(const BatchStep& s, const BatchLayout& l, std::size_t stride,
                const std::vector<double>& all) {
  PB_FUZZ_CHECK(s.warnings.size() == 2 * kWarnings && inside(s.warnings, all));
  for (const double w : s.warnings) PB_FUZZ_CHECK(std::isfinite(w) && w == std::floor(w));
  PB_FUZZ_CHECK(s.qpos.size() == l.nq && inside(s.qpos, all));
  PB_FUZZ_CHECK(s.qvel.size() == l.nv && inside(s.qvel, all));
  PB_FUZZ_CHECK(s.contacts.size() == s.ncon * stride && inside(s.contacts, all));
  for (std::size_t i = 0; i < s.ncon; ++i) {
    const double* c = s.contacts.data() + i * stride;
    for (int k = 0; k < 2; ++k) {
      PB_FUZZ_CHECK(c[k] >= 0.0 && c[k] < static_cast<double>(l.ngeom) && c[k] == std::floor(c[k]));
    }
    PB_FUZZ_CHECK(c[15] >= 0.0 && c[15] <= 4.0 && c[15] == std::floor(c[15]));
    if (stride == kRecordContactNumbers) PB_FUZZ_CHECK(c[16] >= -1.0 && c[16] == std::floor(c[16]));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const BatchLayout layout{static_cast<std::size_t>(data[0] % 8), static_cast<std::size_t>(data[1] % 8),
                           static_cast<std::size_t>(data[2] % 16)};
  std::vector<double> message((size - 3) / sizeof(double));
  if (!message.empty()) std::memcpy(message.data(), data + 3, message.size() * sizeof(double));
  try {
    const Batch b = read_batch(message, layout);
    for (const BatchStep& s : b.records) check_step(s, layout, kRecordContactNumbers, message);
    if (b.question) check_step(*b.question, layout, kContactNumbers, message);
  } catch (const pb::EngineError&) {
    // refused, naming what is wrong: the run ends diverged with it
  }
  return 0;
}
