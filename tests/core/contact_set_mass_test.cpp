// Tests for core/src/contact_set_mass.cpp
//
// Effective masses worked out by hand for rigid-body configurations whose
// answer is known: a point on a free body (1/m + r^2/I), a face of a
// translating body (its mass), a pinned body (I_pivot / lever^2), two free
// bodies head on (the reduced mass).
#include "planarbench/contact_set_mass.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace pb {
namespace {

// sums and quotients of O(1) numbers, a few roundings: 1e-14 relative
constexpr double kRel = 1e-14;

const PlanarInertia kGround{true, 0.0, 0.0, Vec2::Zero(), false, Vec2::Zero()};

// the square of square_landing.toml: side 0.2 m, 1.5 kg, I = m s^2 / 6 = 0.01 kg m^2
PlanarInertia square_at(const Vec2& centre) {
  return PlanarInertia{false, 1.5, 0.01, centre, false, Vec2::Zero()};
}

TEST(ContactSetMass, OneCornerOfASquare) {
  // corner 0.1 m beside the centre along the face: 1/m_eff = 1/1.5 + 0.1^2 / 0.01
  const double m = point_effective_mass_kg(kGround, square_at(Vec2(0, 0.1)), Vec2(0.1, 0.0),
                                           Vec2(0, 1));
  EXPECT_NEAR(m, 1.0 / (1.0 / 1.5 + 1.0), kRel);  // 0.6 kg
}

TEST(ContactSetMass, AFaceMovesTheWholeMass) {
  // both bottom corners: a uniform push lifts the square without turning it
  const std::array<Vec2, 2> p = {Vec2(-0.1, 0.0), Vec2(0.1, 0.0)};
  const std::array<Vec2, 2> n = {Vec2(0, 1), Vec2(0, 1)};
  const ContactSetMatrix a = contact_inverse_mass(kGround, square_at(Vec2(0, 0.1)), p, n);
  const std::array<double, 2> uniform = {0.02, 0.02};
  const ContactSetScale s = contact_set_scale(a, uniform);
  EXPECT_NEAR(s.mass_kg, 1.5, 1.5 * kRel);
  EXPECT_NEAR(s.weighted_depth_m, 0.02, 0.02 * kRel);
  EXPECT_NEAR(s.scale, 1.0, kRel);
  // tilted: corners 0.03 and 0.01 deep; w = (0.75, 0.75) kg by symmetry, so
  // delta_w = 0.02 m and the deepest corner asks for 1.5 times the spring
  const std::array<double, 2> tilted = {0.03, 0.01};
  const ContactSetScale t = contact_set_scale(a, tilted);
  EXPECT_NEAR(t.weighted_depth_m, 0.02, 0.02 * kRel);
  EXPECT_NEAR(t.scale, 1.5, 1.5 * kRel);
}

TEST(ContactSetMass, DependentPointsOfTwoFeetStillGiveTheMass) {
  // an arch on both feet: four points on one line are dependent (rank 2), the
  // pseudo-inverse finds the uniform push all the same: m_set = m
  const PlanarInertia arch{false, 1.0, 0.0168, Vec2(0, 0.12), false, Vec2::Zero()};
  const std::array<Vec2, 4> p = {Vec2(-0.2, 0), Vec2(-0.12, 0), Vec2(0.12, 0), Vec2(0.2, 0)};
  const std::array<Vec2, 4> n = {Vec2(0, 1), Vec2(0, 1), Vec2(0, 1), Vec2(0, 1)};
  const ContactSetMatrix a = contact_inverse_mass(kGround, arch, p, n);
  const std::array<double, 4> uniform = {1e-3, 1e-3, 1e-3, 1e-3};
  // a rank-deficient solve: 1e-12 relative
  EXPECT_NEAR(contact_set_scale(a, uniform).mass_kg, 1.0, 1e-12);
  EXPECT_NEAR(contact_set_scale(a, uniform).scale, 1.0, 1e-12);
}

TEST(ContactSetMass, PinnedBodyTurnsAboutItsPivot) {
  // a disk (m 1 kg, I 0.005) on a 0.6 m rod from (0, 0), hanging straight
  // down, pushed horizontally at its centre: I_pivot = 0.005 + 0.36, lever 0.6
  const PlanarInertia bob{false, 1.0, 0.005, Vec2(0, -0.6), true, Vec2::Zero()};
  const double m = point_effective_mass_kg(kGround, bob, Vec2(0, -0.6), Vec2(1, 0));
  EXPECT_NEAR(m, 0.365 / 0.36, kRel);
  // pushed along the rod: the pivot takes it all, nothing moves
  EXPECT_EQ(point_effective_mass_kg(kGround, bob, Vec2(0, -0.6), Vec2(0, 1)),
            std::numeric_limits<double>::infinity());
}

TEST(ContactSetMass, TwoFreeBodiesHeadOnGiveTheReducedMass) {
  // through both centres: no lever, 1/m_eff = 1/m_a + 1/m_b
  const PlanarInertia a{false, 1.0, 0.02, Vec2(-0.2, 0), false, Vec2::Zero()};
  const PlanarInertia b{false, 2.0, 0.04, Vec2(0.2, 0), false, Vec2::Zero()};
  EXPECT_NEAR(point_effective_mass_kg(a, b, Vec2(0, 0), Vec2(1, 0)), 2.0 / 3.0, kRel);
}

TEST(ContactSetMass, RejectsMismatchedOrOversizedSets) {
  const std::array<Vec2, 2> p = {Vec2(0, 0), Vec2(1, 0)};
  const std::array<Vec2, 1> n = {Vec2(0, 1)};
  EXPECT_THROW((void)contact_inverse_mass(kGround, square_at(Vec2::Zero()), p, n),
               std::invalid_argument);
}

// (moved here from the Box2D adapter, whose effective mass this now is)
// A free body hit at its centre along any normal responds with its mass; hit
// off-centre, with 1/m + (r x n)^2 / I (Featherstone §11; the textbook
// collision of a free rigid body). A fixed body adds nothing.
TEST(ContactSetMass, EffectiveMassOfFreeBodies) {
  const PlanarInertia ground{true, 0.0, 0.0, Vec2::Zero(), false, Vec2::Zero()};
  const PlanarInertia disk{false, 2.0, 0.25, Vec2(1.0, 1.0), false, Vec2::Zero()};
  const Vec2 n(0.0, 1.0);
  EXPECT_DOUBLE_EQ(point_effective_mass_kg(ground, disk, Vec2(1.0, 0.5), n), 2.0);
  // off centre by 0.3 m across the normal: 1 / (1/2 + 0.09/0.25) = 1/0.86
  // 1e-15 kg: rounding of 0.3^2 / 0.25 and the reciprocals (size 1)
  EXPECT_NEAR(point_effective_mass_kg(ground, disk, Vec2(1.3, 0.5), n), 1.0 / 0.86, 1e-15);
  // two free bodies in series: 1 / (1/m1 + 1/m2)
  const PlanarInertia other{false, 3.0, 0.5, Vec2(1.0, 2.0), false, Vec2::Zero()};
  EXPECT_NEAR(point_effective_mass_kg(disk, other, Vec2(1.0, 1.5), n), 1.0 / (0.5 + 1.0 / 3.0), 1e-15);
}

// A body pinned at q turns about q only: an impulse along n at p meets the
// inertia about the pivot divided by the squared lever, (I + m d^2) / ((p - q) x n)^2.
// Dual pendulum at its first contact: both levers 0.7071 m, horizontal normal.
TEST(ContactSetMass, EffectiveMassOfPendulums) {
  const double a = 0.7071;
  const double b = 0.25;
  const PlanarInertia ellipse{false, 1.0, (a * a + b * b) / 4.0, Vec2(0.0, -a), true, Vec2::Zero()};
  const PlanarInertia disk{false, 1.0, 0.125, Vec2(0.75, -0.7071), true, Vec2(0.75, 0.0)};
  const Vec2 p(0.25, -0.7071);
  const Vec2 n(1.0, 0.0);
  const double inv_e = 0.7071 * 0.7071 / ((a * a + b * b) / 4.0 + a * a);
  const double inv_d = 0.7071 * 0.7071 / (0.125 + 0.7071 * 0.7071);
  // 1e-14 kg: the same sums evaluated in another order (a few eps of ~0.6)
  EXPECT_NEAR(point_effective_mass_kg(ellipse, disk, p, n), 1.0 / (inv_e + inv_d), 1e-14);
  // pushing along the rod (through the pivot) meets an infinite mass
  EXPECT_EQ(point_effective_mass_kg(kGround, disk, Vec2(0.75, -1.2071), Vec2(0.0, 1.0)),
            std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace pb
