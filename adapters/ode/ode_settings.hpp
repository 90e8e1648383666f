// Settings of the ODE adapter (engine "ode"): a plain struct with stated
// defaults, bound to the keys of `--set ode.KEY=VALUE` (shared key: "dt").
#pragma once

#include <string>

#include "planarbench/settings.hpp"

namespace pb::internal::ode {

struct OdeSettings {
  // s, the base step; "dt" is shared with the other fixed-step engines
  double dt_s = 1e-4;
  // steps per dt: 0 = auto (the smallest n for which the corrected damping
  // mapping is valid and the first impact spans contact_steps steps)
  int substeps = 0;
  // auto substeps: at least this many steps over the first impact's force phase
  int contact_steps = 20;
  // "world": dWorldStep, the direct (Dantzig LCP) solver, deterministic;
  // "quick": dWorldQuickStep, iterative SOR with randomly reordered rows
  std::string stepper = "world";
  // dWorldQuickStep iterations (ODE's default is 20)
  int quick_iterations = 20;
  // "corrected": soft contact from c' = c - h k (removes the backward-Euler
  // damping h k); "textbook": ERP = hk/(hk + c), CFM = 1/(hk + c) (ODE manual)
  std::string damping_mapping = "corrected";
  // "native": ODE contact joints (soft ERP/CFM); "inject": no contact joints,
  // the case's force law applied with dBodyAddForceAtPos at ODE's contact geometry
  std::string mode = "native";
};

// Binds every member of `s` under engine name "ode"; the binder keeps
// pointers into `s`, which must outlive it.
[[nodiscard]] SettingsBinder bind_ode_settings(OdeSettings& s);

}  // namespace pb::internal::ode
