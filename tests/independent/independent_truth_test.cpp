// Tests for core/independent/independent_truth.cpp: which cases it covers,
// and why not the others.
#include "planarbench/independent/independent_truth.hpp"

#include <gtest/gtest.h>

#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"

namespace pb::independent {
namespace {

Case load(const char* name) {
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
}

TEST(IndependentTruth, CoversTheCasesItReplaces) {
  for (const char* name : {"ellipse_incline", "dual_pendulum", "pendulum_wall", "falling_ball"}) {
    EXPECT_EQ(IndependentTruth::unsupported(load(name)), "") << name;
  }
  const IndependentTruth t(load("ellipse_incline"));
  const nlohmann::json d = t.description();
  EXPECT_NE(d.at("solver").get<std::string>().find("Boost.Odeint"), std::string::npos);
  EXPECT_EQ(d.at("laws").size(), 1u);
}

TEST(IndependentTruth, SaysWhyNot) {
  Case friction = load("ellipse_incline");
  friction.contacts[0].friction = 0.3;
  EXPECT_NE(IndependentTruth::unsupported(friction).find("frictionless"), std::string::npos);
  EXPECT_THROW(IndependentTruth{friction}, EngineError);

  Case disks = load("head_on");  // two disks: not a pair this truth covers
  EXPECT_NE(IndependentTruth::unsupported(disks).find("shapes circle and circle"),
            std::string::npos)
      << IndependentTruth::unsupported(disks);

  Case overlap = load("ellipse_incline");
  overlap.bodies[1].position_m = Vec2(0.0, 0.05);  // the ellipse's centre 5 cm above the line
  EXPECT_NE(IndependentTruth::unsupported(overlap).find("overlaps at t = 0"), std::string::npos);

  Case two_joints = load("pendulum_wall");
  two_joints.joints.push_back(two_joints.joints[0]);
  EXPECT_NE(IndependentTruth::unsupported(two_joints).find("more than one joint"),
            std::string::npos);
}

}  // namespace
}  // namespace pb::independent
