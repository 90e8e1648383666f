#include "planarbench/reference/unclamped_force.hpp"

#include <variant>

#include "planarbench/contact_force.hpp"

namespace pb {

namespace {

// B of F = A + B delta_dot, given A = F at delta_dot = 0
double damping_given(const ContactLaw& law, double delta_m, double approach_speed_mps, double a) {
  const double b_plus = contact_force_n(law, delta_m, 1.0, approach_speed_mps) - a;
  if (b_plus > 0.0) return b_plus;
  // B <= 0: the probe at +1 m/s may have been clamped, the one at -1 m/s is not
  return a - contact_force_n(law, delta_m, -1.0, approach_speed_mps);
}

}  // namespace

double unclamped_force_n(const ContactLaw& law, double delta_m, double delta_dot_mps,
                         double approach_speed_mps) {
  if (!(delta_m > 0.0)) {
    // smooth continuation below contact
    if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
      const double damping = kv->damping_depth_m > 0.0 ? 0.0 : kv->damping_ns_per_m;
      return kv->stiffness_n_per_m * delta_m + damping * delta_dot_mps;
    }
    return 0.0;
  }
  // F = A + B delta_dot; A is never clamped (the elastic part is >= 0)
  const double a = contact_force_n(law, delta_m, 0.0, approach_speed_mps);
  return a + damping_given(law, delta_m, approach_speed_mps, a) * delta_dot_mps;
}

double law_damping_ns_per_m(const ContactLaw& law, double delta_m, double approach_speed_mps) {
  return damping_given(law, delta_m, approach_speed_mps,
                       contact_force_n(law, delta_m, 0.0, approach_speed_mps));
}

}  // namespace pb
