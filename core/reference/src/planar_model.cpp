#include "planarbench/reference/planar_model.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <variant>

namespace pb {

namespace {
Eigen::Matrix2d rotation(double angle) { return Pose{Vec2::Zero(), angle}.rotation(); }
}  // namespace

PlanarModel::PlanarModel(const Case& c) : gravity_mps2_(c.gravity_mps2) {
  // joints per body
  std::vector<int> joint_of(c.bodies.size(), -1);
  for (std::size_t j = 0; j < c.joints.size(); ++j) {
    const int b = c.joints[j].body;
    if (b < 0 || b >= static_cast<int>(c.bodies.size())) {
      throw std::invalid_argument("joint '" + c.joints[j].name + "' names no body");
    }
    if (joint_of[static_cast<std::size_t>(b)] >= 0 && !c.bodies[static_cast<std::size_t>(b)].fixed) {
      throw std::invalid_argument("body '" + c.bodies[static_cast<std::size_t>(b)].name +
                                  "' has more than one revolute joint to ground");
    }
    joint_of[static_cast<std::size_t>(b)] = static_cast<int>(j);
  }

  std::vector<double> mass;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    ModelBody mb;
    mb.mass_kg = b.mass_kg;
    mb.initial = BodyState{b.position_m, b.angle_rad, b.velocity_mps, b.angular_velocity_radps};
    if (b.fixed) {
      mb.kind = Kind::fixed;
      mb.fixed_pose = Pose{b.position_m, b.angle_rad};
    } else if (std::holds_alternative<HalfPlane>(b.shape)) {
      throw std::invalid_argument("half-plane '" + b.name + "' must be fixed");
    } else if (joint_of[i] >= 0) {
      const RevoluteJoint& j = c.joints[static_cast<std::size_t>(joint_of[i])];
      mb.kind = Kind::pendulum;
      mb.anchor_world_m = j.anchor_world_m;
      mb.anchor_local_m = j.anchor_local_m;
      // pivot inertia, parallel-axis theorem
      const double pivot_inertia = b.inertia_kgm2 + b.mass_kg * j.anchor_local_m.squaredNorm();
      if (!(pivot_inertia > 0.0)) {
        throw std::invalid_argument("pendulum '" + b.name + "' has no inertia about its pivot");
      }
      mb.coord = n_;
      n_ += 1;
      mass.push_back(pivot_inertia);
    } else {
      if (!(b.mass_kg > 0.0) || !(b.inertia_kgm2 > 0.0)) {
        throw std::invalid_argument("free body '" + b.name + "' needs mass and inertia > 0");
      }
      mb.kind = Kind::free;
      mb.coord = n_;
      n_ += 3;
      mass.insert(mass.end(), {b.mass_kg, b.mass_kg, b.inertia_kgm2});
    }
    bodies_.push_back(mb);
  }
  mass_ = Eigen::Map<const Eigen::VectorXd>(mass.data(), static_cast<Eigen::Index>(mass.size()));
}

void PlanarModel::initial_state(Eigen::VectorXd& q, Eigen::VectorXd& u) const {
  q.setZero(n_);
  u.setZero(n_);
  for (const auto& b : bodies_) {
    if (b.kind == Kind::pendulum) {
      q[b.coord] = b.initial.angle_rad;
      u[b.coord] = b.initial.angular_velocity_radps;
    } else if (b.kind == Kind::free) {
      q.segment<2>(b.coord) = b.initial.position_m;
      q[b.coord + 2] = b.initial.angle_rad;
      u.segment<2>(b.coord) = b.initial.velocity_mps;
      u[b.coord + 2] = b.initial.angular_velocity_radps;
    }
  }
}

Pose PlanarModel::pose(int body, ConstVectorRef q) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  switch (b.kind) {
    case Kind::fixed: return b.fixed_pose;
    case Kind::pendulum: {
      const double th = q[b.coord];
      return Pose{b.anchor_world_m - rotation(th) * b.anchor_local_m, th};
    }
    case Kind::free: return Pose{q.segment<2>(b.coord), q[b.coord + 2]};
  }
  return b.fixed_pose;
}

BodyState PlanarModel::state(int body, ConstVectorRef q, ConstVectorRef u) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  const Pose p = pose(body, q);
  BodyState s;
  s.position_m = p.position_m;
  s.angle_rad = p.angle_rad;
  switch (b.kind) {
    case Kind::fixed: break;
    case Kind::pendulum:
      s.angular_velocity_radps = u[b.coord];
      s.velocity_mps = u[b.coord] * perp(p.position_m - b.anchor_world_m);
      break;
    case Kind::free:
      s.velocity_mps = u.segment<2>(b.coord);
      s.angular_velocity_radps = u[b.coord + 2];
      break;
  }
  return s;
}

Vec2 PlanarModel::point_velocity(int body, ConstVectorRef q, ConstVectorRef u,
                                 const Vec2& p_m) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  switch (b.kind) {
    case Kind::fixed: return Vec2::Zero();
    case Kind::pendulum: return u[b.coord] * perp(p_m - b.anchor_world_m);
    case Kind::free:
      return Vec2(u.segment<2>(b.coord)) + u[b.coord + 2] * perp(p_m - q.segment<2>(b.coord));
  }
  return Vec2::Zero();
}

Vec2 PlanarModel::point_centripetal_acceleration(int body, ConstVectorRef q, ConstVectorRef u,
                                                 const Vec2& p_m) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  switch (b.kind) {
    case Kind::fixed: return Vec2::Zero();
    case Kind::pendulum: return -u[b.coord] * u[b.coord] * (p_m - b.anchor_world_m);
    case Kind::free: {
      const double w = u[b.coord + 2];
      return -w * w * (p_m - Vec2(q.segment<2>(b.coord)));
    }
  }
  return Vec2::Zero();
}

void PlanarModel::gravity_forces(ConstVectorRef q, Eigen::VectorXd& gen_force) const {
  gen_force.setZero(n_);
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const ModelBody& b = bodies_[i];
    const Vec2 w = b.mass_kg * gravity_mps2_;  // N, weight
    if (b.kind == Kind::pendulum) {
      gen_force[b.coord] += cross2(pose(static_cast<int>(i), q).position_m - b.anchor_world_m, w);
    } else if (b.kind == Kind::free) {
      gen_force.segment<2>(b.coord) += w;
    }
  }
}

void PlanarModel::add_point_force(int body, ConstVectorRef q, const Vec2& p_m,
                                  const Vec2& f_n, Eigen::VectorXd& gen_force) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  // virtual work: Q = J^T f with J the Jacobian of the material point
  if (b.kind == Kind::pendulum) {
    gen_force[b.coord] += cross2(p_m - b.anchor_world_m, f_n);
  } else if (b.kind == Kind::free) {
    gen_force.segment<2>(b.coord) += f_n;
    gen_force[b.coord + 2] += cross2(p_m - q.segment<2>(b.coord), f_n);
  }
}

int PlanarModel::point_force_entries(int body, ConstVectorRef q, const Vec2& p_m, const Vec2& f_n,
                                     int index[3], double value[3]) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  if (b.kind == Kind::pendulum) {
    index[0] = b.coord;
    value[0] = cross2(p_m - b.anchor_world_m, f_n);
    return 1;
  }
  if (b.kind == Kind::free) {
    index[0] = b.coord;
    index[1] = b.coord + 1;
    index[2] = b.coord + 2;
    value[0] = f_n.x();
    value[1] = f_n.y();
    value[2] = cross2(p_m - q.segment<2>(b.coord), f_n);
    return 3;
  }
  return 0;
}

void PlanarModel::add_couple(int body, double torque_nm, Eigen::VectorXd& gen_force) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  if (b.kind == Kind::pendulum) gen_force[b.coord] += torque_nm;
  if (b.kind == Kind::free) gen_force[b.coord + 2] += torque_nm;
}

double PlanarModel::angular_velocity(int body, ConstVectorRef u) const {
  const ModelBody& b = bodies_[static_cast<std::size_t>(body)];
  if (b.kind == Kind::pendulum) return u[b.coord];
  if (b.kind == Kind::free) return u[b.coord + 2];
  return 0.0;
}

double PlanarModel::energy_j(ConstVectorRef q, ConstVectorRef u) const {
  // kinetic 1/2 u^T M u (M diagonal), potential -m g . c
  double e = 0.5 * (mass_.array() * u.array().square()).sum();
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].kind == Kind::fixed) continue;
    e -= bodies_[i].mass_kg * gravity_mps2_.dot(pose(static_cast<int>(i), q).position_m);
  }
  return e;
}

double PlanarModel::joint_violation_m(ConstVectorRef q) const {
  double worst = 0.0;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const ModelBody& b = bodies_[i];
    if (b.kind != Kind::pendulum) continue;
    // the anchor point of the body, reconstructed from its state
    const Pose p = pose(static_cast<int>(i), q);
    worst = std::max(worst, (p.to_world(b.anchor_local_m) - b.anchor_world_m).norm());
  }
  return worst;
}

}  // namespace pb
