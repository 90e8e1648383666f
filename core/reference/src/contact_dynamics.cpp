#include "planarbench/reference/contact_dynamics.hpp"

#include <stdexcept>
#include <string>

#include "planarbench/reference/unclamped_force.hpp"

namespace pb {

ContactDynamics::ContactDynamics(const Case& c, GeometryMode mode, DetectionMode detection)
    : model_(c), pairs_(c.contacts) {
  const int nb = static_cast<int>(c.bodies.size());
  for (const auto& p : pairs_) {
    if (p.body_a < 0 || p.body_a >= nb || p.body_b < 0 || p.body_b >= nb || p.body_a == p.body_b) {
      throw std::invalid_argument("contact pair '" + p.name + "' needs two different bodies");
    }
    geometry_.push_back(std::make_unique<PairGeometry>(c.bodies[static_cast<std::size_t>(p.body_a)],
                                                       c.bodies[static_cast<std::size_t>(p.body_b)],
                                                       mode, detection));
  }
  modes_.assign(pairs_.size(), PairMode{});
  last_.assign(pairs_.size(), PairEvaluation{});
  q_.setZero(coordinates());
  u_.setZero(coordinates());
  gen_force_.setZero(coordinates());
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
  const ContactPair& p = pairs_[static_cast<std::size_t>(k)];
  PairEvaluation e;
  e.geometry = geometry_[static_cast<std::size_t>(k)]->evaluate(model_.pose(p.body_a, q_),
                                                                model_.pose(p.body_b, q_));
  const Vec2 va = model_.point_velocity(p.body_a, q_, u_, e.geometry.point_a_m);
  const Vec2 vb = model_.point_velocity(p.body_b, q_, u_, e.geometry.point_b_m);
  e.gap_rate_mps = e.geometry.normal.dot(vb - va);
  e.unclamped_force_n = unclamped_force_n(p.law, -e.geometry.gap_m, -e.gap_rate_mps,
                                          mode.approach_speed_mps);
  e.force_n = mode.phase == ContactPhase::pressing ? e.unclamped_force_n : 0.0;
  return e;
}

void ContactDynamics::derivative(const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
  const int n = coordinates();
  q_ = y.head(n);
  u_ = y.segment(n, n);
  model_.gravity_forces(q_, gen_force_);
  dy.resize(state_size());
  for (int k = 0; k < pair_count(); ++k) {
    const PairEvaluation e = evaluate(k, modes_[static_cast<std::size_t>(k)]);
    last_[static_cast<std::size_t>(k)] = e;
    dy[impulse_index(k)] = e.force_n;
    if (e.force_n == 0.0) continue;
    // F n on b at p_b, -F n on a at p_a
    const ContactPair& p = pairs_[static_cast<std::size_t>(k)];
    const Vec2 f = e.force_n * e.geometry.normal;
    model_.add_point_force(p.body_b, q_, e.geometry.point_b_m, f, gen_force_);
    model_.add_point_force(p.body_a, q_, e.geometry.point_a_m, -f, gen_force_);
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

}  // namespace pb
