#include "planarbench/contact_force.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace pb {

double cubic_step(double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x * x * (3.0 - 2.0 * x);
}

namespace {

// paper eq. 1, damping optionally ramped over damping_depth_m (ADAMS IMPACT)
double kelvin_voigt_force(const KelvinVoigt& law, double delta, double delta_dot) {
  const double ramp =
      law.damping_depth_m > 0.0 ? cubic_step(delta / law.damping_depth_m) : 1.0;
  return law.stiffness_n_per_m * delta + ramp * law.damping_ns_per_m * delta_dot;
}

// Hertz: F = K delta^n
double hertz_force(const Hertz& law, double delta) {
  return law.stiffness * std::pow(delta, law.exponent);
}

// paper eq. 7 (Lankarani & Nikravesh 1990): hysteresis damping scaled by the
// approach speed latched at onset; without an approach (a contact that starts
// at rest) the damping term is undefined and left out.
double lankarani_nikravesh_force(const LankaraniNikravesh& law, double delta, double delta_dot,
                                 double approach_speed) {
  const double elastic = law.stiffness * std::pow(delta, law.exponent);
  if (!(approach_speed > 0.0)) return elastic;
  return elastic * (1.0 + damping_factor(law) * delta_dot / approach_speed);
}

}  // namespace

double damping_factor(const LankaraniNikravesh& law) {
  if (law.damping_factor) return *law.damping_factor;
  const double e = law.restitution;
  return 0.75 * (1.0 - e * e);
}

double contact_force_n(const ContactLaw& law, double delta_m, double delta_dot_mps,
                       double approach_speed_mps) {
  if (!(delta_m > 0.0)) return 0.0;
  double f = 0.0;
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    f = kelvin_voigt_force(*kv, delta_m, delta_dot_mps);
  } else if (const auto* hz = std::get_if<Hertz>(&law)) {
    f = hertz_force(*hz, delta_m);
  } else {
    f = lankarani_nikravesh_force(std::get<LankaraniNikravesh>(law), delta_m, delta_dot_mps,
                                  approach_speed_mps);
  }
  // a normal contact force never pulls (SPEC §1)
  return std::max(f, 0.0);
}

LinearizedLaw linearize_law(const ContactLaw& law, double delta_m, double approach_speed_mps) {
  LinearizedLaw out;
  if (!(delta_m > 0.0)) return out;
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    out.stiffness_n_per_m = kv->stiffness_n_per_m;
    const double ramp =
        kv->damping_depth_m > 0.0 ? cubic_step(delta_m / kv->damping_depth_m) : 1.0;
    out.damping_ns_per_m = ramp * kv->damping_ns_per_m;
  } else if (const auto* hz = std::get_if<Hertz>(&law)) {
    out.stiffness_n_per_m = hz->stiffness * std::pow(delta_m, hz->exponent - 1.0);
  } else {
    const auto& ln = std::get<LankaraniNikravesh>(law);
    out.stiffness_n_per_m = ln.stiffness * std::pow(delta_m, ln.exponent - 1.0);
    if (approach_speed_mps > 0.0) {
      // eq. 7's factor in its own order of operations (the pinned results'
      // bits), a stated one as it is
      const double e = ln.restitution;
      out.damping_ns_per_m =
          ln.damping_factor
              ? out.stiffness_n_per_m * delta_m * *ln.damping_factor / approach_speed_mps
              : out.stiffness_n_per_m * delta_m * 0.75 * (1.0 - e * e) / approach_speed_mps;
    }
  }
  return out;
}

}  // namespace pb
