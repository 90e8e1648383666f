#include "disk_on_line.hpp"

#include <cmath>
#include <limits>
#include <variant>

#include "normal_contact_episodes.hpp"

namespace pb::internal {

namespace {

// tangent and outward normal of a half-plane body: its surface is the body x
// axis, its outward normal body +y (case.hpp)
Vec2 line_tangent(const Body& line) {
  return {std::cos(line.angle_rad), std::sin(line.angle_rad)};
}
Vec2 line_normal(const Body& line) {
  return {-std::sin(line.angle_rad), std::cos(line.angle_rad)};
}

}  // namespace

NormalContactParams DiskOnLine::normal_params(const Case& c, int disk, int line, int pair,
                                              bool& snapped) {
  const Body& d = c.bodies.at(static_cast<std::size_t>(disk));
  const Body& l = c.bodies.at(static_cast<std::size_t>(line));
  const auto& law = std::get<KelvinVoigt>(c.contacts.at(static_cast<std::size_t>(pair)).law);
  const double radius = std::get<Circle>(d.shape).radius_m;
  const Vec2 n = line_normal(l);
  const double height = (d.position_m - l.position_m).dot(n);  // centre above the line, m

  NormalContactParams p;
  p.mass_kg = d.mass_kg;
  p.stiffness_n_per_m = law.stiffness_n_per_m;
  p.damping_ns_per_m = law.damping_ns_per_m;
  p.normal_gravity_mps2 = c.gravity_mps2.dot(n);
  p.gap0_m = height - radius;
  p.gap_rate0_mps = d.velocity_mps.dot(n);
  // a gap within the rounding of the numbers that formed it is zero: the case
  // states "touching" through coordinates like R sin 45, R cos 45
  constexpr double eps = std::numeric_limits<double>::epsilon();
  snapped = false;
  if (p.gap0_m != 0.0 && std::abs(p.gap0_m) <= 8.0 * eps * (std::abs(height) + radius)) {
    p.gap0_m = 0.0;
    snapped = true;
  }
  return p;
}

DiskOnLine::DiskOnLine(const Case& c, int disk, int line, int pair)
    : normal_(normal_params(c, disk, line, pair, gap_snapped_)) {
  const Body& d = c.bodies.at(static_cast<std::size_t>(disk));
  const Body& l = c.bodies.at(static_cast<std::size_t>(line));
  const ContactPair& cp = c.contacts.at(static_cast<std::size_t>(pair));
  disk_ = disk;
  pair_body_a_ = cp.body_a;
  pair_body_b_ = cp.body_b;
  disk_is_a_ = cp.body_a == disk;
  radius_m_ = std::get<Circle>(d.shape).radius_m;
  line_origin_m_ = l.position_m;
  tangent_ = line_tangent(l);
  normal_dir_ = line_normal(l);
  along0_m_ = (d.position_m - l.position_m).dot(tangent_);
  along_rate0_mps_ = d.velocity_mps.dot(tangent_);
  along_accel_mps2_ = c.gravity_mps2.dot(tangent_);
  angle0_rad_ = d.angle_rad;
  spin_radps_ = d.angular_velocity_radps;
  for (const Body& b : c.bodies) {
    BodyState s;
    s.position_m = b.position_m;
    s.angle_rad = b.angle_rad;
    if (!b.fixed) {
      s.velocity_mps = b.velocity_mps;
      s.angular_velocity_radps = b.angular_velocity_radps;
    }
    initial_.push_back(s);
  }
}

void DiskOnLine::body_states(double t_s, std::vector<BodyState>& out) const {
  out = initial_;
  const NormalState ns = normal_.state_at(t_s);
  // uniform acceleration along the line, constant spin
  const double along = along0_m_ + t_s * (along_rate0_mps_ + 0.5 * along_accel_mps2_ * t_s);
  const double along_rate = along_rate0_mps_ + along_accel_mps2_ * t_s;
  BodyState& s = out[static_cast<std::size_t>(disk_)];
  s.position_m = line_origin_m_ + along * tangent_ + (ns.gap_m + radius_m_) * normal_dir_;
  s.velocity_mps = along_rate * tangent_ + ns.gap_rate_mps * normal_dir_;
  s.angle_rad = angle0_rad_ + spin_radps_ * t_s;
  s.angular_velocity_radps = spin_radps_;
}

void DiskOnLine::contacts(double t_s, std::vector<ContactSample>& out) const {
  out.clear();
  const NormalState ns = normal_.state_at(t_s);
  if (!(ns.gap_m < 0.0)) return;
  const double along = along0_m_ + t_s * (along_rate0_mps_ + 0.5 * along_accel_mps2_ * t_s);
  const Vec2 centre = line_origin_m_ + along * tangent_ + (ns.gap_m + radius_m_) * normal_dir_;
  ContactSample cs;
  cs.body_a = pair_body_a_;
  cs.body_b = pair_body_b_;
  cs.force_n = ns.force_n;
  cs.penetration_m = -ns.gap_m;
  cs.normal = disk_is_a_ ? Vec2(-normal_dir_) : normal_dir_;
  // midpoint of the disk's deepest point, centre - R n, and its projection
  // onto the line, centre - (R + u) n
  cs.point_m = centre - (radius_m_ + 0.5 * ns.gap_m) * normal_dir_;
  out.push_back(cs);
}

std::vector<ContactEpisode> DiskOnLine::episodes(double now_s) const {
  std::vector<ContactEpisode> eps = normal_contact_episodes(normal_, now_s);
  for (auto& e : eps) {
    e.body_a = pair_body_a_;
    e.body_b = pair_body_b_;
  }
  return eps;
}

long DiskOnLine::phases_begun(double t_s) const {
  return static_cast<long>(normal_.phase_index_at(t_s)) + 1;
}

nlohmann::json DiskOnLine::mapping() const {
  const NormalContactParams& p = normal_.params();
  const double omega0 = std::sqrt(normal_.omega0_sq_per_s2());
  nlohmann::json j;
  j["closed_form"] = "disk_on_line";
  j["description"] =
      "frictionless disk on a fixed line: uniform tangential acceleration g.t, constant spin, "
      "normal gap piecewise free flight / damped linear oscillator (Kelvin-Voigt, paper eq. 1) "
      "/ free flight while the clamped force is zero, until the gap returns to zero";
  j["law"] = "kelvin_voigt";
  j["stiffness_n_per_m"] = p.stiffness_n_per_m;
  j["damping_ns_per_m"] = p.damping_ns_per_m;
  j["mass_kg"] = p.mass_kg;
  j["radius_m"] = radius_m_;
  j["line_normal"] = {normal_dir_.x(), normal_dir_.y()};
  j["normal_gravity_mps2"] = p.normal_gravity_mps2;
  j["tangential_gravity_mps2"] = along_accel_mps2_;
  j["natural_frequency_radps"] = omega0;
  j["damping_ratio"] = normal_.sigma_per_s() / omega0;
  j["static_penetration_m"] = -normal_.equilibrium_gap_m();
  j["initial_gap_m"] = p.gap0_m;
  j["initial_gap_rounding_set_to_zero"] = gap_snapped_;
  j["event_location"] =
      "onset, offset and re-contact: quadratics solved without cancellation; the clamp "
      "(force back to 0): bisection to the last bit between consecutive stationary points "
      "of the closed-form force";
  j["episodes"] =
      "peak force and penetration at closed-form stationary points; impulse from the normal "
      "momentum balance m du' - m (g.n) dt; a contact begun at rest has restitution NaN";
  j["not_expressed"] = nlohmann::json::array();
  return j;
}

}  // namespace pb::internal
