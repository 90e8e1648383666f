#include "body_on_line.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <variant>

#include "normal_contact_episodes.hpp"
#include "planarbench/errors.hpp"

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

double static_level_m(const Case& c, int body, int line, int pair) {
  const ContactPair& p = c.contacts.at(static_cast<std::size_t>(pair));
  const auto* kv = std::get_if<KelvinVoigt>(&p.law);
  if (!p.has_friction() || kv == nullptr || !(kv->stiffness_n_per_m > 0.0)) return 0.0;
  const Body& d = c.bodies.at(static_cast<std::size_t>(body));
  const Vec2 n = line_normal(c.bodies.at(static_cast<std::size_t>(line)));
  return d.mass_kg * std::abs(c.gravity_mps2.dot(n)) / kv->stiffness_n_per_m;
}

std::optional<TranslatingSupport> translating_support(const Body& body, const Vec2& normal,
                                                      std::string* why, double level_m) {
  if (const auto* circle = std::get_if<Circle>(&body.shape)) {
    return TranslatingSupport{circle->radius_m, std::numeric_limits<double>::infinity(), 0};
  }
  const auto* polygon = std::get_if<Polygon>(&body.shape);
  auto refuse = [&](const std::string& text) -> std::optional<TranslatingSupport> {
    if (why) *why = text;
    return std::nullopt;
  };
  if (polygon == nullptr) {
    return refuse(fmt::format("the body '{}' is a {}: the closed form needs a circle or a polygon",
                              body.name, shape_type_name(body.shape)));
  }
  // each vertex's height above the centre along n, and its offset along the line
  const Vec2 tangent(normal.y(), -normal.x());
  const double c = std::cos(body.angle_rad);
  const double s = std::sin(body.angle_rad);
  double size = 0.0;  // m
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec2& v : polygon->points_m) {
    const Vec2 w(c * v.x() - s * v.y(), s * v.x() + c * v.y());
    lowest = std::min(lowest, w.dot(normal));
    size = std::max(size, w.norm());
  }
  // a face parallel to the line: its vertices' heights agree to the rounding
  // of a rotated coordinate (~1e-16 relative); 1e-12 of the body's size
  const double tol = 1e-12 * size;
  double offset_sum = 0.0;
  int face = 0;
  double next = std::numeric_limits<double>::infinity();
  double face_top = lowest;  // m, the highest of the face's vertices
  double face_min = std::numeric_limits<double>::infinity();
  double face_max = -face_min;  // m, the face's ends along the line
  for (const Vec2& v : polygon->points_m) {
    const Vec2 w(c * v.x() - s * v.y(), s * v.x() + c * v.y());
    const double h = w.dot(normal);
    if (h <= lowest + tol + level_m) {
      offset_sum += w.dot(tangent);
      ++face;
      face_top = std::max(face_top, h);
      face_min = std::min(face_min, w.dot(tangent));
      face_max = std::max(face_max, w.dot(tangent));
    } else {
      next = std::min(next, h);
    }
  }
  // equal depths put the law's force at the face's middle (SPEC §1): it must
  // lie on the normal through the centre of mass, or the body turns. A face
  // tilted within level_m by phi = (its ends' height difference) / (its
  // width) has its middle moved by the tilt alone, support x phi: allowed
  const double tilt = face > 1 ? (face_top - lowest) / (face_max - face_min) : 0.0;
  const double middle = offset_sum / face;
  if (std::abs(middle) > tol + std::abs(lowest) * tilt) {
    return refuse(fmt::format(
        "the polygon '{}' touches the line with {} lowest vertices whose middle lies {:.3g} m "
        "beside its centre of mass: the contact force would turn it (no closed form)",
        body.name, face, middle));
  }
  if (body.angular_velocity_radps != 0.0) {
    return refuse(fmt::format("the polygon '{}' spins ({} rad/s): its lowest point would move",
                              body.name, body.angular_velocity_radps));
  }
  return TranslatingSupport{-lowest, next - lowest, face, face_min, face_max};
}

std::string tipping_reason(const Case& c, const Body& body, const ContactPair& pair,
                           const Vec2& normal, const TranslatingSupport& s) {
  if (s.face_vertices < 2 || !pair.has_friction()) return "";
  // The closed form holds the block not to turn. A rigid block does not turn
  // while the contact's resultant acts inside its face: by the moments about
  // the centre of mass, the friction f a support_m below it moves the normal
  // force N to x = support_m f / N from the centre's foot, so the block holds
  // its face while x stays within the nearer end of the face. f / N is at
  // most tan(incline) = |g.t| / |g.n| for a block that starts at rest and
  // holds (mu >= tan), else mu (sliding; after it stops f <= mu N still).
  const Vec2 tangent(normal.y(), -normal.x());
  const double g_n = std::abs(c.gravity_mps2.dot(normal));
  const double g_t = std::abs(c.gravity_mps2.dot(tangent));
  const bool holds = body.velocity_mps.dot(tangent) == 0.0 && g_t <= pair.friction * g_n;
  const double ratio = holds && g_n > 0.0 ? g_t / g_n : pair.friction;
  const double arm = s.support_m * ratio;
  const double edge = std::min(s.face_max_m, -s.face_min_m);
  // the face's ends to the rounding of rotated coordinates (as its level)
  const double tol = 1e-12 * std::max(s.support_m, s.face_max_m - s.face_min_m);
  if (arm <= edge + tol) return "";
  return fmt::format(
      "the polygon '{}' would tip: with f/N up to {:.4g} ({}) at {:.4g} m below its centre of "
      "mass, the contact force acts {:.4g} m from the centre's foot, beyond its face's nearer end "
      "at {:.4g} m (the closed form holds a block that does not turn)",
      body.name, ratio, holds ? "tan of the incline: it holds" : "mu: it slides", s.support_m, arm,
      edge);
}

NormalContactParams BodyOnLine::normal_params(const Case& c, int body, int line, int pair,
                                              bool& snapped) {
  const Body& d = c.bodies.at(static_cast<std::size_t>(body));
  const Body& l = c.bodies.at(static_cast<std::size_t>(line));
  const auto& law = std::get<KelvinVoigt>(c.contacts.at(static_cast<std::size_t>(pair)).law);
  const Vec2 n = line_normal(l);
  const double radius =
      translating_support(d, n, nullptr, static_level_m(c, body, line, pair)).value().support_m;
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

BodyOnLine::BodyOnLine(const Case& c, int body, int line, int pair)
    : normal_(normal_params(c, body, line, pair, gap_snapped_)) {
  const Body& d = c.bodies.at(static_cast<std::size_t>(body));
  const Body& l = c.bodies.at(static_cast<std::size_t>(line));
  const ContactPair& cp = c.contacts.at(static_cast<std::size_t>(pair));
  body_ = body;
  pair_body_a_ = cp.body_a;
  pair_body_b_ = cp.body_b;
  body_is_a_ = cp.body_a == body;
  shape_ = shape_type_name(d.shape);
  support_ = translating_support(d, line_normal(l), nullptr, static_level_m(c, body, line, pair))
                 .value();
  line_origin_m_ = l.position_m;
  tangent_ = line_tangent(l);
  normal_dir_ = line_normal(l);
  along0_m_ = (d.position_m - l.position_m).dot(tangent_);
  along_rate0_mps_ = d.velocity_mps.dot(tangent_);
  along_accel_mps2_ = c.gravity_mps2.dot(tangent_);
  angle0_rad_ = d.angle_rad;
  spin_radps_ = d.angular_velocity_radps;
  if (cp.has_friction()) {
    TangentialParams tp;
    tp.mass_kg = d.mass_kg;
    tp.inertia_kgm2 = d.inertia_kgm2;
    tp.rotates = std::holds_alternative<Circle>(d.shape);
    tp.radius_m = tp.rotates ? support_.support_m : 0.0;
    tp.friction = cp.friction;
    tp.tangential_gravity_mps2 = along_accel_mps2_;
    tp.along0_m = along0_m_;
    tp.along_rate0_mps = along_rate0_mps_;
    tp.angle0_rad = angle0_rad_;
    tp.spin0_radps = spin_radps_;
    tangential_ = std::make_unique<TangentialMotion>(tp, normal_);
  }
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

void BodyOnLine::extend_to(double t_s) {
  normal_.extend_to(t_s);
  if (tangential_) tangential_->extend_to(t_s);
  if (!std::isfinite(support_.clearance_m)) return;
  // a polygon: no other vertex level may reach the line
  const auto& phases = normal_.phases();
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (phases[i].kind == NormalPhaseKind::separated || phases[i].start_s > t_s) continue;
    const double end = std::min(phases[i].end_s, t_s);
    const double deepest = normal_.max_penetration_m(i, phases[i].start_s, end);
    if (deepest >= support_.clearance_m) {
      throw EngineError(fmt::format(
          "analytic: the polygon presses {:.4g} m into the line at t <= {:.6g} s, deeper than "
          "the {:.4g} m to its next vertex level: the translating closed form no longer holds",
          deepest, end, support_.clearance_m));
    }
  }
}

void BodyOnLine::body_states(double t_s, std::vector<BodyState>& out) const {
  out = initial_;
  const NormalState ns = normal_.state_at(t_s);
  BodyState& s = out[static_cast<std::size_t>(body_)];
  if (tangential_) {
    const TangentialState ts = tangential_->state_at(t_s);
    s.position_m =
        line_origin_m_ + ts.along_m * tangent_ + (ns.gap_m + support_.support_m) * normal_dir_;
    s.velocity_mps = ts.along_rate_mps * tangent_ + ns.gap_rate_mps * normal_dir_;
    s.angle_rad = ts.angle_rad;
    s.angular_velocity_radps = ts.spin_radps;
    return;
  }
  // uniform acceleration along the line, constant spin
  const double along = along0_m_ + t_s * (along_rate0_mps_ + 0.5 * along_accel_mps2_ * t_s);
  const double along_rate = along_rate0_mps_ + along_accel_mps2_ * t_s;
  s.position_m = line_origin_m_ + along * tangent_ + (ns.gap_m + support_.support_m) * normal_dir_;
  s.velocity_mps = along_rate * tangent_ + ns.gap_rate_mps * normal_dir_;
  s.angle_rad = angle0_rad_ + spin_radps_ * t_s;
  s.angular_velocity_radps = spin_radps_;
}

void BodyOnLine::contacts(double t_s, std::vector<ContactSample>& out) const {
  out.clear();
  const NormalState ns = normal_.state_at(t_s);
  if (!(ns.gap_m < 0.0)) return;
  const double along = tangential_ ? tangential_->state_at(t_s).along_m
                                   : along0_m_ + t_s * (along_rate0_mps_ + 0.5 * along_accel_mps2_ * t_s);
  const Vec2 centre = line_origin_m_ + along * tangent_ + (ns.gap_m + support_.support_m) * normal_dir_;
  ContactSample cs;
  cs.body_a = pair_body_a_;
  cs.body_b = pair_body_b_;
  cs.force_n = ns.force_n;
  cs.penetration_m = -ns.gap_m;
  cs.normal = body_is_a_ ? Vec2(-normal_dir_) : normal_dir_;
  // midpoint of the body's deepest point (a face's middle), centre - R n
  // (R the support distance), and its projection onto the line, centre - (R + u) n
  cs.point_m = centre - (support_.support_m + 0.5 * ns.gap_m) * normal_dir_;
  out.push_back(cs);
}

std::vector<ContactEpisode> BodyOnLine::episodes(double now_s) const {
  std::vector<ContactEpisode> eps = normal_contact_episodes(normal_, now_s);
  for (auto& e : eps) {
    e.body_a = pair_body_a_;
    e.body_b = pair_body_b_;
  }
  return eps;
}

long BodyOnLine::phases_begun(double t_s) const {
  return static_cast<long>(normal_.phase_index_at(t_s)) + 1 +
         (tangential_ ? tangential_->phases_begun(t_s) : 0);
}

nlohmann::json BodyOnLine::mapping() const {
  const NormalContactParams& p = normal_.params();
  const double omega0 = std::sqrt(normal_.omega0_sq_per_s2());
  nlohmann::json j;
  j["closed_form"] = "body_on_line";
  j["description"] =
      "frictionless body on a fixed line, the normal force through its centre of mass: uniform "
      "tangential acceleration g.t, constant spin (a polygon: none), normal gap piecewise free "
      "flight / damped linear oscillator (Kelvin-Voigt, paper eq. 1) / free flight while the "
      "clamped force is zero, until the gap returns to zero";
  j["shape"] = shape_;
  j["support_m"] = support_.support_m;
  if (std::isfinite(support_.clearance_m)) {
    j["face_vertices"] = support_.face_vertices;
    j["clearance_m"] = support_.clearance_m;
    j["holds_while"] =
        "no other vertex level reaches the line: the penetration stays below clearance_m "
        "(checked over the run)";
  }
  j["law"] = "kelvin_voigt";
  j["stiffness_n_per_m"] = p.stiffness_n_per_m;
  j["damping_ns_per_m"] = p.damping_ns_per_m;
  j["mass_kg"] = p.mass_kg;
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
  if (tangential_) {
    j["description"] =
        "body on a fixed line with Coulomb friction (SPEC §7), the normal force through its "
        "centre of mass: normal gap piecewise free flight / damped linear oscillator "
        "(Kelvin-Voigt, paper eq. 1) / free flight while the clamped force is zero; along the "
        "line and in rotation the stick / slip motion of `friction` under that normal force";
    j["friction"] = tangential_->mapping();
    if (std::isfinite(support_.clearance_m)) {
      j["not_expressed"].push_back(
          "the block is held not to turn: the moment of the friction force about its centre "
          "(the force acts support_m below it), which tilts a compliant block slightly, is left "
          "out");
    }
  }
  return j;
}

}  // namespace pb::internal
