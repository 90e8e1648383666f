// The effective mass of a set of contact points of one pair (SPEC §1, one
// force per pair): engines that make several contact points for one pair (a
// face on a face, a concave body pressed in at several places) must spread
// the pair's law over them so that a uniform penetration gives the law's
// force. For a single point this is the familiar m_eff = 1 / (J M^-1 J^T);
// for a set of points it is the mass a uniform normal acceleration of every
// point moves: with A = J M^-1 J^T (one row of J per point, its unit normal
// through the Jacobian of the two bodies at that point), the forces f = A^+ 1
// give every point the same unit normal acceleration, and their sum
//   m_set = 1^T A^+ 1
// is the force per unit acceleration (the pseudo-inverse because several
// points of one rigid face are dependent: four points, three planar degrees
// of freedom). A square of mass m landing flat on two corners: m_set = m
// (one corner alone: m / (1 + m r^2 / I)). Reference: the contact-space
// inverse inertia of constrained dynamics, e.g. Featherstone, Rigid Body
// Dynamics Algorithms (2008), §11.
#pragma once

#include <Eigen/Core>
#include <span>

#include "planarbench/case.hpp"

namespace pb {

// how a planar body responds to an impulse
struct PlanarInertia {
  bool fixed = false;              // does not move
  double mass_kg = 0.0;            // kg
  double inertia_kgm2 = 0.0;       // kg m^2 about the centre of mass
  Vec2 centre_m = Vec2::Zero();    // m, world, centre of mass now
  bool pinned = false;             // one revolute joint to ground
  Vec2 pivot_m = Vec2::Zero();     // m, world, the joint's anchor when pinned
};

// the most points a set may hold; deeper points are kept first by callers
inline constexpr int kMaxContactSetPoints = 32;

using ContactSetMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxContactSetPoints,
                  kMaxContactSetPoints>;

// A = J M^-1 J^T, 1/kg, of unit impulses along normals[i] (from body a to
// body b) at points[i] (world): per body, free: n_i.n_j / m + (r_i x n_i)
// (r_j x n_j) / I (r from the centre of mass); pinned at q: (r_i x n_i)
// (r_j x n_j) / (I + m |c - q|^2) with r from q; fixed: 0. At most
// kMaxContactSetPoints points.
[[nodiscard]] ContactSetMatrix contact_inverse_mass(const PlanarInertia& a, const PlanarInertia& b,
                                                    std::span<const Vec2> points_m,
                                                    std::span<const Vec2> normals);

// m = 1 / (J M^-1 J^T) of one point, kg; infinite when neither body can move
// along n there
[[nodiscard]] double point_effective_mass_kg(const PlanarInertia& a, const PlanarInertia& b,
                                             const Vec2& point_m, const Vec2& normal);

// How a pair's law is spread over a set of rows that each follow the same
// reference acceleration (MuJoCo's soft contacts: one solref for the pair):
// a spring k' per unit effective mass on every row gives the total force
// k' w^T r with w = A^+ 1 and r the rows' depths; scaling by
//   sigma = delta / delta_w,  delta_w = w^T r / m_set
// (delta the deepest row) makes it k delta, the law's force on the pair's
// penetration, for any depths; sigma = 1 for a uniform penetration and for
// a single point.
struct ContactSetScale {
  double mass_kg = 0.0;           // m_set = 1^T A^+ 1, kg
  double weighted_depth_m = 0.0;  // delta_w, m
  double scale = 1.0;             // sigma, -
};
// inverse_mass: A (n x n); depths_m: the n depths, > 0 pressing. With a
// degenerate set (m_set <= 0 or not finite, delta_w <= 0) the scale is 1.
[[nodiscard]] ContactSetScale contact_set_scale(const ContactSetMatrix& inverse_mass,
                                                std::span<const double> depths_m);

}  // namespace pb
