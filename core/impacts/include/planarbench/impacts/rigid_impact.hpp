// The project's rigid-impact baselines (SPEC §8), instantaneous and at the
// contact point of the pre-impact angle (impact_object.hpp):
//
// rigid_impact: Newton restitution and Coulomb friction with a stick check.
// With W = (1/m) I + p p^T / I_c the inverse effective mass of the contact
// point (p = the offset turned by +90 deg, the point's velocity per unit
// omega), the impulse that stops the tangential slip and reverses the normal
// velocity by e, P = W^-1 (-u_t, -(1 + e) u_n), is taken when it lies inside
// the cone |P_t| <= mu P_n (the contact sticks); otherwise the contact slides
// throughout the impact, P = P_n (-mu sign(u_t), 1) with P_n setting the
// normal velocity to -e u_n (Brach, "Mechanical impact dynamics", 1991,
// ch. 4; the law of the dataset's own rigid baselines, Fazeli et al. 2017).
//
// rigid_compliant (issue 34): the rigid law with two compliances of the
// contact that a rigid Coulomb impact lacks, each measured in the data
// (../shared/data/mcube/README.md): (1) restitution that depends on the
// pre-impact state, e = e0 + e1 x' (clamped to [0, 1]; the per-impact
// restitution of the training split correlates -0.60 with x', against
// |r| <= 0.39 for the approach speed, the slip and the angle, and a fitted
// tilt of the ground explains none of it: an empirical law, its mechanism
// not identified); (2) tangential compliance as Stronge's tangential
// restitution e_t (Stronge, "Impact Mechanics", 2000, ch. 8; Brach 1991,
// ch. 4): a contact that sticks rebounds its tangential velocity to -e_t u_t
// (the tangential spring's return), which lets the slip reverse (57 % of the
// impacts reverse theirs), capped by Coulomb as before; e_t = 0 is the rigid
// stick. `gyration_scale` scales the radius of gyration k (the measured lever
// is ~7 % off). With e1 = 0, e_t = 0 and scale 1 it is rigid_impact.
//
// naive_bounce: x' and theta' kept, y' -> -e y'.
#pragma once

#include "planarbench/impacts/impact_object.hpp"

namespace pb {

[[nodiscard]] ImpactState rigid_impact(const ImpactObject& o, const ImpactState& before,
                                       double restitution, double friction);

struct CompliantImpactLaw {
  double restitution = 0.6;             // e0
  double restitution_slope_s_per_m = 0; // e1, de/dx'
  double tangential_restitution = 0.0;  // e_t
  double friction = 0.2;                // mu
  double gyration_scale = 1.0;          // k / k_measured
};
[[nodiscard]] ImpactState rigid_compliant_impact(const ImpactObject& o, const ImpactState& before,
                                                 const CompliantImpactLaw& law);

[[nodiscard]] ImpactState naive_bounce(const ImpactState& before, double restitution);

}  // namespace pb
