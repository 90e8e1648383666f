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
  EXPECT_EQ(fb.kind, ClosedFormKind::disk_on_line);
  EXPECT_EQ(fb.disk, 1);
  EXPECT_EQ(fb.line, 0);
  EXPECT_EQ(fb.pair, 0);
  EXPECT_TRUE(fb.reason.empty());
  EXPECT_EQ(match_closed_form(testing::sliding()).kind, ClosedFormKind::disk_on_line);
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
  c.contacts[0].law = LankaraniNikravesh{1e9, 1.5, 0.7, std::nullopt};
  EXPECT_TRUE(mentions(reason(c), "lankarani_nikravesh"));

  c = testing::falling_ball();
  Body second = c.bodies[1];
  second.name = "second";
  second.position_m = Vec2(5.0, 5.0);
  c.bodies.push_back(second);
  EXPECT_TRUE(mentions(reason(c), "2 moving bodies"));

  c = testing::falling_ball();
  c.bodies[1].shape = Polygon{{Vec2(-0.5, -0.5), Vec2(0.5, -0.5), Vec2(0.0, 0.5)}};
  EXPECT_TRUE(mentions(reason(c), "needs a circle"));

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
}

}  // namespace
}  // namespace pb::internal
