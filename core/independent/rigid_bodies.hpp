// The equations of motion of the independent truth: planar rigid bodies,
// each free (x, y, theta and their rates) or pinned to the world by one
// revolute joint and then written in its angle alone (theta, theta_dot): the
// joint holds by construction, with no constraint force to stabilise.
//   free:    m x_ddot = m g + sum F,   I theta_ddot = sum (p - x) x F
//   pinned:  (I + m |r|^2) theta_ddot = (x - A) x m g + sum (p - A) x F,
//            x = A - R(theta) r (A the anchor, r the anchor in the body frame),
//            x_dot = theta_dot k x (x - A)
// (Euler's laws for a body on a fixed axis, e.g. Meriam & Kraige, Engineering
// Mechanics: Dynamics, §6/4). Forces F act at points p; fixed bodies never move.
// Written for the independent truth: no code shared with core/reference.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "pair_contact.hpp"
#include "planarbench/case.hpp"

namespace pb::independent {

using State = std::vector<double>;

// a force on a body at a world point
struct AppliedForce {
  int body = -1;
  Vec2 force_n = Vec2::Zero();  // N, world
  Vec2 point_m = Vec2::Zero();  // m, world
};

class RigidBodies {
 public:
  // "" when every joint pins one moving body to the world (one joint at most
  // per body) and every moving body has mass and inertia > 0; else why not
  [[nodiscard]] static std::string unsupported(const Case& c);

  // extra_states: entries appended to the state after the bodies' (the
  // integrator's impulses), starting at 0
  RigidBodies(const Case& c, std::size_t extra_states);

  [[nodiscard]] std::size_t state_size() const { return size_; }
  [[nodiscard]] std::size_t first_extra() const { return bodies_size_; }
  [[nodiscard]] State initial_state() const;
  // every body's pose and velocity (index = Case::bodies index)
  void motions(const State& x, std::vector<BodyMotion>& out) const;
  // the bodies' part of dx/dt under gravity and the given forces (the extra
  // entries are left to the caller)
  void derivative(const std::vector<BodyMotion>& m, const std::vector<AppliedForce>& forces,
                  State& dxdt) const;
  // kinetic energy plus the potential of gravity, J
  [[nodiscard]] double energy(const std::vector<BodyMotion>& m) const;

 private:
  enum class Kind { fixed, free, pinned };
  struct Slot {
    Kind kind = Kind::fixed;
    std::size_t at = 0;                 // first state index
    double mass_kg = 0.0;               // kg
    double inertia_kgm2 = 0.0;          // kg m^2 about the centre of mass
    Vec2 anchor_m = Vec2::Zero();       // m, world (pinned)
    Vec2 anchor_body_m = Vec2::Zero();  // m, body frame (pinned)
    BodyMotion start;                   // fixed bodies' pose, every body's start
  };
  std::vector<Slot> slots_;
  // scratch of derivative(): each body's resultant force and moment
  mutable std::vector<Vec2> force_;
  mutable std::vector<double> moment_;
  Vec2 gravity_mps2_ = Vec2::Zero();
  std::size_t bodies_size_ = 0;
  std::size_t size_ = 0;
};

}  // namespace pb::independent
