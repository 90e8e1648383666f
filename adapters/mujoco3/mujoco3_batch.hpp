// A BATCH message of the WebAssembly side (wasm/server.mjs) read and checked
// before anything of it is used: its counts and flags, and every integer
// MuJoCo writes as one (a contact's geoms, exclude and efc row, the warning
// counters), which no state of a run, however wild, makes anything else
// (issue 49: geom indices of +-1e6 were read out of the mirror's bounds and
// the run written `ok`). Its real numbers are MuJoCo's to compute: a NaN or
// an infinity in a state or a force is a fault of the run, met when its step
// is reached (the runner's checks of states and contacts), not an error of
// the message. Pure: no MuJoCo type, so the fuzzer
// (tests/fuzz/fuzz_mujoco3_batch.cpp) drives it without a model.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace pb::internal::mujoco3 {

// numbers of one contact in the WebAssembly side's question (wasm/server.mjs):
// geom1, geom2, dist, pos[3], frame[9], exclude
inline constexpr std::size_t kContactNumbers = 16;
// and in a step's record: those, efc_address and mj_contactForce's 6
inline constexpr std::size_t kRecordContactNumbers = 23;
// mjNWARNING of 3.3.8 (mjtWarning, the same eight kinds in the same order as 2.2.2)
inline constexpr std::size_t kWarnings = 8;

// the model's sizes a message is read against
struct BatchLayout {
  std::size_t nq = 0;
  std::size_t nv = 0;
  std::size_t ngeom = 0;
};

// one step's outcome or the question: views into the message
struct BatchStep {
  bool asked = false;                  // a record's: the C++ side was asked at this step
  std::span<const double> warnings;    // numbers[8], lastinfo[8]
  std::span<const double> qpos;
  std::span<const double> qvel;
  std::size_t ncon = 0;
  std::span<const double> contacts;    // ncon x (kRecordContactNumbers or kContactNumbers)
};

struct Batch {
  std::vector<BatchStep> records;
  std::optional<BatchStep> question;   // the contacts of the next step, to be answered
};

// The message's records and question; EngineError naming what is wrong (a
// count that is no count, a message cut short or too long, a flag that is
// neither 0 nor 1, a contact's geom outside [0, ngeom), an exclude or row
// that MuJoCo never writes, a warning counter that is no integer).
[[nodiscard]] Batch read_batch(std::span<const double> message, const BatchLayout& layout);

}  // namespace pb::internal::mujoco3
