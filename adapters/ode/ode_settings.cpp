#include "ode_settings.hpp"

#include "planarbench/errors.hpp"

namespace pb::internal::ode {

SettingsBinder bind_ode_settings(OdeSettings& s) {
  SettingsBinder b("ode");
  b.real("dt", &s.dt_s, 1e-7, 1e-2, "base time step, s, in [1e-7, 1e-2] (default 1e-4)")
      .integer("substeps", &s.substeps, 0, 100000,
               "steps per dt (default 1: ODE at the step given); 0 = auto, mode=oracle only: "
               "smallest n with h k <= c for the corrected damping mapping and contact_steps "
               "steps over the probe's first impact")
      .integer("contact_steps", &s.contact_steps, 1, 100000,
               "auto substeps (oracle): minimum steps over the first impact's force phase "
               "(default 20)")
      .choice("stepper", &s.stepper, {"auto", "world", "quick"},
              "world = dWorldStep (direct LCP), quick = dWorldQuickStep (SOR, rows reordered "
              "with a reseeded global RNG), auto = world for declared pairs, quick for a scene "
              "(contact groups) (default)")
      .integer("quick_iterations", &s.quick_iterations, 1, 100000,
               "dWorldQuickStep iterations (default 20, ODE's own default)")
      .choice("damping_mapping", &s.damping_mapping, {"corrected", "textbook"},
              "spring-damper to ERP/CFM: corrected uses c' = c - h k (default), textbook "
              "ERP = hk/(hk+c), CFM = 1/(hk+c)")
      .choice("mode", &s.mode, {"native", "oracle", "inject"},
              "native = ODE's collision and soft contact joints, ERP/CFM set each step from the "
              "law at the current penetration (default); oracle = one spring-damper calibrated "
              "on a probe run of the case (foreknowledge); inject = the case's force law applied "
              "with dBodyAddForceAtPos at ODE's contact geometry");
  return b;
}

void validate_ode_settings(const OdeSettings& s, const SettingsOverrides& given) {
  if (s.substeps != 0 || s.mode == "oracle") return;
  const SettingValue* v = given.find("ode.substeps");
  const std::string key = v ? "ode.substeps" : "substeps";
  if (!v) v = given.find("substeps");
  throw InputError(v ? v->source.origin : "defaults", v ? v->source.line : 0, key,
                   "0 (auto) needs ode.mode=oracle: the step is chosen from the first impact "
                   "of a probe run; give a number of steps per dt >= 1");
}

}  // namespace pb::internal::ode
