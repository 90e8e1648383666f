// The case's normal contact law written again from the paper's equations
// (seed/000_e4b801bfb88d4695.txt §2.1.2) for the independent truth; it shares
// no code with core/src/contact_force.cpp.
//   Kelvin-Voigt, eq. 1:        F = K delta + c delta_dot; with a damping depth
//                               d > 0 the damping is c s(delta / d), s the cubic
//                               step 3x^2 - 2x^3 on [0, 1] (MSC ADAMS IMPACT's
//                               STEP, the case format's option)
//   Hertz, eq. 2 with c = 0:    F = K delta^n
//   Hertz with hysteresis damping, eqs. 2, 5, 6 (eq. 7 in one line):
//                               F = K delta^n + D delta_dot, D = mu delta^n,
//                               mu = 3 K (1 - e^2) / (4 delta_dot^-),
//                               delta_dot^- the approach speed at this contact's
//                               onset; with no approach (> 0) D is left out
//   K from materials, eqs. 3-4: K = 4 / (3 pi (h_i + h_j)) (R_i R_j / (R_i + R_j))^(1/2),
//                               h_l = (1 - nu_l^2) / (pi E_l), with the square
//                               root of the published Lankarani-Nikravesh model
//                               where the seed prints a square (SPEC §1)
// A normal force never pulls: the truth clamps F at 0 (SPEC §1) by a mode of
// its own (hybrid_integration.hpp), so the unclamped F here stays smooth.
#pragma once

#include <string>

#include "planarbench/case.hpp"

namespace pb::independent {

class NormalLaw {
 public:
  explicit NormalLaw(const ContactLaw& law);

  // the unclamped force, N; for delta < 0 (only inside a step that a located
  // event then cuts short) the odd extension K sign(delta) |delta|^n, so that
  // the right-hand side stays smooth across the event
  [[nodiscard]] double unclamped_force_n(double delta_m, double delta_dot_mps,
                                         double approach_mps) const;
  // a smooth function with the sign of the unclamped force while delta > 0,
  // also at delta = 0+ where F itself starts from 0: K delta + c s delta_dot
  // (Kelvin-Voigt), 1 (Hertz), 1 + mu delta_dot / K (hysteresis damping)
  [[nodiscard]] double pushes(double delta_m, double delta_dot_mps, double approach_mps) const;
  // K as used, N/m^n (from eqs. 3-4 when the case gives materials)
  [[nodiscard]] double stiffness() const { return k_; }
  [[nodiscard]] std::string describe() const;

 private:
  enum class Kind { kelvin_voigt, hertz, hysteresis };
  [[nodiscard]] double damping_factor(double delta_m) const;  // Kelvin-Voigt's s(delta / d)
  [[nodiscard]] double power(double delta_m) const;           // sign(delta) |delta|^n
  Kind kind_ = Kind::kelvin_voigt;
  double k_ = 0.0;        // N/m (Kelvin-Voigt) or N/m^n
  double c_ = 0.0;        // N s/m, Kelvin-Voigt
  double depth_m_ = 0.0;  // m, Kelvin-Voigt's damping depth (0: none)
  double n_ = 1.0;        // exponent
  double e_ = 1.0;        // restitution of the hysteresis law
  std::optional<double> chi_;  // its damping factor when stated (else eq. 6's 3 (1 - e^2) / 4)
};

}  // namespace pb::independent
