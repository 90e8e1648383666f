#include "planarbench/case.hpp"

#include <cmath>
#include <numbers>

#include "planarbench/overloaded.hpp"

namespace pb {

const char* shape_type_name(const Shape& shape) {
  return std::visit(overloaded{[](const Circle&) { return "circle"; },
                               [](const Ellipse&) { return "ellipse"; },
                               [](const Polygon&) { return "polygon"; },
                               [](const HalfPlane&) { return "halfplane"; }},
                    shape);
}

const char* contact_law_name(const ContactLaw& law) {
  return std::visit(overloaded{[](const KelvinVoigt&) { return "kelvin_voigt"; },
                               [](const Hertz&) { return "hertz"; },
                               [](const LankaraniNikravesh&) { return "lankarani_nikravesh"; }},
                    law);
}

// paper eqs. 3-4 with the square root of the published Lankarani-Nikravesh
// model (Lankarani & Nikravesh 1990, eq. 3); the seed prints a square (SPEC §1)
double hertz_stiffness(const HertzMaterial& m) {
  const double pi = std::numbers::pi;
  const double h_i = (1.0 - m.poisson_ratio_i * m.poisson_ratio_i) / (pi * m.young_modulus_i_pa);
  const double h_j = (1.0 - m.poisson_ratio_j * m.poisson_ratio_j) / (pi * m.young_modulus_j_pa);
  return 4.0 / (3.0 * pi * (h_i + h_j)) *
         std::sqrt(m.radius_i_m * m.radius_j_m / (m.radius_i_m + m.radius_j_m));
}

const char* scene_kind_name(SceneKind kind) {
  switch (kind) {
    case SceneKind::stack: return "stack";
    case SceneKind::pyramid: return "pyramid";
    case SceneKind::row: return "row";
    case SceneKind::grid: return "grid";
  }
  return "grid";
}

const char* truth_kind_name(TruthKind kind) {
  switch (kind) {
    case TruthKind::none: return "none";
    case TruthKind::analytic: return "analytic";
    case TruthKind::analytic_until_first_contact: return "analytic_until_first_contact";
    case TruthKind::converged: return "converged";
  }
  return "none";
}

int Case::body_index(const std::string& body_name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].name == body_name) return static_cast<int>(i);
  }
  return -1;
}

// the grid t_k = k * output_interval_s, k = 0 .. floor(duration / interval),
// with a 1e-9 relative allowance so that 2.5 / 1e-4 gives 25001 points
int Case::output_samples() const {
  const double n = std::floor(duration_s / output_interval_s * (1.0 + 1e-12) + 1e-9);
  return static_cast<int>(n) + 1;
}

double Case::output_time(int k) const { return static_cast<double>(k) * output_interval_s; }

const ContactPair* Case::first_pair_with_friction() const {
  for (const ContactPair& p : contacts) {
    if (p.has_friction()) return &p;
  }
  return nullptr;
}

std::string inject_friction_reason(const Case& c) {
  for (const ContactGroup& g : c.contact_groups) {
    if (!g.has_friction()) continue;
    return "contact group '" + g.name +
           "' has friction: mode inject applies the case's normal law as a force and has no "
           "Coulomb friction (use the engine's native mode)";
  }
  const ContactPair* p = c.first_pair_with_friction();
  if (p == nullptr) return {};
  return "pair '" + p->name +
         "' has friction: mode inject applies the case's normal law as a force and has no "
         "Coulomb friction (use the engine's native mode)";
}

}  // namespace pb
