#include "planarbench/reference/reference_settings.hpp"

namespace pb {

void bind_reference_settings(SettingsBinder& binder, ReferenceSettings& s) {
  binder
      .choice("geometry", &s.geometry, {"outline", "exact"},
              "contact geometry: outline = the paper's outline points (case outline_points, "
              "paper §2.1.1); exact = true circle/ellipse/line, to separate the outline "
              "discretisation error. Default outline")
      .choice("detection", &s.detection, {"fast", "brute"},
              "outline contact search: fast = bounding-volume trees, O(log N) per evaluation "
              "apart, the same result as brute; brute = every point against every edge, O(N M), "
              "the oracle. Default fast")
      .choice("integrator", &s.integrator, {"rk45", "paper", "fixed"},
              "rk45 = Dormand-Prince 5(4) with error control (rtol, atol) and located events; "
              "paper = RK4 with the paper's gap-driven step (§3.1: h = gap_safety * gap / "
              "closing speed in [h_min, h_max], contact_dt in contact); fixed = classic RK4 at "
              "step dt. Default rk45")
      .real("rtol", &s.rtol, 1e-14, 1e-2, "rk45 relative tolerance, - (1e-14 .. 1e-2, default 1e-10)")
      .real("atol", &s.atol, 1e-18, 1.0,
            "rk45 absolute tolerance per state component (m, rad, m/s, rad/s, N s) "
            "(1e-18 .. 1, default 1e-12)")
      .real("dt", &s.dt, 1e-9, 0.1, "fixed RK4 step, s (1e-9 .. 0.1, default 1e-5)")
      .real("h_max", &s.h_max, 1e-9, 1.0,
            "largest step of rk45 and paper, s (1e-9 .. 1, default 1e-2)")
      .real("h_min", &s.h_min, 1e-12, 1e-2,
            "smallest step of the paper's gap rule, s (1e-12 .. 1e-2, default 1e-7)")
      .real("contact_dt", &s.contact_dt, 1e-10, 1e-2,
            "paper integrator's fixed step while a contact is declared, s "
            "(1e-10 .. 1e-2, default 1e-5)")
      .real("gap_safety", &s.gap_safety, 1e-3, 1.0,
            "paper rule factor in h = gap_safety * gap / closing speed, - "
            "(1e-3 .. 1, default 0.25)");
}

}  // namespace pb
