// Tests for adapters/ode/ode_friction.cpp
#include "ode_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ode_library.hpp"
#include "ode_pair_contact.hpp"
#include "ode_test_cases.hpp"

namespace pb::internal::ode {
namespace {

// friction mu: a coefficient (Approx1), one friction row along the in-plane
// tangent (FDir1, and Mu2 with mu2 = 0), the soft normal bits kept
TEST(OdeFriction, CoulombCoefficientWithOneInPlaneRow) {
  dContact c{};
  c.surface.mode = dContactSoftERP | dContactSoftCFM;
  const double s = std::sqrt(0.5);
  c.geom.normal[0] = s;
  c.geom.normal[1] = s;
  add_coulomb_friction(c, 0.4);
  EXPECT_EQ(c.surface.mode & (dContactSoftERP | dContactSoftCFM), dContactSoftERP | dContactSoftCFM);
  EXPECT_EQ(c.surface.mode & dContactApprox1, dContactApprox1);
  EXPECT_NE(c.surface.mode & dContactFDir1, 0);
  EXPECT_NE(c.surface.mode & dContactMu2, 0);
  EXPECT_EQ(c.surface.mu, 0.4);
  EXPECT_EQ(c.surface.mu2, 0.0);
  // unit, in the plane, perpendicular to the normal (copies and a sign: exact)
  EXPECT_EQ(c.fdir1[0], -s);
  EXPECT_EQ(c.fdir1[1], s);
  EXPECT_EQ(c.fdir1[2], 0.0);
}

TEST(OdeFriction, ZeroLeavesTheContactFrictionless) {
  dContact c{};
  c.surface.mode = dContactSoftERP | dContactSoftCFM;
  add_coulomb_friction(c, 0.0);
  EXPECT_EQ(c.surface.mode, dContactSoftERP | dContactSoftCFM);
  EXPECT_EQ(c.surface.mu, 0.0);
}

// a square prism on the ground: dCollide reports each bottom vertex on both
// faces (z = +-w), 4 contacts; the pair keeps one per in-plane point, 2, with
// friction (their friction rows would be the same row twice) and without (a
// vertex two convex pieces share would otherwise count twice in the law's
// spread: ode_pair_contact.cpp)
TEST(OdeFriction, PrismContactsAtOneInPlanePointAreMerged) {
  ensure_ode_ready_in_this_thread();
  for (const double mu : {0.0, 0.5}) {
    Case c;
    Body square;
    square.name = "square";
    square.shape = Polygon{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
    square.mass_kg = 1.0;
    square.inertia_kgm2 = 1.0 / 150.0;
    square.position_m = Vec2(0.0, 0.099);  // 1 mm into the ground
    c.bodies = {ode_test::ground_body(), square};
    c.contacts = {ode_test::pair(0, 1, KelvinVoigt{1e4, 10.0, 0.0})};
    c.contacts[0].friction = mu;
    OdeWorld world(c);
    PairCollider collider(c, world);
    StepContacts out;
    collider.collide(out);
    ASSERT_EQ(out.pairs.size(), 1u);
    EXPECT_EQ(out.pairs[0].contacts_reported, 4);
    EXPECT_EQ(out.pairs[0].count, 2) << "mu = " << mu;
  }
}

// ODE's non-fatal messages are counted, not printed
TEST(OdeFriction, MessagesAreCountedNotPrinted) {
  ensure_ode_ready_in_this_thread();
  const long before = ode_messages_on_this_thread().count;
  dMessage(7, "a test message %d", 42);
  EXPECT_EQ(ode_messages_on_this_thread().count, before + 1);
  EXPECT_EQ(ode_messages_on_this_thread().last, "ODE message 7: a test message 42");
}

}  // namespace
}  // namespace pb::internal::ode
