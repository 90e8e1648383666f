#include "planarbench/reference/contact_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <variant>

#include <fmt/format.h>
#include <string>

#include "planarbench/convex_pieces.hpp"
#include "planarbench/ellipse_distance.hpp"
#include "planarbench/reference/unclamped_force.hpp"
#include "planarbench/contact_pairs.hpp"

namespace pb {

namespace {

// m, the distance from a shape's origin to its farthest material point
double reach_m(const Shape& shape) {
  if (const auto* c = std::get_if<Circle>(&shape)) return c->radius_m;
  if (const auto* e = std::get_if<Ellipse>(&shape)) return std::max(e->semi_axis_a_m, e->semi_axis_b_m);
  if (const auto* p = std::get_if<Polygon>(&shape)) {
    double r = 0.0;
    for (const Vec2& v : p->points_m) r = std::max(r, v.norm());
    return r;
  }
  return std::numeric_limits<double>::infinity();  // a half-plane
}

// m, how deep body-frame point p lies inside the shape: > 0 inside, <= 0 not
double depth_inside(const Shape& shape, const Vec2& p) {
  if (const auto* c = std::get_if<Circle>(&shape)) return c->radius_m - p.norm();
  if (const auto* e = std::get_if<Ellipse>(&shape)) {
    return -closest_point_on_ellipse(e->semi_axis_a_m, e->semi_axis_b_m, p).signed_distance_m;
  }
  if (std::holds_alternative<HalfPlane>(shape)) return -p.y();
  // a simple polygon: inside by the even-odd crossing rule, the depth is the
  // distance to the nearest edge
  const auto& v = std::get<Polygon>(shape).points_m;
  bool inside = false;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const Vec2& a = v[j];
    const Vec2& b = v[i];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      inside = !inside;
    }
    const Vec2 ab = b - a;
    const double s = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    nearest = std::min(nearest, (a + s * ab - p).norm());
  }
  return inside ? nearest : -nearest;
}

// a pair whose friction can hold a face: friction with a polygon on either
// side. Its geometry gives the face's spread and, on a half-plane, takes the
// line of action from the polygon's own points (pair_geometry.hpp); its damping
// has the face's couple. A curved body's inside points span a short arc (the
// ellipse of the measured impacts: ~2 mm, a couple of ~1e-3 of its rotation's
// rate over a contact), so its pairs keep the convex closed form's speed.
bool friction_on_a_face(const ContactPair& p, const std::vector<Body>& bodies) {
  if (!p.has_friction()) return false;
  for (const int i : {p.body_a, p.body_b}) {
    if (std::holds_alternative<Polygon>(bodies[static_cast<std::size_t>(i)].shape)) return true;
  }
  return false;
}

}  // namespace

ContactDynamics::ContactDynamics(const Case& c, GeometryMode mode, DetectionMode detection)
    : model_(c),
      pairs_(c),
      declared_(static_cast<int>(c.contacts.size())),
      near_(c, model_),
      detection_(detection),
      mode_(mode),
      has_friction_(case_has_friction(c)),
      stick_(model_.coordinates(), static_cast<int>(c.contacts.size())) {
  bodies_ = c.bodies;
  for (const Body& b : bodies_) {
    reach_m_.push_back(reach_m(b.shape));
    convex_.push_back(!std::holds_alternative<HalfPlane>(b.shape) &&
                      (!std::holds_alternative<Polygon>(b.shape) ||
                       is_convex_ccw(std::get<Polygon>(b.shape).points_m)));
  }
  add_pair_state();
  for (int k = 0; k < declared_; ++k) active_.push_back(k);
  q_.setZero(coordinates());
  u_.setZero(coordinates());
  gen_force_.setZero(coordinates());
  u_dot_.setZero(coordinates());
  stick_rows_.reserve(pairs_.all().size());
  stick_pairs_.reserve(pairs_.all().size());
  stick_force_n_.reserve(pairs_.all().size());
}

void ContactDynamics::add_pair_state() {
  const int nb = static_cast<int>(bodies_.size());
  for (auto k = static_cast<int>(geometry_.size()); k < pair_count(); ++k) {
    const ContactPair& p = pairs_[k];
    if (p.body_a < 0 || p.body_a >= nb || p.body_b < 0 || p.body_b >= nb || p.body_a == p.body_b) {
      throw std::invalid_argument("contact pair '" + p.name + "' needs two different bodies");
    }
    face_.push_back(friction_on_a_face(p, bodies_));
    geometry_.push_back(std::make_unique<PairGeometry>(bodies_[static_cast<std::size_t>(p.body_a)],
                                                       bodies_[static_cast<std::size_t>(p.body_b)],
                                                       mode_, detection_, face_.back()));
    modes_.emplace_back();
    last_.emplace_back();
  }
}

bool ContactDynamics::update_near(const Eigen::VectorXd& y) {
  if (near_.empty()) return false;
  if (!near_.update(y.head(coordinates()), pairs_, near_scratch_)) return false;
  add_pair_state();
  // every declared pair, the near group pairs, and any group pair still in
  // contact (none, by the margins: kept so that no phase is left behind)
  std::vector<int> next;
  next.reserve(static_cast<std::size_t>(declared_) + near_scratch_.size());
  for (int k = 0; k < declared_; ++k) next.push_back(k);
  std::size_t n = 0;
  for (const int k : active_) {
    if (k < declared_ || modes_[static_cast<std::size_t>(k)].phase == ContactPhase::apart) continue;
    while (n < near_scratch_.size() && near_scratch_[n] < k) next.push_back(near_scratch_[n++]);
    if (n < near_scratch_.size() && near_scratch_[n] == k) ++n;
    next.push_back(k);
  }
  while (n < near_scratch_.size()) next.push_back(near_scratch_[n++]);
  const bool changed = next != active_;
  active_ = std::move(next);
  return changed;
}

double ContactDynamics::near_excursion(const Eigen::VectorXd& y) const {
  return near_.empty() ? 0.0 : near_.excursion(y.head(coordinates()));
}

void ContactDynamics::initial_state(Eigen::VectorXd& y) const {
  const int n = coordinates();
  Eigen::VectorXd q, u;
  model_.initial_state(q, u);
  y.setZero(state_size());
  y.head(n) = q;
  y.segment(n, n) = u;
}

PairEvaluation ContactDynamics::evaluate(int k, const PairMode& mode) {
  const ContactPair& p = pairs_[k];
  PairEvaluation e;
  e.geometry = geometry_[static_cast<std::size_t>(k)]->evaluate(model_.pose(p.body_a, q_),
                                                                model_.pose(p.body_b, q_));
  const Vec2 va = model_.point_velocity(p.body_a, q_, u_, e.geometry.point_a_m);
  const Vec2 vb = model_.point_velocity(p.body_b, q_, u_, e.geometry.point_b_m);
  e.gap_rate_mps = e.geometry.normal.dot(vb - va);
  e.unclamped_force_n = unclamped_force_n(p.law, -e.geometry.gap_m, -e.gap_rate_mps,
                                          mode.approach_speed_mps);
  e.force_n = mode.phase == ContactPhase::pressing ? e.unclamped_force_n : 0.0;
  if (p.has_friction()) {
    e.tangent = Vec2(e.geometry.normal.y(), -e.geometry.normal.x());
    e.slip_rate_mps = e.tangent.dot(vb - va);
  }
  return e;
}

void ContactDynamics::add_damping_couple(int k, const PairEvaluation& e) {
  // the law's damping spread over a face's points by depth: besides the force
  // at their centroid, the couple -B spread (omega_b - omega_a) of the rates
  // that a rotation about the centroid gives the points (coulomb_friction.hpp)
  if (!(e.geometry.spread_m2 > 0.0)) return;
  const ContactPair& p = pairs_[k];
  const double b = law_damping_ns_per_m(p.law, -e.geometry.gap_m,
                                        modes_[static_cast<std::size_t>(k)].approach_speed_mps);
  const double omega = model_.angular_velocity(p.body_b, u_) - model_.angular_velocity(p.body_a, u_);
  const double torque = -b * e.geometry.spread_m2 * omega;  // N m, on b
  model_.add_couple(p.body_b, torque, gen_force_);
  model_.add_couple(p.body_a, -torque, gen_force_);
}

void ContactDynamics::add_friction() {
  // slip: -mu F s, on b at p_b along t and the opposite on a at p_a
  stick_rows_.clear();
  stick_pairs_.clear();
  for (const int k : active_) {
    const auto ku = static_cast<std::size_t>(k);
    const ContactPair& p = pairs_[k];
    PairEvaluation& e = last_[ku];
    e.friction_n = 0.0;
    const PairMode& m = modes_[ku];
    if (!p.has_friction() || m.phase != ContactPhase::pressing) continue;
    if (m.slip == SlipPhase::stick) {
      stick_pairs_.push_back(k);
      stick_rows_.push_back(StickRow{p.body_a, p.body_b, e.geometry.point_a_m,
                                     e.geometry.point_b_m, e.tangent, e.slip_rate_mps});
      continue;
    }
    e.friction_n = -p.friction * e.force_n * m.slip_sign;
    const Vec2 f = e.friction_n * e.tangent;
    model_.add_point_force(p.body_b, q_, e.geometry.point_b_m, f, gen_force_);
    model_.add_point_force(p.body_a, q_, e.geometry.point_a_m, -f, gen_force_);
  }
  if (stick_rows_.empty()) return;
  // stick: the forces that hold the sticking pairs, given everything else
  u_dot_ = gen_force_.cwiseQuotient(model_.mass_diagonal());
  if (has_groups()) {
    sparse_stick_.solve(model_, q_, u_, u_dot_, stick_rows_, stick_force_n_);
  } else {
    stick_.solve(model_, q_, u_, u_dot_, stick_rows_, stick_force_n_);
  }
  for (std::size_t j = 0; j < stick_rows_.size(); ++j) {
    const StickRow& r = stick_rows_[j];
    last_[static_cast<std::size_t>(stick_pairs_[j])].friction_n = stick_force_n_[j];
    const Vec2 f = stick_force_n_[j] * r.tangent;
    model_.add_point_force(r.body_b, q_, r.point_b_m, f, gen_force_);
    model_.add_point_force(r.body_a, q_, r.point_a_m, -f, gen_force_);
  }
}

void ContactDynamics::choose_slip_phase(int k, const Eigen::VectorXd& y) {
  const auto ku = static_cast<std::size_t>(k);
  PairMode& m = modes_[ku];
  m.slip = SlipPhase::stick;
  Eigen::VectorXd f(state_size());  // at events only, not per step
  derivative(y, f);
  const PairEvaluation& e = last_[ku];
  const double mu_f = pairs_[k].friction * e.force_n;
  if (std::abs(e.slip_rate_mps) <= kStickSpeed_mps && std::abs(e.friction_n) <= mu_f) return;
  // slip: along the tangential speed, or, from rest, the way the load drives
  // it (against the force that would have held it)
  m.slip = SlipPhase::slip;
  if (std::abs(e.slip_rate_mps) > kStickSpeed_mps) {
    m.slip_sign = e.slip_rate_mps > 0.0 ? 1.0 : -1.0;
  } else {
    m.slip_sign = e.friction_n > 0.0 ? -1.0 : 1.0;
  }
  derivative(y, f);
}

void ContactDynamics::derivative(const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
  const int n = coordinates();
  q_ = y.head(n);
  u_ = y.segment(n, n);
  model_.gravity_forces(q_, gen_force_);
  dy.resize(state_size());
  // the slots of the group pairs not evaluated stay constant
  if (has_groups()) dy.tail(state_size() - 2 * n - slots() * declared_).setZero();
  for (const int k : active_) {
    const PairEvaluation e = evaluate(k, modes_[static_cast<std::size_t>(k)]);
    last_[static_cast<std::size_t>(k)] = e;
    dy[impulse_index(k)] = e.force_n;
    if (e.force_n == 0.0) continue;
    // F n on b at p_b, -F n on a at p_a
    const ContactPair& p = pairs_[k];
    const Vec2 f = e.force_n * e.geometry.normal;
    model_.add_point_force(p.body_b, q_, e.geometry.point_b_m, f, gen_force_);
    model_.add_point_force(p.body_a, q_, e.geometry.point_a_m, -f, gen_force_);
    if (face_[static_cast<std::size_t>(k)]) add_damping_couple(k, e);
  }
  if (has_friction_) {
    add_friction();
    for (const int k : active_) {
      const PairEvaluation& e = last_[static_cast<std::size_t>(k)];
      dy[tangential_impulse_index(k)] = e.friction_n;
      dy[dissipation_index(k)] = -e.friction_n * e.slip_rate_mps;
    }
  }
  dy.head(n) = u_;
  dy.segment(n, n) = gen_force_.cwiseQuotient(model_.mass_diagonal());
  ++evaluations_;
}

PairEvaluation ContactDynamics::evaluate_pair(int k, const Eigen::VectorXd& y, const PairMode& mode) {
  const int n = coordinates();
  q_ = y.head(n);
  u_ = y.segment(n, n);
  return evaluate(k, mode);
}

void ContactDynamics::evaluate_with_friction(const Eigen::VectorXd& y,
                                             const std::vector<PairMode>& modes,
                                             std::vector<PairEvaluation>& out) {
  // copies into vectors that keep their capacity: no allocation after the first output
  kept_modes_ = modes_;
  const long evaluations = evaluations_;
  modes_ = modes;
  derivative(y, output_dy_);
  out = last_;
  modes_ = kept_modes_;
  evaluations_ = evaluations;
}

BodyState ContactDynamics::body_state(int body, const Eigen::VectorXd& y) const {
  const int n = coordinates();
  return model_.state(body, y.head(n), y.segment(n, n));
}

double ContactDynamics::energy_j(const Eigen::VectorXd& y) const {
  const int n = coordinates();
  return model_.energy_j(y.head(n), y.segment(n, n));
}

double ContactDynamics::joint_violation_m(const Eigen::VectorXd& y) const {
  return model_.joint_violation_m(y.head(coordinates()));
}

std::string ContactDynamics::beyond_geometry(const Eigen::VectorXd& y) const {
  const auto q = y.head(coordinates());
  for (const int k : active_) {
    const ContactPair& p = pairs_[k];
    for (const auto& [self, other] : {std::pair{p.body_a, p.body_b}, std::pair{p.body_b, p.body_a}}) {
      const auto si = static_cast<std::size_t>(self);
      const auto oi = static_cast<std::size_t>(other);
      if (bodies_[si].fixed || !convex_[si]) continue;
      const Pose ps = model_.pose(self, q);
      const Pose po = model_.pose(other, q);
      const Vec2 d = ps.position_m - po.position_m;
      if (d.norm() >= reach_m_[oi]) continue;  // cannot be inside: no shape test
      const Vec2 local = po.rotation().transpose() * d;
      const double depth = depth_inside(bodies_[oi].shape, local);
      if (depth <= 0.0) continue;
      const auto* plane = std::get_if<HalfPlane>(&bodies_[oi].shape);
      if (plane != nullptr && mode_ == GeometryMode::outline &&
          std::abs(local.x()) > 0.5 * plane->extent_m) {
        return fmt::format(
            "body '{}' went past the end of the {:.6g} m segment of outline points that "
            "represents half-plane '{}' (contact '{}'; raise its extent): its centre of mass is "
            "{:.6g} m along the surface from the segment's middle and {:.6g} m below it",
            bodies_[si].name, plane->extent_m, bodies_[oi].name, p.name, std::abs(local.x()),
            depth);
      }
      {
        return fmt::format(
            "penetration beyond what the geometry represents: the centre of mass of body '{}' "
            "is {:.6g} m inside body '{}' (contact '{}'); the contact law does not hold that "
            "deep and the outlines no longer cross where the bodies overlap",
            bodies_[si].name, depth, bodies_[oi].name, p.name);
      }
    }
  }
  return {};
}

}  // namespace pb
