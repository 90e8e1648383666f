#include "rigid_bodies.hpp"

#include <fmt/format.h>

#include <cmath>

#include "plane_rotation.hpp"

namespace pb::independent {

namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

std::string RigidBodies::unsupported(const Case& c) {
  std::vector<int> joints_of(c.bodies.size(), 0);
  for (const RevoluteJoint& j : c.joints) {
    if (j.body < 0 || static_cast<std::size_t>(j.body) >= c.bodies.size()) {
      return fmt::format("joint '{}' names a body that does not exist", j.name);
    }
    if (c.bodies[static_cast<std::size_t>(j.body)].fixed) {
      return fmt::format("joint '{}' pins a fixed body", j.name);
    }
    if (++joints_of[static_cast<std::size_t>(j.body)] > 1) {
      return fmt::format("body '{}' has more than one joint (one revolute joint to the world only)",
                         c.bodies[static_cast<std::size_t>(j.body)].name);
    }
  }
  for (const Body& b : c.bodies) {
    if (b.fixed) continue;
    if (!(b.mass_kg > 0.0) || !(b.inertia_kgm2 > 0.0)) {
      return fmt::format("body '{}' moves without a positive mass and inertia", b.name);
    }
  }
  return {};
}

RigidBodies::RigidBodies(const Case& c, std::size_t extra_states) : gravity_mps2_(c.gravity_mps2) {
  slots_.resize(c.bodies.size());
  std::size_t at = 0;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    Slot& s = slots_[i];
    s.mass_kg = b.mass_kg;
    s.inertia_kgm2 = b.inertia_kgm2;
    s.start.pose = {b.position_m, b.angle_rad};
    s.start.velocity_mps = b.velocity_mps;
    s.start.angular_velocity_radps = b.angular_velocity_radps;
    if (b.fixed) {
      s.kind = Kind::fixed;
      s.start.velocity_mps = Vec2::Zero();
      s.start.angular_velocity_radps = 0.0;
      continue;
    }
    s.kind = Kind::free;
    for (const RevoluteJoint& j : c.joints) {
      if (static_cast<std::size_t>(j.body) == i) {
        s.kind = Kind::pinned;
        s.anchor_m = j.anchor_world_m;
        s.anchor_body_m = j.anchor_local_m;
      }
    }
    s.at = at;
    at += s.kind == Kind::pinned ? 2 : 6;
  }
  bodies_size_ = at;
  size_ = at + extra_states;
}

State RigidBodies::initial_state() const {
  State x(size_, 0.0);
  for (const Slot& s : slots_) {
    if (s.kind == Kind::free) {
      x[s.at + 0] = s.start.pose.centre_m.x();
      x[s.at + 1] = s.start.pose.centre_m.y();
      x[s.at + 2] = s.start.pose.angle_rad;
      x[s.at + 3] = s.start.velocity_mps.x();
      x[s.at + 4] = s.start.velocity_mps.y();
      x[s.at + 5] = s.start.angular_velocity_radps;
    } else if (s.kind == Kind::pinned) {
      // the joint fixes the centre's velocity by the angular velocity
      x[s.at + 0] = s.start.pose.angle_rad;
      x[s.at + 1] = s.start.angular_velocity_radps;
    }
  }
  return x;
}

void RigidBodies::motions(const State& x, std::vector<BodyMotion>& out) const {
  out.resize(slots_.size());
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    const Slot& s = slots_[i];
    BodyMotion& m = out[i];
    switch (s.kind) {
      case Kind::fixed:
        m = s.start;
        break;
      case Kind::free:
        m.pose = {Vec2(x[s.at + 0], x[s.at + 1]), x[s.at + 2]};
        m.velocity_mps = Vec2(x[s.at + 3], x[s.at + 4]);
        m.angular_velocity_radps = x[s.at + 5];
        break;
      case Kind::pinned: {
        const double theta = x[s.at + 0];
        const double w = x[s.at + 1];
        const Vec2 arm = -rotate(theta, s.anchor_body_m);  // centre - anchor
        m.pose = {s.anchor_m + arm, theta};
        m.velocity_mps = w * Vec2(-arm.y(), arm.x());
        m.angular_velocity_radps = w;
        break;
      }
    }
  }
}

void RigidBodies::derivative(const std::vector<BodyMotion>& m,
                             const std::vector<AppliedForce>& forces, State& dxdt) const {
  // the resultant force and its moment about the centre, per body
  std::vector<Vec2>& force = force_;
  std::vector<double>& moment = moment_;
  force.assign(slots_.size(), Vec2::Zero());
  moment.assign(slots_.size(), 0.0);
  for (const AppliedForce& f : forces) {
    const auto i = static_cast<std::size_t>(f.body);
    force[i] += f.force_n;
    moment[i] += cross(f.point_m - m[i].pose.centre_m, f.force_n);
  }
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    const Slot& s = slots_[i];
    if (s.kind == Kind::free) {
      dxdt[s.at + 0] = m[i].velocity_mps.x();
      dxdt[s.at + 1] = m[i].velocity_mps.y();
      dxdt[s.at + 2] = m[i].angular_velocity_radps;
      dxdt[s.at + 3] = gravity_mps2_.x() + force[i].x() / s.mass_kg;
      dxdt[s.at + 4] = gravity_mps2_.y() + force[i].y() / s.mass_kg;
      dxdt[s.at + 5] = moment[i] / s.inertia_kgm2;
    } else if (s.kind == Kind::pinned) {
      const Vec2 arm = m[i].pose.centre_m - s.anchor_m;
      // moment about the anchor: gravity and the forces at the centre, plus
      // the forces' moment about the centre
      const double about_anchor = cross(arm, s.mass_kg * gravity_mps2_ + force[i]) + moment[i];
      const double inertia_anchor = s.inertia_kgm2 + s.mass_kg * s.anchor_body_m.squaredNorm();
      dxdt[s.at + 0] = m[i].angular_velocity_radps;
      dxdt[s.at + 1] = about_anchor / inertia_anchor;
    }
  }
}

double RigidBodies::energy(const std::vector<BodyMotion>& m) const {
  double e = 0.0;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    const Slot& s = slots_[i];
    if (s.kind == Kind::fixed) continue;
    const double w = m[i].angular_velocity_radps;
    e += 0.5 * s.mass_kg * m[i].velocity_mps.squaredNorm() + 0.5 * s.inertia_kgm2 * w * w -
         s.mass_kg * gravity_mps2_.dot(m[i].pose.centre_m);
  }
  return e;
}

}  // namespace pb::independent
