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
// naive_bounce: x' and theta' kept, y' -> -e y'.
#pragma once

#include "planarbench/impacts/impact_object.hpp"

namespace pb {

[[nodiscard]] ImpactState rigid_impact(const ImpactObject& o, const ImpactState& before,
                                       double restitution, double friction);

[[nodiscard]] ImpactState naive_bounce(const ImpactState& before, double restitution);

}  // namespace pb
