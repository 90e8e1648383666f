// Settings of engine "reference", bound as "reference.KEY" or "KEY".
#pragma once

#include <string>

#include "planarbench/settings.hpp"

namespace pb {

struct ReferenceSettings {
  // contact geometry: "outline" (the paper's outline points, §2.1.1) or
  // "exact" (true circle / ellipse / line, to separate the outline error)
  std::string geometry = "outline";
  // outline contact search: "fast" (bounding-volume trees, exact: the same
  // result as the brute force; fast_outline_contact.hpp) or "brute" (the
  // O(N M) brute force, the oracle; outline_contact.hpp)
  std::string detection = "fast";
  // "rk45": Dormand-Prince 5(4), error-controlled, located events (default:
  //   the truth at tight tolerance);
  // "paper": RK4 with the paper's gap-driven step (§3.1), fixed contact_dt in contact;
  // "fixed": classic RK4 at step dt (work-precision sweeps)
  std::string integrator = "rk45";
  double rtol = 1e-10;        // -, rk45 relative tolerance
  double atol = 1e-12;        // rk45 absolute tolerance, per state component (m, rad, m/s, rad/s, N s)
  double dt = 1e-5;           // s, fixed RK4 step
  double h_max = 1e-2;        // s, largest step (rk45, paper)
  double h_min = 1e-7;        // s, smallest step of the paper's gap rule
  double contact_dt = 1e-5;   // s, paper integrator's step while a contact is declared
  double gap_safety = 0.25;   // -, paper rule h = gap_safety * gap / closing speed
};

// binds every member to `binder` (keys as in the struct)
void bind_reference_settings(SettingsBinder& binder, ReferenceSettings& s);

}  // namespace pb
