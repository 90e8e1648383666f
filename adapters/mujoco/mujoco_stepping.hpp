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
#include <vector>

namespace pb::internal::mujoco {

// A function run inside the forward pass between mj_collision (the contacts
// of the current state are in d->contact) and mj_makeConstraint (their
// solref is read into the constraint rows): native mode's SolrefRule.
using CollisionHook = void (*)(void* context, const mjModel* m, mjData* d);

// A function run between mj_makeConstraint (the rows and their efc_KBIP are
// made) and mj_fwdVelocity (mj_referenceConstraint reads efc_KBIP into
// efc_aref): the opt-in stiff friction rows (mujoco_friction.hpp).
using ConstraintHook = void (*)(const mjModel* m, mjData* d);

// first half: checks and mj_forward at the current state. With a hook,
// mj_forward's stages are called one by one (engine_forward.c 2.2.2:
// mj_fwdPosition = kinematics, comPos, camlight, tendon, crb, factorM,
// collision, makeConstraint, transmission, projectConstraint; then
// fwdVelocity, fwdActuation, fwdAcceleration, fwdConstraint; the model has no
// sensors, energy or control callback) with the hook after mj_collision and
// constraint_hook after mj_makeConstraint.
void forward_checked(const mjModel* m, mjData* d, CollisionHook hook = nullptr,
                     void* context = nullptr, ConstraintHook constraint_hook = nullptr);
// second half: the integrator of m->opt (RK4 reuses the qacc of forward_checked)
void integrate(const mjModel* m, mjData* d);
// every integrate() of this thread, whoever calls it (a run, the oracle's
// probe): a trace the engine reads before and after build to prove that its
// default mode steps nothing ahead of t = 0 (SPEC §5b)
[[nodiscard]] long integrations_on_this_thread();

// What one of MuJoCo's warnings (mjtWarning, mjdata.h) means for a run.
struct WarningInfo {
  const char* name = "";     // "mjWARN_BADQACC"
  const char* meaning = "";  // what MuJoCo found and what it did about it
  // true: the simulation is no longer the case's (state reset, contacts or
  // constraints dropped, mass matrix altered), the run is diverged; false:
  // noted only (rendering buffers, actuators this adapter never makes)
  bool fault = false;
  // what lastinfo is: "DOF", "qpos index", or a count ("contacts (nconmax)")
  const char* info = "";
};
[[nodiscard]] const WarningInfo& warning_info(int warning);

// One kind of warning raised since the last look at the counters.
struct RaisedWarning {
  int warning = -1;  // mjtWarning
  int count = 0;     // times raised since the last look
  int lastinfo = 0;  // mjWarningStat::lastinfo of the last time
};

// Counts of MuJoCo's warnings (mjData::warning) seen so far. MuJoCo raises a
// bad qpos, qvel or qacc in mj_checkPos/Vel/Acc, then calls mj_resetData,
// which zeroes every counter, and counts the bad number again
// (engine_forward.c): a counter below the one seen last means such a reset.
class WarningWatch {
 public:
  void reset(const mjData* d);
  // Every warning raised since the last call (empty, without allocating, when
  // none): bad numbers first (they come with a reset), then the other
  // faults, then noted ones; each kind once with its count.
  [[nodiscard]] std::vector<RaisedWarning> raised(const mjData* d);
  // The description of the first warning raised since the last call
  // ("mjWARN_... (meaning)"), nullptr if none; mjWARN_VGEOMFULL is ignored.
  const char* new_warning(const mjData* d);

 private:
  std::array<int, mjNWARNING> seen_{};
};

// Routes MuJoCo's warning texts (mju_user_warning, process-global) to a
// thread-local record instead of stdout and a MUJOCO_LOG.TXT in the working
// directory: the adapter reports warnings itself, as EngineError. Installed
// once, only if no other handler is set. MuJoCo sends a warning's text the
// first time it is raised in an mjData (or after a reset) only.
void install_warning_handler();
// the last MuJoCo warning text seen on this thread, "" if none
[[nodiscard]] const std::string& last_warning_text();

}  // namespace pb::internal::mujoco
