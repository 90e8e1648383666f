// MuJoCo's mj_step in its two halves, and a watch on MuJoCo's warnings.
// MuJoCo 2.2.2's mj_step is mj_checkPos, mj_checkVel, mj_forward, mj_checkAcc,
// then mj_RungeKutta(m, d, 4) or mj_Euler (engine_forward.c); calling the two
// halves ourselves is bit-identical (tested) and lets the adapter read the
// contacts and forces of the state a step starts from, which mj_step leaves
// overwritten (RK4 stages) or half-updated (Euler: qpos, qvel advanced,
// everything else not).
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <string>

namespace pb::internal::mujoco {

// first half: checks and mj_forward at the current state
void forward_checked(const mjModel* m, mjData* d);
// second half: the integrator of m->opt (RK4 reuses the qacc of forward_checked)
void integrate(const mjModel* m, mjData* d);

// Counts of MuJoCo's warnings (mjData::warning) seen so far.
class WarningWatch {
 public:
  void reset(const mjData* d);
  // the description of a warning raised since the last call, nullptr if none;
  // the display-only mjWARN_VGEOMFULL is ignored
  const char* new_warning(const mjData* d);

 private:
  std::array<int, mjNWARNING> seen_{};
};

// Routes MuJoCo's warning texts (mju_user_warning, process-global) to a
// thread-local record instead of stdout and a MUJOCO_LOG.TXT in the working
// directory: the adapter reports warnings itself, as EngineError. Installed
// once, only if no other handler is set.
void install_warning_handler();
// the last MuJoCo warning text seen on this thread, "" if none
[[nodiscard]] const std::string& last_warning_text();

}  // namespace pb::internal::mujoco
