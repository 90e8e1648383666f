#include "mujoco_settings.hpp"

#include <fmt/format.h>

#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {

SettingsBinder bind_mujoco_settings(MujocoSettings& s, MujocoLine line) {
  const bool v3 = line == MujocoLine::v3;
  SettingsBinder b(v3 ? "mujoco3" : "mujoco");
  b.real("dt", &s.dt_s, 1e-7, 1e-2,
         "time step (mjOption::timestep), s, in [1e-7, 1e-2] (default 1e-4)");
  if (v3) {
    b.choice("integrator", &s.integrator, {"Euler", "RK4", "implicit", "implicitfast"},
             "Euler = MuJoCo's default semi-implicit Euler (default), RK4 = 4th-order "
             "Runge-Kutta, implicit / implicitfast = MuJoCo 3's implicit-in-velocity Euler "
             "(implicitfast: without the Coriolis terms, MuJoCo 3's recommended integrator)");
  } else {
    b.choice(
        "integrator", &s.integrator, {"Euler", "RK4"},
        "Euler = MuJoCo's default semi-implicit Euler (default), RK4 = its 4th-order Runge-Kutta");
  }
  b.choice("solver", &s.solver, {"Newton", "CG", "PGS"},
           "constraint solver (default Newton, MuJoCo's default)")
      .integer("iterations", &s.iterations, 1, 100000,
               "constraint solver iterations (default 100, MuJoCo's default)")
      .real("tolerance", &s.tolerance, 0.0, 1.0,
            "constraint solver tolerance, in [0, 1] (default 1e-8, MuJoCo's default)")
      .choice("cone", &s.cone, {"pyramidal", "elliptic"},
              "friction cone of pairs with friction (mjOption::cone; default pyramidal, "
              "MuJoCo's default)")
      .real("impratio", &s.impratio, 1e-6, 1e6,
            "ratio of frictional to normal constraint impedance (mjOption::impratio), in "
            "[1e-6, 1e6] (default 1, MuJoCo's default)")
      .integer("noslip_iterations", &s.noslip_iterations, 0, 100000,
               "noslip solver iterations after the main solve (mjOption::noslip_iterations; "
               "default 0: off, MuJoCo's default)");
  if (v3) {
    b.reals("solreffriction", &s.solreffriction, 2,
            "the friction rows' own solref on every pair with friction (<pair "
            "solreffriction>, MuJoCo >= 2.3.6; the elliptic cone's rows only, so it needs "
            "cone = elliptic): (timeconst, dampratio) > 0 or direct "
            "(-stiffness, -damping) <= 0; default [0, 0] = MuJoCo's default, the friction rows "
            "take the contact's solref (the rule's)");
  } else {
    b.choice("friction_damping", &s.friction_damping, {"shared", "stiff"},
             "damping of the friction rows: shared = the pair's solref, MuJoCo 2.2.2's only "
             "option (default); stiff = opt-in, elliptic cone only: each friction row's B "
             "rewritten after mj_makeConstraint to 2 sqrt(K) of the contact's normal row, so "
             "a slip inside the cone stops within the contact");
  }
  b.reals("solimp", &s.solimp, 5,
          "contact impedance (dmin, dmax, width m, midpoint, power); d in [0.0001, 0.9999] "
          "(default [0.9999, 0.9999, 0.001, 0.5, 2]: near the clamp, the spring-damper is "
          "followed and gravity's share of a resting load is scaled by 1 - d)")
      .real("detection_margin", &s.detection_margin_m, 0.0, 1.0,
            "m, margin of exact-collider pairs, reported as inactive contacts for onset "
            "interpolation; changes no force (default 0.01; MPR pairs always use 0)");
  b.choice("multiccd", &s.multiccd, {"auto", "on", "off"},
           "MuJoCo's multiccd flag: several contacts of a flat mesh-mesh contact instead of one "
           "at a support vertex; auto = on where a contact group lets two polygons meet "
           "(default), off elsewhere");
  b.integer("nconmax", &s.nconmax, 0, 100'000'000,
            v3 ? "contacts the rule's MuJoCo 2.2.2 mirror holds (its <size nconmax>); 0 = the "
                 "adapter's rule from the scene (default; mujoco_capacity.hpp)"
               : "MuJoCo 2.2.2's contact capacity (<size nconmax>); 0 = the adapter's rule from "
                 "the scene (default; MuJoCo's own 100 for a case without contact groups)");
  if (!v3) {
    b.integer("njmax", &s.njmax, 0, 100'000'000,
              "MuJoCo 2.2.2's constraint-row capacity (<size njmax>; mjData holds njmax x nv "
              "Jacobians and njmax^2 more); 0 = the adapter's rule from the scene (default; "
              "MuJoCo's own 500 for a case without contact groups)");
  } else {
    b.integer("memory_mb", &s.memory_mb, 0, 2000,
              "MB of MuJoCo 3's mjData arena (<size memory>: contacts, constraint rows and the "
              "solver's stack); 0 = MuJoCo 3's own default, its heuristic from nv (default)");
  }
  if (v3) {
    b.choice("mode", &s.mode, {"native"},
             "native = MuJoCo's collision and soft contact, solref set each step from the law "
             "and the current effective mass (the only mode: this build has no mjcb_passive "
             "for inject, and oracle's probe run is not ported)");
  } else {
    b.choice("mode", &s.mode, {"native", "oracle", "inject"},
             "native = MuJoCo's collision and soft contact, solref set each step from the law "
             "and the current effective mass (default); oracle = solref calibrated once on a "
             "probe run of the case (foreknowledge); inject = contacts inactive and the case's "
             "force law applied at MuJoCo's contact geometry");
  }
  return b;
}

void validate_mujoco_settings(const MujocoSettings& s, const SettingsOverrides& given,
                              MujocoLine line) {
  const std::string engine = line == MujocoLine::v3 ? "mujoco3" : "mujoco";
  const auto& srf = s.solreffriction;
  // MuJoCo's solref forms (mjmodel.h): both > 0 (timeconst, dampratio), both
  // <= 0 (direct: -stiffness, -damping), or [0, 0], the default
  if (srf.size() == 2 && !((srf[0] > 0.0 && srf[1] > 0.0) || (srf[0] <= 0.0 && srf[1] <= 0.0))) {
    const SettingValue* v = given.find(engine + ".solreffriction");
    throw InputError(v ? v->source.origin : "defaults", v ? v->source.line : 0,
                     engine + ".solreffriction",
                     fmt::format("must be both > 0 (timeconst, dampratio) or both <= 0 (direct "
                                 "-stiffness, -damping); got [{:g}, {:g}]",
                                 srf[0], srf[1]));
  }
  // MuJoCo reads solreffriction for the elliptic cone's friction rows only
  // (engine_core_constraint.c, mj_makeImpedance: "elliptic contacts use
  // solreffriction in non-normal directions"); with the pyramidal cone it
  // would be silently ignored
  if (srf.size() == 2 && (srf[0] != 0.0 || srf[1] != 0.0) && s.cone != "elliptic") {
    const SettingValue* v = given.find(engine + ".solreffriction");
    throw InputError(v ? v->source.origin : "defaults", v ? v->source.line : 0,
                     engine + ".solreffriction",
                     "acts on the elliptic cone's friction rows only (MuJoCo's mj_makeImpedance); "
                     "set " + engine + ".cone=elliptic as well");
  }
  if (s.friction_damping == "stiff" && s.cone != "elliptic") {
    const SettingValue* f = given.find("mujoco.friction_damping");
    throw InputError(f ? f->source.origin : "defaults", f ? f->source.line : 0,
                     "mujoco.friction_damping",
                     "stiff rewrites the elliptic cone's friction rows; set mujoco.cone=elliptic "
                     "as well (the pyramidal cone's rows each carry normal and friction at once)");
  }
  const auto& p = s.solimp;
  // the prefixed key wins over the shared one (settings.hpp)
  const SettingValue* v = given.find(engine + ".solimp");
  const std::string key = v ? engine + ".solimp" : "solimp";
  if (!v) v = given.find("solimp");
  auto bad = [&](const std::string& what) {
    throw InputError(v ? v->source.origin : "defaults", v ? v->source.line : 0, key, what);
  };
  if (p.size() != 5) bad("must be 5 numbers (dmin, dmax, width, midpoint, power)");
  // MuJoCo clamps d to [mjMINIMP, mjMAXIMP] = [0.0001, 0.9999] (mjmodel.h)
  for (int i : {0, 1, 3}) {
    if (p[static_cast<std::size_t>(i)] < 0.0001 || p[static_cast<std::size_t>(i)] > 0.9999) {
      bad(fmt::format("entry {} must be in [0.0001, 0.9999] (got {:g})", i,
                      p[static_cast<std::size_t>(i)]));
    }
  }
  if (!(p[2] >= 0.0)) bad(fmt::format("width must be >= 0 (got {:g})", p[2]));
  if (!(p[4] >= 1.0)) bad(fmt::format("power must be >= 1 (got {:g})", p[4]));
}

}  // namespace pb::internal::mujoco
