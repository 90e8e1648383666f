#include "mujoco_stepping.hpp"

#include <mutex>

namespace pb::internal::mujoco {

namespace {

thread_local std::string t_last_warning;
thread_local long t_integrations = 0;

void record_warning(const char* text) {
  t_last_warning = text ? text : "";
}

// mjtWarning order (mjdata.h); what each check does in MuJoCo 2.2.2:
// mj_factorI clamps a mass-matrix pivot below mjMINVAL (engine_core_smooth.c),
// mj_collision and mj_makeConstraint stop adding at nconmax / njmax,
// mj_checkPos/Vel/Acc reset the state on NaN or |x| > mjMAXVAL (mju_isBad)
constexpr std::array<WarningInfo, mjNWARNING> kWarnings = {{
    {"mjWARN_INERTIA",
     "near-singular inertia matrix: a pivot of the mass matrix below mjMINVAL = 1e-15 was "
     "raised to it, the bodies are no longer the case's",
     true, "DOF"},
    {"mjWARN_CONTACTFULL", "contact list full (nconmax): MuJoCo dropped contacts", true,
     "contacts (nconmax)"},
    {"mjWARN_CNSTRFULL", "constraint list full (njmax): MuJoCo dropped constraints", true,
     "constraint rows (njmax)"},
    {"mjWARN_VGEOMFULL", "visual geom list full: rendering only", false, "geoms"},
    {"mjWARN_BADQPOS",
     "bad number in qpos (NaN, inf or |value| > mjMAXVAL = 1e10): MuJoCo reset the whole state "
     "to the model's initial state",
     true, "qpos index"},
    {"mjWARN_BADQVEL",
     "bad number in qvel (NaN, inf or |value| > mjMAXVAL = 1e10): MuJoCo reset the whole state "
     "to the model's initial state",
     true, "DOF"},
    {"mjWARN_BADQACC",
     "bad number in qacc (NaN, inf or |value| > mjMAXVAL = 1e10): MuJoCo reset the whole state "
     "to the model's initial state",
     true, "DOF"},
    {"mjWARN_BADCTRL", "bad number in ctrl: the adapter makes no actuators, ctrl is unused", false,
     "actuator"},
}};

// the three checks that reset the state come first in a report
constexpr std::array<int, mjNWARNING> kReportOrder = {
    mjWARN_BADQPOS,     mjWARN_BADQVEL,   mjWARN_BADQACC,   mjWARN_INERTIA,
    mjWARN_CONTACTFULL, mjWARN_CNSTRFULL, mjWARN_VGEOMFULL, mjWARN_BADCTRL};

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

void forward_checked(const mjModel* m, mjData* d, CollisionHook hook, void* context,
                     ConstraintHook constraint_hook) {
  mj_checkPos(m, d);
  mj_checkVel(m, d);
  if (hook == nullptr && constraint_hook == nullptr) {
    mj_forward(m, d);
  } else {
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_camlight(m, d);
    mj_tendon(m, d);
    mj_crb(m, d);
    mj_factorM(m, d);
    mj_collision(m, d);
    if (hook != nullptr) hook(context, m, d);
    mj_makeConstraint(m, d);
    if (constraint_hook != nullptr) constraint_hook(m, d);
    mj_transmission(m, d);
    mj_projectConstraint(m, d);
    mj_fwdVelocity(m, d);
    mj_fwdActuation(m, d);
    mj_fwdAcceleration(m, d);
    mj_fwdConstraint(m, d);
  }
  mj_checkAcc(m, d);
}

void integrate(const mjModel* m, mjData* d) {
  if (m->opt.integrator == mjINT_RK4) {
    mj_RungeKutta(m, d, 4);
  } else {
    mj_Euler(m, d);
  }
  ++t_integrations;
}

long integrations_on_this_thread() { return t_integrations; }

const WarningInfo& warning_info(int warning) {
  static const WarningInfo unknown{"mjWARN_?", "a warning this adapter does not know", true,
                                   "info"};
  if (warning < 0 || warning >= mjNWARNING) return unknown;
  return kWarnings[static_cast<std::size_t>(warning)];
}

void WarningWatch::reset(const mjData* d) {
  for (int i = 0; i < mjNWARNING; ++i) seen_[static_cast<std::size_t>(i)] = d->warning[i].number;
}

std::vector<RaisedWarning> WarningWatch::raised(const mjData* d) {
  // a counter below the one seen means mj_resetData ran: every count is new
  bool was_reset = false;
  for (int i = 0; i < mjNWARNING; ++i) {
    was_reset = was_reset || d->warning[i].number < seen_[static_cast<std::size_t>(i)];
  }
  std::vector<RaisedWarning> out;
  for (const int i : kReportOrder) {
    const auto k = static_cast<std::size_t>(i);
    const int now = d->warning[i].number;
    const int count = was_reset ? now : now - seen_[k];
    seen_[k] = now;
    if (count > 0) out.push_back(RaisedWarning{i, count, d->warning[i].lastinfo});
  }
  return out;
}

const char* WarningWatch::new_warning(const mjData* d) {
  // "name (meaning)" of every warning, built once
  static const std::array<std::string, mjNWARNING> kText = [] {
    std::array<std::string, mjNWARNING> t;
    for (int i = 0; i < mjNWARNING; ++i) {
      const WarningInfo& w = warning_info(i);
      t[static_cast<std::size_t>(i)] = std::string(w.name) + " (" + w.meaning + ")";
    }
    return t;
  }();
  for (const RaisedWarning& w : raised(d)) {
    if (w.warning != mjWARN_VGEOMFULL) return kText[static_cast<std::size_t>(w.warning)].c_str();
  }
  return nullptr;
}

}  // namespace pb::internal::mujoco
