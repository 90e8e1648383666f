#include "planarbench/reference/unclamped_force.hpp"

#include <variant>

#include "planarbench/contact_force.hpp"

namespace pb {

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
  const double b_plus = contact_force_n(law, delta_m, 1.0, approach_speed_mps) - a;
  double b = b_plus;
  if (!(b_plus > 0.0)) {
    // B <= 0: the probe at +1 m/s may have been clamped, the one at -1 m/s is not
    b = a - contact_force_n(law, delta_m, -1.0, approach_speed_mps);
  }
  return a + b * delta_dot_mps;
}

}  // namespace pb
