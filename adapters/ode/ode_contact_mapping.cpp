#include "ode_contact_mapping.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <variant>

namespace pb::internal::ode {

SoftRow soft_row(double k, double c, double h, bool corrected) {
  SoftRow r;
  double used = c;  // c', N s/m
  if (corrected) {
    r.correction_valid = c >= h * k;
    used = r.correction_valid ? c - h * k : 0.0;
  }
  const double denom = h * k + used;  // N s/m
  r.erp = h * k / denom;
  r.cfm = 1.0 / denom;
  return r;
}

SoftContact soft_contact(double k, double c, double h, bool corrected) {
  if (!(k > 0.0) || !(c >= 0.0) || !(h > 0.0)) {
    throw std::invalid_argument("soft_contact: needs k > 0, c >= 0, h > 0");
  }
  const SoftRow row = soft_row(k, c, h, corrected);
  SoftContact s;
  s.corrected = corrected;
  s.numerical_damping_ns_per_m = h * k;
  s.erp = row.erp;
  s.cfm = row.cfm;
  s.correction_valid = row.correction_valid;
  if (!corrected) {
    s.damping_used_ns_per_m = c;
    s.note = fmt::format(
        "textbook mapping c' = c: backward Euler adds about h k = {:.6g} N s/m of damping", h * k);
  } else if (row.correction_valid) {
    s.damping_used_ns_per_m = c - h * k;
    s.note = fmt::format("corrected mapping c' = c - h k = {:.6g} - {:.6g} = {:.6g} N s/m", c,
                         h * k, c - h * k);
  } else {
    s.damping_used_ns_per_m = 0.0;
    s.note = fmt::format(
        "corrected mapping invalid: c = {:.6g} < h k = {:.6g} N s/m; clamped at c' = 0 (ERP = 1), "
        "the contact damps like h k instead of c; use a smaller step",
        c, h * k);
  }
  return s;
}

SpreadLaw spread_law(double k, double c, double deepest_m, double depth_m, double depth_sum_m) {
  if (!(depth_sum_m > 0.0)) return {k, c};
  // the shares first: one contact gets exactly 1 and the law itself
  return {k * (deepest_m / depth_sum_m), c * (depth_m / depth_sum_m)};
}

FaceRow face_row(double k, double c, double deepest_m, double depth_m, double depth_sum_m,
               int pressed) {
  const SpreadLaw spread = spread_law(k, c, deepest_m, depth_m, depth_sum_m);
  FaceRow row;
  row.stiffness_n_per_m = spread.stiffness_n_per_m;
  if (pressed <= 1) {
    row.implicit_damping_ns_per_m = spread.damping_ns_per_m;
    return row;
  }
  row.implicit_damping_ns_per_m = c / pressed;
  row.explicit_damping_ns_per_m = spread.damping_ns_per_m - row.implicit_damping_ns_per_m;
  return row;
}

LinearLaw linear_law(const ContactLaw& law, double m, double v) {
  if (!(m > 0.0) || !std::isfinite(m)) {
    throw std::invalid_argument("linear_law: the effective mass must be finite and > 0");
  }
  LinearLaw out;
  out.mass_kg = m;
  const bool nominal_speed = !(v > 0.0);
  out.approach_speed_mps = nominal_speed ? 1.0 : v;
  const std::string speed_note =
      nominal_speed ? " (no approach found: nominal 1 m/s; a linear law does not depend on it)"
                    : "";

  // plain Kelvin-Voigt: the law is a linear spring-damper already
  if (const auto* kv = std::get_if<KelvinVoigt>(&law);
      kv != nullptr && kv->damping_depth_m <= 0.0) {
    out.stiffness_n_per_m = kv->stiffness_n_per_m;
    out.damping_ns_per_m = kv->damping_ns_per_m;
    out.exact = true;
    out.law_response = kelvin_voigt_response(out.stiffness_n_per_m, out.damping_ns_per_m, m,
                                             out.approach_speed_mps);
    out.linear_response = out.law_response;
    out.how = "exact: the law is a linear spring-damper" + speed_note;
    return out;
  }

  // any other law: match the force duration and restitution of one collision
  out.law_response = simulate_collision(law, m, out.approach_speed_mps);
  const double e = out.law_response.restitution;
  if (e >= 1.0 - 1e-9) {
    // elastic: undamped half period T = pi sqrt(m / k)
    const double w = std::numbers::pi / out.law_response.force_duration_s;  // rad/s
    out.stiffness_n_per_m = m * w * w;
    out.damping_ns_per_m = 0.0;
    out.how = "elastic law: k = m (pi / T)^2 from the collision's duration T, c = 0";
  } else {
    const LinearEquivalent eq = linear_equivalent(out.law_response, m);
    out.stiffness_n_per_m = eq.stiffness_n_per_m;
    out.damping_ns_per_m = eq.damping_ns_per_m;
    out.how =
        "linear_equivalent(simulate_collision(law, m_eff, v), m_eff): same force duration and "
        "restitution as the law's collision";
  }
  out.how += speed_note;
  out.linear_response =
      kelvin_voigt_response(out.stiffness_n_per_m, out.damping_ns_per_m, m, out.approach_speed_mps);
  return out;
}

namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// 1 / m_eff contribution of one body, 1/kg
double inverse_mass_along(const Case& c, int body, const std::vector<Vec2>& centres,
                          const Vec2& point, const Vec2& normal) {
  const Body& b = c.bodies.at(static_cast<std::size_t>(body));
  if (b.fixed) return 0.0;
  const Vec2& centre = centres.at(static_cast<std::size_t>(body));
  int joints = 0;
  Vec2 pivot = Vec2::Zero();
  for (const RevoluteJoint& j : c.joints) {
    if (j.body == body) {
      ++joints;
      pivot = j.anchor_world_m;
    }
  }
  if (joints == 0) {
    const double arm = cross(point - centre, normal);  // m
    return 1.0 / b.mass_kg + arm * arm / b.inertia_kgm2;
  }
  if (joints == 1) {
    const double inertia_pivot = b.inertia_kgm2 + b.mass_kg * (centre - pivot).squaredNorm();
    const double arm = cross(point - pivot, normal);  // m
    return arm * arm / inertia_pivot;
  }
  return 0.0;
}

}  // namespace

double effective_mass_kg(const Case& c, const ContactPair& pair, const std::vector<Vec2>& centres,
                         const Vec2& point, const Vec2& normal) {
  const double w = inverse_mass_along(c, pair.body_a, centres, point, normal) +
                   inverse_mass_along(c, pair.body_b, centres, point, normal);
  return w > 0.0 ? 1.0 / w : std::numeric_limits<double>::infinity();
}

int auto_substeps(double dt, const std::vector<StepNeed>& needs, int contact_steps,
                  bool need_hk_le_c) {
  // ceil with a relative allowance, so that an exact ratio (hk == c) stays
  double n = 1.0;
  auto ceil_ratio = [](double x) { return std::ceil(x * (1.0 - 1e-12)); };
  for (const StepNeed& s : needs) {
    if (s.force_duration_s > 0.0) {
      n = std::max(n, ceil_ratio(dt * contact_steps / s.force_duration_s));
    }
    if (need_hk_le_c && s.damping_ns_per_m > 0.0) {
      n = std::max(n, ceil_ratio(dt * s.stiffness_n_per_m / s.damping_ns_per_m));
    }
  }
  if (n > 1e6) throw std::invalid_argument("auto_substeps: more than 1e6 steps per dt needed");
  return static_cast<int>(n);
}

}  // namespace pb::internal::ode
