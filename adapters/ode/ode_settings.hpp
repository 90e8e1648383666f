// Settings of the ODE adapter (engine "ode"): a plain struct with stated
// defaults, bound to the keys of `--set ode.KEY=VALUE` (shared key: "dt").
#pragma once

#include <string>

#include "planarbench/settings.hpp"

namespace pb::internal::ode {

struct OdeSettings {
  // s, the step; "dt" is shared with the other fixed-step engines
  double dt_s = 1e-4;
  // steps per dt: 1 = ODE steps at dt, the step the user gave (default);
  // n > 1: n equal steps per dt; 0 = auto, mode = oracle only: the smallest n
  // for which the corrected damping mapping is valid and the first impact
  // (found by the oracle's probe run) spans contact_steps steps
  int substeps = 1;
  // auto substeps (oracle): at least this many steps over the first impact's force phase
  int contact_steps = 20;
  // "world": dWorldStep, the direct (Dantzig LCP) solver, deterministic;
  // "quick": dWorldQuickStep, iterative SOR with randomly reordered rows;
  // "auto" (default): world for a case of declared pairs, quick for a scene
  // (contact groups): dWorldStep factors each island's dense LCP, O(m^3) in
  // its m rows, and a scene is one island of hundreds to thousands of rows
  // (measured: pyramid_5, 15 bricks, 14x slower than quick; pile_1000 and
  // pyramid_50 out of reach), which is why ODE's users step large worlds
  // with dWorldQuickStep (ODE manual: "for large systems this is a lot faster")
  std::string stepper = "auto";
  // dWorldQuickStep iterations (ODE's default is 20)
  int quick_iterations = 20;
  // "corrected": soft contact from c' = c - h k (removes the backward-Euler
  // damping h k); "textbook": ERP = hk/(hk + c), CFM = 1/(hk + c) (ODE manual)
  std::string damping_mapping = "corrected";
  // "native" (default): ODE's own collision and soft contact joints; every
  // contact's ERP/CFM is set each step, as ODE's near callbacks do, from the
  // case's law at the pair's current penetration (linearised), spread over
  // the pair's contacts. "oracle": the law replaced by one spring-damper
  // calibrated on a contact-free probe run (the first impact's effective mass
  // and speed), deepest contact only: foreknowledge, opt-in. "inject": no
  // contact joints, the case's force law applied with dBodyAddForceAtPos at
  // ODE's contact geometry.
  std::string mode = "native";
};

// Binds every member of `s` under engine name "ode"; the binder keeps
// pointers into `s`, which must outlive it.
[[nodiscard]] SettingsBinder bind_ode_settings(OdeSettings& s);

// Checks what the binder cannot (substeps = 0 needs mode = oracle); throws
// InputError naming the key and where its value came from.
void validate_ode_settings(const OdeSettings& s, const SettingsOverrides& given);

}  // namespace pb::internal::ode
