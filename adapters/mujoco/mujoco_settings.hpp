// Settings of the MuJoCo adapter (engine "mujoco"): a plain struct with stated
// defaults, bound to the keys of `--set mujoco.KEY=VALUE` (shared key: "dt").
#pragma once

#include <string>
#include <vector>

#include "planarbench/settings.hpp"

namespace pb::internal::mujoco {

struct MujocoSettings {
  // s, mjOption::timestep; "dt" is shared with the other fixed-step engines
  double dt_s = 1e-4;
  // "Euler" (MuJoCo's default, semi-implicit: velocity first, then position
  // with the new velocity; what MuJoCo's users run) or "RK4"
  std::string integrator = "Euler";
  // "Newton" (MuJoCo's default), "CG" or "PGS"
  std::string solver = "Newton";
  // mjOption::iterations and ::tolerance (MuJoCo's defaults 100 and 1e-8)
  int iterations = 100;
  double tolerance = 1e-8;
  // friction (pairs with friction > 0, condim 3): the friction cone
  // ("pyramidal", MuJoCo's default, or "elliptic"), the ratio of frictional to
  // normal impedance (MuJoCo's default 1) and the noslip solver's iterations
  // (default 0: off), as MuJoCo's users set them in <option>
  std::string cone = "pyramidal";
  double impratio = 1.0;
  int noslip_iterations = 0;
  // the friction rows' damping (issue 31): "shared" (default, MuJoCo 2.2.2 as
  // its users run it: the friction rows take the pair's solref, so a slip
  // decays at the law's b = c / m) or "stiff" (opt-in, elliptic cone only:
  // after mj_makeConstraint each friction row's B in efc_KBIP is rewritten to
  // 2 sqrt(K) of the contact's normal row, so that a slip inside the cone
  // stops within the contact, as a rigid Coulomb stick; MuJoCo 3's
  // solreffriction is the setting that does this there; mujoco_friction.hpp)
  std::string friction_damping = "shared";
  // solimp (dmin, dmax, width m, midpoint, power): impedance d near its clamp
  // 0.9999 makes the constraint follow the reference acceleration -b v - k r,
  // i.e. the spring-damper (ENGINES.md)
  std::vector<double> solimp = {0.9999, 0.9999, 0.001, 0.5, 2.0};
  // m, contact margin of pairs whose collider is exact (plane-sphere,
  // plane-ellipsoid, plane-mesh, sphere-sphere): MuJoCo reports the pair while
  // its distance is below this, as inactive (gap = margin) contacts, so that
  // onsets are interpolated; it changes no force. Pairs through libccd MPR
  // always get margin 0: a margin spoils MPR's depth (measured: 0.4 mm error
  // at 0.01 m margin against 1e-6 m at 0).
  double detection_margin_m = 0.01;
  // "native" (default): MuJoCo's own collision and soft contact, each pair's
  // solref set at every step from the case's law and the effective mass of
  // the current configuration (mujoco_solref_rule.hpp); "oracle": solref set
  // once, calibrated at each pair's first touch in a contact-free probe run
  // (foreknowledge, opt-in); "inject": MuJoCo's contacts kept inactive, the
  // case's own law applied as a force at MuJoCo's contact geometry
  // (mjcb_passive)
  std::string mode = "native";
  // MuJoCo 3 only (engine "mujoco3"): the friction rows' own solref
  // (mjContact::solreffriction, <pair solreffriction>, MuJoCo 2.3.6 on);
  // [0, 0] = MuJoCo's default, the friction rows take the contact's solref
  std::vector<double> solreffriction = {0.0, 0.0};
  // MuJoCo 2.2.2's contact and constraint capacity (<size nconmax njmax>:
  // compiled-in 100 and 500 unless the model states them; mjData is sized
  // for them once, njmax x nv Jacobians and njmax^2 included). 0 = the
  // adapter's rule from the scene (mujoco_capacity.hpp); a case without
  // contact groups keeps MuJoCo's defaults unless these are set
  int nconmax = 0;
  int njmax = 0;
  // MuJoCo's multiccd flag (<option><flag multiccd>): its convex-convex
  // collider (mesh-mesh: two polygons) gives one contact per geom pair, at a
  // support vertex, which cannot hold a flat face (MuJoCo's documentation:
  // "instabilities that typically manifest as sliding or wobbling"); with
  // the flag it looks for more by turning the geoms +-1e-3 rad (2.2.2) or
  // clips the faces (3.3.8, nativeccd). "auto" (default): enabled where a
  // contact group lets two polygons meet (a scene of boxes, as its users
  // build one), off elsewhere (the cases without groups unchanged); "on", "off"
  std::string multiccd = "auto";
  // MuJoCo 3 only: MB of mjData's arena (<size memory>, contacts,
  // constraint rows and the solver's stack share it); 0 = MuJoCo 3's own
  // default (its heuristic from nv)
  int memory_mb = 0;
};

// which MuJoCo a settings struct is bound for: its engine name, and the keys
// its version has
enum class MujocoLine { v2, v3 };

// Binds the members of `s` under engine name "mujoco" (v2: MuJoCo 2.2.2,
// every key but solreffriction) or "mujoco3" (v3: MuJoCo 3.3.8: native mode
// only, no friction_damping, solreffriction, and the integrators implicit and
// implicitfast); the binder keeps pointers into `s`, which must outlive it.
[[nodiscard]] SettingsBinder bind_mujoco_settings(MujocoSettings& s,
                                                  MujocoLine line = MujocoLine::v2);

// Checks what the binder cannot (the solimp ranges of MuJoCo's documentation);
// throws InputError naming the key and where its value came from.
void validate_mujoco_settings(const MujocoSettings& s, const SettingsOverrides& given,
                              MujocoLine line = MujocoLine::v2);

}  // namespace pb::internal::mujoco
