// Tests for core/analytic/closed_form_match.cpp
#include "closed_form_match.hpp"

#include <gtest/gtest.h>

#include "test_cases.hpp"

namespace pb::internal {
namespace {

// the reason mentions `what`
::testing::AssertionResult mentions(const std::string& reason, const std::string& what) {
  if (reason.find(what) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << reason << "' does not mention '" << what << "'";
}

TEST(ClosedFormMatch, CanonicalCases) {
  const ClosedFormMatch fb = match_closed_form(testing::falling_ball());
  EXPECT_EQ(fb.kind, ClosedFormKind::body_on_line);
  EXPECT_EQ(fb.disk, 1);
  EXPECT_EQ(fb.line, 0);
  EXPECT_EQ(fb.pair, 0);
  EXPECT_TRUE(fb.reason.empty());
  EXPECT_EQ(match_closed_form(testing::sliding()).kind, ClosedFormKind::body_on_line);
  EXPECT_EQ(match_closed_form(testing::dual_pendulum()).kind,
            ClosedFormKind::pendulums_until_contact);
}

// Each reason names what stands in the way.
TEST(ClosedFormMatch, ReasonsForNone) {
  auto reason = [](const Case& c) {
    const ClosedFormMatch m = match_closed_form(c);
    EXPECT_EQ(m.kind, ClosedFormKind::none);
    return m.reason;
  };
  Case c = testing::falling_ball();
  c.truth = TruthKind::none;
  EXPECT_TRUE(mentions(reason(c), "truth = none"));

  c = testing::falling_ball();
  c.contacts[0].law = KelvinVoigt{1e4, 10.0, 0.1};  // the paper's "Depth 0.1 m"
  EXPECT_TRUE(mentions(reason(c), "damping ramp"));

  c = testing::falling_ball();
  c.contacts[0].law = LankaraniNikravesh{1e9, 1.5, 0.7, std::nullopt, {}};
  EXPECT_TRUE(mentions(reason(c), "lankarani_nikravesh"));

  c = testing::falling_ball();
  Body second = c.bodies[1];
  second.name = "second";
  second.position_m = Vec2(5.0, 5.0);
  c.bodies.push_back(second);
  EXPECT_TRUE(mentions(reason(c), "the two disks only"));  // 3 bodies: not the head-on form

  c = testing::falling_ball();
  c.bodies[1].shape = Polygon{{Vec2(-0.5, -0.5), Vec2(0.5, -0.5), Vec2(0.0, 0.5)}};
  // on the 30 deg incline a corner lands first, beside the centre of mass
  EXPECT_TRUE(mentions(reason(c), "would turn it"));

  c = testing::falling_ball();
  c.bodies[1].shape = Ellipse{0.5, 0.3};
  EXPECT_TRUE(mentions(reason(c), "needs a circle or a polygon"));

  c = testing::falling_ball();
  c.bodies[0].shape = Ellipse{2.0, 1.0};
  EXPECT_TRUE(mentions(reason(c), "needs a half-plane"));

  c = testing::falling_ball();
  c.contacts.clear();
  EXPECT_TRUE(mentions(reason(c), "0 contact pairs"));

  c = testing::falling_ball();
  c.joints.push_back(RevoluteJoint{"pin", 1, Vec2::Zero(), Vec2::Zero()});
  EXPECT_TRUE(mentions(reason(c), "joints"));

  c = testing::dual_pendulum();
  c.bodies[1].shape = Ellipse{0.5, 0.3};
  EXPECT_TRUE(mentions(reason(c), "no exact gap"));

  c = testing::dual_pendulum();
  c.joints.pop_back();  // the disk flies free
  EXPECT_TRUE(mentions(reason(c), "'disk' has 0 revolute joints"));

  c = testing::dual_pendulum();
  c.bodies[1].fixed = true;
  EXPECT_TRUE(mentions(reason(c), "holds the fixed body"));

  c = testing::falling_ball();
  c.truth = TruthKind::converged;
  EXPECT_TRUE(mentions(reason(c), "truth = converged"));
}

// Two free disks moving along the line of their centres have the head-on
// closed form; an oblique approach does not.
TEST(ClosedFormMatch, TwoDisksHeadOn) {
  Case c;
  c.truth = TruthKind::analytic;
  c.gravity_mps2 = Vec2::Zero();
  auto disk = [](const char* name, double x, double v) {
    Body d;
    d.name = name;
    d.shape = Circle{0.2};
    d.mass_kg = 1.0;
    d.position_m = Vec2(x, 0.0);
    d.velocity_mps = Vec2(v, 0.0);
    return d;
  };
  c.bodies = {disk("a", -0.5, 2.0), disk("b", 0.5, -0.5)};
  ContactPair p;
  p.name = "ab";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  const ClosedFormMatch m = match_closed_form(c);
  EXPECT_EQ(m.kind, ClosedFormKind::two_disks_head_on) << m.reason;
  c.bodies[1].velocity_mps = Vec2(-0.5, 0.1);
  EXPECT_EQ(match_closed_form(c).kind, ClosedFormKind::none);
  EXPECT_TRUE(mentions(match_closed_form(c).reason, "line of their centres"));
}

}  // namespace
}  // namespace pb::internal
