// One measured impact as a case (SPEC §8): the ellipse over horizontal
// ground, started kLeadTime_s before the touch on the ballistic arc that
// reaches the measured pre-impact state (angle, velocities) at the touch, with
// the contact law whose parameters are being fitted.
#pragma once

#include <string>

#include "planarbench/case.hpp"
#include "planarbench/impacts/impact_object.hpp"

namespace pb {

// s: the flight before the touch. 1 ms starts the lowest point 2.2-2.9 mm
// above the ground at the dataset's speeds: ten steps of a 1e-4 s engine, and
// more than the 0.3 mm by which a spin of 30 rad/s can move it.
inline constexpr double kLeadTime_s = 1e-3;
// s: how long a run may last; the softest law fitted (K = 1e3 N/m) rings for
// ~15 ms at the ellipse's smallest effective mass
inline constexpr double kImpactRunLimit_s = 0.06;

// The parameters of the contact law that every engine is fitted with: the
// case's Kelvin-Voigt law (paper eq. 1), each engine expressing it in its own
// model (mapping() says how), and the pair's Coulomb coefficient (SPEC §7).
// Which normal law an impact's case states (issue 34 adds the last two):
//   kelvin_voigt         K, zeta (paper eq. 1)
//   lankarani_nikravesh  K delta^n [1 + 3 (1 - e^2)/4 delta' / delta'-]: K, n, e (eq. 7)
//   hunt_crossley        K delta^n (1 + alpha delta'): K, n, alpha, the restitution
//                        falling with the approach speed; stated as eq. 7's family
//                        with chi = alpha times the impact's approach speed (case.hpp)
enum class ImpactLawKind { kelvin_voigt, lankarani_nikravesh, hunt_crossley };

struct ImpactLaw {
  double stiffness_n_per_m = 1e4;  // N/m, K (N/m^n for the two with an exponent)
  double damping_ratio = 0.2;      // -, zeta: c = 2 zeta sqrt(K m), m the object's mass
  double friction = 0.2;           // -, Coulomb mu
  ImpactLawKind kind = ImpactLawKind::kelvin_voigt;
  double exponent = 1.5;           // n
  double restitution = 0.6;        // e (Lankarani-Nikravesh)
  double damping_s_per_m = 0.0;    // alpha (Hunt-Crossley)
};

// The case of one impact; `outline_points` of the ellipse (the reference and
// every outline-based engine; 180 = the paper's).
[[nodiscard]] Case impact_case(const ImpactObject& o, const ImpactState& at_touch,
                               const ImpactLaw& law, int outline_points = 180);

// The same impact in a world whose length unit is 1/s m (s > 0): every
// length and velocity times s, inertia times s^2, gravity times s; masses,
// angles, rates and time unchanged, so the motion is the same one measured in
// the new unit; a Kelvin-Voigt law keeps its K and c (force and length both
// scale by s), K delta^n's K scales by s^(1 - n). For an engine tuned to a
// size range the object is not in (Box2D: moving objects of 0.1 to 10 m, its
// manual's "Units"), as its users scale their worlds.
[[nodiscard]] Case scaled_impact_case(Case c, double s);
[[nodiscard]] ImpactObject scaled_impact_object(ImpactObject o, double s);

// m, the gap between the ellipse and the ground at t in [0, kLeadTime_s] of the
// ballistic arc (positive: apart); impact_case refuses a state whose arc
// touches before kLeadTime_s.
[[nodiscard]] double ballistic_gap(const ImpactObject& o, const ImpactState& at_touch, double t_s);

// Why `at_touch` cannot be run as an impact ("" when it can): its arc
// touches the ground before the measured touch (the lowest point does not
// approach the ground), sampled at 1/20 of the lead time.
[[nodiscard]] std::string impact_arc_problem(const ImpactObject& o, const ImpactState& at_touch);

}  // namespace pb
