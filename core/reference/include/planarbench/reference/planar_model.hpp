// Planar rigid bodies with revolute joints to ground, in joint coordinates
// (paper §2, the equations of motion into which the contact forces enter as
// applied forces).
//
// Formulation. Every moving body is either free, coordinates (x, y, theta) of
// its centre of mass, or a pendulum: one revolute joint to ground, coordinate
// theta (its body angle) alone, the centre following as
//   c(theta) = anchor_world - R(theta) anchor_local.
// The joint is therefore satisfied by construction: no constraint equations,
// no drift, no stabilisation. joint_violation_m() still measures it from the
// reconstructed anchor, so that the claim is checked, not assumed.
// The generalised velocities are u = q_dot, and the mass matrix is constant
// and diagonal: diag(m, m, I) for a free body, the pivot inertia
// I + m |anchor_local|^2 (parallel-axis theorem) for a pendulum. With joints
// to ground only, bodies couple through contact forces alone, so M u_dot = Q
// is solved component-wise (Eigen vectors hold q, u and Q).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"
#include "planarbench/reference/contact_geometry.hpp"

namespace pb {

// a read-only view of q or u (a whole vector or a segment of the ODE state)
using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;

class PlanarModel {
 public:
  enum class Kind { fixed, pendulum, free };

  // throws std::invalid_argument for what it cannot model (a body with two
  // joints, a moving half-plane, a free body without mass or inertia)
  explicit PlanarModel(const Case& c);

  [[nodiscard]] int coordinates() const { return n_; }
  [[nodiscard]] int bodies() const { return static_cast<int>(bodies_.size()); }
  [[nodiscard]] Kind kind(int body) const { return bodies_[static_cast<std::size_t>(body)].kind; }

  // q and u at t = 0 from the case (a pendulum keeps only its angular velocity)
  void initial_state(Eigen::VectorXd& q, Eigen::VectorXd& u) const;

  [[nodiscard]] Pose pose(int body, ConstVectorRef q) const;
  [[nodiscard]] BodyState state(int body, ConstVectorRef q, ConstVectorRef u) const;
  // velocity of the body's material point now at world point p_m
  [[nodiscard]] Vec2 point_velocity(int body, ConstVectorRef q, ConstVectorRef u,
                                    const Vec2& p_m) const;

  // the part of that velocity's rate not linear in u_dot: -omega^2 r, r the
  // point's offset from the body's centre of rotation (centre of mass, or
  // pivot); the whole rate is this plus the rate of J u at u_dot
  [[nodiscard]] Vec2 point_centripetal_acceleration(int body, ConstVectorRef q, ConstVectorRef u,
                                                    const Vec2& p_m) const;

  // generalised forces of gravity (overwrites Q)
  void gravity_forces(ConstVectorRef q, Eigen::VectorXd& gen_force) const;
  // adds the generalised force of world force f_n applied at world point p_m
  void add_point_force(int body, ConstVectorRef q, const Vec2& p_m, const Vec2& f_n,
                       Eigen::VectorXd& gen_force) const;
  // the same as sparse entries: the coordinates it acts on (up to 3) and
  // their generalised forces; returns how many (0 for a fixed body)
  int point_force_entries(int body, ConstVectorRef q, const Vec2& p_m, const Vec2& f_n, int index[3],
                          double value[3]) const;
  // adds the generalised force of a couple of torque_nm (N m, counter-clockwise)
  void add_couple(int body, double torque_nm, Eigen::VectorXd& gen_force) const;
  // rad/s, counter-clockwise (0 for a fixed body)
  [[nodiscard]] double angular_velocity(int body, ConstVectorRef u) const;
  // the diagonal of the constant mass matrix (kg, kg m^2)
  [[nodiscard]] const Eigen::VectorXd& mass_diagonal() const { return mass_; }

  // kinetic + gravitational potential energy, J
  [[nodiscard]] double energy_j(ConstVectorRef q, ConstVectorRef u) const;
  // largest distance between a jointed body's anchor point and its world pivot, m
  [[nodiscard]] double joint_violation_m(ConstVectorRef q) const;

 private:
  struct ModelBody {
    Kind kind = Kind::fixed;
    int coord = -1;                       // first coordinate in q
    double mass_kg = 0.0;
    Vec2 anchor_world_m = Vec2::Zero();   // m (pendulum)
    Vec2 anchor_local_m = Vec2::Zero();   // m (pendulum)
    Pose fixed_pose;                      // fixed bodies
    BodyState initial;                    // t = 0
  };
  std::vector<ModelBody> bodies_;
  Vec2 gravity_mps2_ = Vec2::Zero();
  Eigen::VectorXd mass_;
  int n_ = 0;
};

}  // namespace pb
