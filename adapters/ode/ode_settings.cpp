#include "ode_settings.hpp"

namespace pb::internal::ode {

SettingsBinder bind_ode_settings(OdeSettings& s) {
  SettingsBinder b("ode");
  b.real("dt", &s.dt_s, 1e-7, 1e-2, "base time step, s, in [1e-7, 1e-2] (default 1e-4)")
      .integer("substeps", &s.substeps, 0, 100000,
               "steps per dt, 0 = auto: smallest n with h k <= c for the corrected damping "
               "mapping and contact_steps steps over the first impact (default 0)")
      .integer("contact_steps", &s.contact_steps, 1, 100000,
               "auto substeps: minimum steps over the first impact's force phase (default 20)")
      .choice("stepper", &s.stepper, {"world", "quick"},
              "world = dWorldStep (direct LCP, default), quick = dWorldQuickStep (SOR, rows "
              "reordered with a reseeded global RNG)")
      .integer("quick_iterations", &s.quick_iterations, 1, 100000,
               "dWorldQuickStep iterations (default 20, ODE's own default)")
      .choice("damping_mapping", &s.damping_mapping, {"corrected", "textbook"},
              "spring-damper to ERP/CFM: corrected uses c' = c - h k (default), textbook "
              "ERP = hk/(hk+c), CFM = 1/(hk+c)")
      .choice("mode", &s.mode, {"native", "inject"},
              "native = ODE soft contact joints (default), inject = the case's force law "
              "applied with dBodyAddForceAtPos at ODE's contact geometry");
  return b;
}

}  // namespace pb::internal::ode
