#include "two_disks_head_on.hpp"

#include <cmath>

#include "normal_contact_episodes.hpp"

namespace pb::internal {

NormalContactParams TwoDisksHeadOn::relative_params(const Case& c, int a, int b, int pair) {
  const Body& da = c.bodies.at(static_cast<std::size_t>(a));
  const Body& db = c.bodies.at(static_cast<std::size_t>(b));
  const auto& law = std::get<KelvinVoigt>(c.contacts.at(static_cast<std::size_t>(pair)).law);
  const Vec2 dx = db.position_m - da.position_m;
  const Vec2 u = dx / dx.norm();
  NormalContactParams p;
  p.mass_kg = da.mass_kg * db.mass_kg / (da.mass_kg + db.mass_kg);
  p.stiffness_n_per_m = law.stiffness_n_per_m;
  p.damping_ns_per_m = law.damping_ns_per_m;
  p.normal_gravity_mps2 = 0.0;  // gravity moves both disks alike
  p.gap0_m = dx.norm() - std::get<Circle>(da.shape).radius_m - std::get<Circle>(db.shape).radius_m;
  p.gap_rate0_mps = (db.velocity_mps - da.velocity_mps).dot(u);
  return p;
}

TwoDisksHeadOn::TwoDisksHeadOn(const Case& c, int a, int b, int pair)
    : normal_(relative_params(c, a, b, pair)) {
  const Body& da = c.bodies.at(static_cast<std::size_t>(a));
  const Body& db = c.bodies.at(static_cast<std::size_t>(b));
  const ContactPair& cp = c.contacts.at(static_cast<std::size_t>(pair));
  a_ = a;
  b_ = b;
  pair_body_a_ = cp.body_a;
  pair_body_b_ = cp.body_b;
  mass_a_kg_ = da.mass_kg;
  mass_b_kg_ = db.mass_kg;
  radius_a_m_ = std::get<Circle>(da.shape).radius_m;
  radius_b_m_ = std::get<Circle>(db.shape).radius_m;
  const Vec2 dx = db.position_m - da.position_m;
  u_ = dx / dx.norm();
  const double m = mass_a_kg_ + mass_b_kg_;
  centre0_m_ = (mass_a_kg_ * da.position_m + mass_b_kg_ * db.position_m) / m;
  centre_v_mps_ = (mass_a_kg_ * da.velocity_mps + mass_b_kg_ * db.velocity_mps) / m;
  gravity_mps2_ = c.gravity_mps2;
  for (const Body& body : c.bodies) {
    BodyState s;
    s.position_m = body.position_m;
    s.angle_rad = body.angle_rad;
    s.velocity_mps = body.velocity_mps;
    s.angular_velocity_radps = body.angular_velocity_radps;
    initial_.push_back(s);
  }
}

void TwoDisksHeadOn::body_states(double t_s, std::vector<BodyState>& out) const {
  out = initial_;
  const NormalState ns = normal_.state_at(t_s);
  const double m = mass_a_kg_ + mass_b_kg_;
  const Vec2 centre = centre0_m_ + t_s * (centre_v_mps_ + 0.5 * t_s * gravity_mps2_);
  const Vec2 centre_v = centre_v_mps_ + t_s * gravity_mps2_;
  const double r = ns.gap_m + radius_a_m_ + radius_b_m_;  // m, between the centres
  BodyState& sa = out[static_cast<std::size_t>(a_)];
  BodyState& sb = out[static_cast<std::size_t>(b_)];
  sa.position_m = centre - (mass_b_kg_ / m) * r * u_;
  sb.position_m = centre + (mass_a_kg_ / m) * r * u_;
  sa.velocity_mps = centre_v - (mass_b_kg_ / m) * ns.gap_rate_mps * u_;
  sb.velocity_mps = centre_v + (mass_a_kg_ / m) * ns.gap_rate_mps * u_;
  sa.angle_rad = initial_[static_cast<std::size_t>(a_)].angle_rad +
                 initial_[static_cast<std::size_t>(a_)].angular_velocity_radps * t_s;
  sb.angle_rad = initial_[static_cast<std::size_t>(b_)].angle_rad +
                 initial_[static_cast<std::size_t>(b_)].angular_velocity_radps * t_s;
}

void TwoDisksHeadOn::contacts(double t_s, std::vector<ContactSample>& out) const {
  out.clear();
  const NormalState ns = normal_.state_at(t_s);
  if (!(ns.gap_m < 0.0)) return;
  std::vector<BodyState> s;
  body_states(t_s, s);
  const Vec2& xa = s[static_cast<std::size_t>(a_)].position_m;
  const Vec2& xb = s[static_cast<std::size_t>(b_)].position_m;
  ContactSample cs;
  cs.body_a = pair_body_a_;
  cs.body_b = pair_body_b_;
  cs.force_n = ns.force_n;
  cs.penetration_m = -ns.gap_m;
  cs.normal = pair_body_a_ == a_ ? u_ : Vec2(-u_);
  // midpoint of the two disks' surface points on the line of centres
  cs.point_m = 0.5 * ((xa + radius_a_m_ * u_) + (xb - radius_b_m_ * u_));
  out.push_back(cs);
}

std::vector<ContactEpisode> TwoDisksHeadOn::episodes(double now_s) const {
  std::vector<ContactEpisode> eps = normal_contact_episodes(normal_, now_s);
  for (auto& e : eps) {
    e.body_a = pair_body_a_;
    e.body_b = pair_body_b_;
  }
  return eps;
}

long TwoDisksHeadOn::phases_begun(double t_s) const {
  return static_cast<long>(normal_.phase_index_at(t_s)) + 1;
}

nlohmann::json TwoDisksHeadOn::mapping() const {
  const NormalContactParams& p = normal_.params();
  const double omega0 = std::sqrt(normal_.omega0_sq_per_s2());
  nlohmann::json j;
  j["closed_form"] = "two_disks_head_on";
  j["description"] =
      "two free disks on the line of their centres: the centre of mass moves uniformly under "
      "gravity, the spins stay constant, and the gap between the disks is the clamped "
      "Kelvin-Voigt oscillator (paper eq. 1) of the reduced mass, without gravity";
  j["law"] = "kelvin_voigt";
  j["stiffness_n_per_m"] = p.stiffness_n_per_m;
  j["damping_ns_per_m"] = p.damping_ns_per_m;
  j["reduced_mass_kg"] = p.mass_kg;
  j["line_of_centres"] = {u_.x(), u_.y()};
  j["natural_frequency_radps"] = omega0;
  j["damping_ratio"] = normal_.sigma_per_s() / omega0;
  j["initial_gap_m"] = p.gap0_m;
  j["episodes"] =
      "impulse from the relative momentum balance mu du', the same on either disk; "
      "peak force and penetration at closed-form stationary points";
  j["not_expressed"] = nlohmann::json::array();
  return j;
}

}  // namespace pb::internal
