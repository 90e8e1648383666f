// Coulomb friction of a case pair on an ODE contact joint (SPEC §7), as ODE's
// users set it (contact.h; ODE 0.16.2, joints/contact.cpp):
//   mode |= dContactApprox1 (mu is a coefficient: the row's bound is
//   mu times this contact's normal force; without it mu is a force in
//   newtons), dContactFDir1 (the first friction direction given: the
//   in-plane tangent (-n_y, n_x, 0)) and dContactMu2 with mu2 = 0 (no second
//   friction row: it would lie along z, where Plane2D already holds the
//   body, and its row would be redundant with Plane2D's).
// With one friction row per contact the pyramid is exact Coulomb in the
// plane. Friction rows are hard (no ERP; world CFM 1e-10 lets a stuck
// contact creep at CFM x its friction force, ~1e-10 m/s per newton).
#pragma once

#include <ode/ode.h>

#include <nlohmann/json.hpp>

namespace pb::internal::ode {

// adds Coulomb friction mu (> 0) to a contact whose geom (normal in z = 0,
// unit) is set; mu = 0 leaves the contact as it is
void add_coulomb_friction(dContact& contact, double mu);

// the mapping's description of a pair's friction (coefficient mu)
[[nodiscard]] nlohmann::json friction_mapping(double mu);

}  // namespace pb::internal::ode
