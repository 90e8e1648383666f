#include "mujoco_stepping.hpp"

#include <mutex>

namespace pb::internal::mujoco {

namespace {

thread_local std::string t_last_warning;

void record_warning(const char* text) {
  t_last_warning = text ? text : "";
}

}  // namespace

void install_warning_handler() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (mju_user_warning == nullptr) mju_user_warning = &record_warning;
  });
}

const std::string& last_warning_text() {
  return t_last_warning;
}

void forward_checked(const mjModel* m, mjData* d) {
  mj_checkPos(m, d);
  mj_checkVel(m, d);
  mj_forward(m, d);
  mj_checkAcc(m, d);
}

void integrate(const mjModel* m, mjData* d) {
  if (m->opt.integrator == mjINT_RK4) {
    mj_RungeKutta(m, d, 4);
  } else {
    mj_Euler(m, d);
  }
}

void WarningWatch::reset(const mjData* d) {
  for (int i = 0; i < mjNWARNING; ++i) seen_[static_cast<std::size_t>(i)] = d->warning[i].number;
}

const char* WarningWatch::new_warning(const mjData* d) {
  // mjtWarning in mjdata.h; mj_checkPos/Vel/Acc reset the state on a bad number
  static constexpr std::array<const char*, mjNWARNING> kText = {
      "near-singular inertia matrix (mjWARN_INERTIA)",
      "contact list full (mjWARN_CONTACTFULL)",
      "constraint list full (mjWARN_CNSTRFULL)",
      "visual geom list full (mjWARN_VGEOMFULL)",
      "bad number in qpos, state reset by MuJoCo (mjWARN_BADQPOS)",
      "bad number in qvel, state reset by MuJoCo (mjWARN_BADQVEL)",
      "bad number in qacc, state reset by MuJoCo (mjWARN_BADQACC)",
      "bad number in ctrl (mjWARN_BADCTRL)",
  };
  const char* found = nullptr;
  for (int i = 0; i < mjNWARNING; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (d->warning[i].number != seen_[k]) {
      seen_[k] = d->warning[i].number;
      if (i != mjWARN_VGEOMFULL && !found) found = kText[k];
    }
  }
  return found;
}

}  // namespace pb::internal::mujoco
