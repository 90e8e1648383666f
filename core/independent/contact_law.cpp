#include "contact_law.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <variant>

namespace pb::independent {

namespace {

// eqs. 3-4 with the square root (SPEC §1)
double stiffness_from_materials(const HertzMaterial& m) {
  const double h_i =
      (1.0 - m.poisson_ratio_i * m.poisson_ratio_i) / (std::numbers::pi * m.young_modulus_i_pa);
  const double h_j =
      (1.0 - m.poisson_ratio_j * m.poisson_ratio_j) / (std::numbers::pi * m.young_modulus_j_pa);
  const double r_eff = m.radius_i_m * m.radius_j_m / (m.radius_i_m + m.radius_j_m);
  return 4.0 / (3.0 * std::numbers::pi * (h_i + h_j)) * std::sqrt(r_eff);
}

}  // namespace

NormalLaw::NormalLaw(const ContactLaw& law) {
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    kind_ = Kind::kelvin_voigt;
    k_ = kv->stiffness_n_per_m;
    c_ = kv->damping_ns_per_m;
    depth_m_ = kv->damping_depth_m;
  } else if (const auto* hz = std::get_if<Hertz>(&law)) {
    kind_ = Kind::hertz;
    k_ = hz->material ? stiffness_from_materials(*hz->material) : hz->stiffness;
    n_ = hz->exponent;
  } else {
    const auto& ln = std::get<LankaraniNikravesh>(law);
    kind_ = Kind::hysteresis;
    k_ = ln.material ? stiffness_from_materials(*ln.material) : ln.stiffness;
    n_ = ln.exponent;
    e_ = ln.restitution;
    // the factor the law states, if any (else eq. 6's, below)
    if (ln.damping_factor) chi_ = *ln.damping_factor;
  }
}

double NormalLaw::damping_factor(double delta_m) const {
  if (!(depth_m_ > 0.0)) return 1.0;
  const double x = delta_m / depth_m_;
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x * x * (3.0 - 2.0 * x);
}

double NormalLaw::power(double delta_m) const {
  return std::copysign(std::pow(std::abs(delta_m), n_), delta_m);
}

double NormalLaw::unclamped_force_n(double delta_m, double delta_dot_mps,
                                    double approach_mps) const {
  switch (kind_) {
    case Kind::kelvin_voigt:
      return k_ * delta_m + c_ * damping_factor(delta_m) * delta_dot_mps;
    case Kind::hertz:
      return k_ * power(delta_m);
    case Kind::hysteresis: {
      const double mu = !(approach_mps > 0.0) ? 0.0
                        : chi_ ? k_ * *chi_ / approach_mps
                               : 3.0 * k_ * (1.0 - e_ * e_) / (4.0 * approach_mps);  // eq. 6
      const double d = mu * power(delta_m);                                              // eq. 5
      return k_ * power(delta_m) + d * delta_dot_mps;
    }
  }
  return 0.0;
}

double NormalLaw::pushes(double delta_m, double delta_dot_mps, double approach_mps) const {
  switch (kind_) {
    case Kind::kelvin_voigt:
      return unclamped_force_n(delta_m, delta_dot_mps, approach_mps);
    case Kind::hertz:
      return 1.0;
    case Kind::hysteresis:
      if (!(approach_mps > 0.0)) return 1.0;
      return chi_ ? 1.0 + *chi_ / approach_mps * delta_dot_mps
                  : 1.0 + 3.0 * (1.0 - e_ * e_) / (4.0 * approach_mps) * delta_dot_mps;
  }
  return 1.0;
}

std::string NormalLaw::describe() const {
  switch (kind_) {
    case Kind::kelvin_voigt:
      return fmt::format("Kelvin-Voigt (eq. 1), K = {:g} N/m, c = {:g} N s/m{}", k_, c_,
                         depth_m_ > 0.0 ? fmt::format(", ramped over {:g} m", depth_m_) : "");
    case Kind::hertz:
      return fmt::format("Hertz (eq. 2), K = {:.6g} N/m^{:g}", k_, n_);
    case Kind::hysteresis:
      return fmt::format(
          "Hertz with hysteresis damping (eqs. 2, 5, 6), K = {:.6g} N/m^{:g}, "
          "e = {:g}{}",
          k_, n_, e_, chi_ ? fmt::format(", damping factor {:g}", *chi_) : std::string());
  }
  return {};
}

}  // namespace pb::independent
