// Tests for adapters/mujoco/mujoco_support.cpp
#include "mujoco_support.hpp"

#include <gtest/gtest.h>

#include "mujoco_test_cases.hpp"

namespace pb::internal::mujoco {
namespace {

TEST(MujocoSupport, KelvinVoigtOnAPlaneIsMappedBecauseOfTheImpedance) {
  const Capability native = mujoco_capability(test::disk_drop(1.0), "native");
  EXPECT_EQ(native.support, Support::mapped);
  EXPECT_NE(native.reason.find("1 - d"), std::string::npos) << native.reason;
  // inject applies the case's own law through an exact collider
  const Capability inject = mujoco_capability(test::disk_drop(1.0), "inject");
  EXPECT_EQ(inject.support, Support::native) << inject.reason;
}

TEST(MujocoSupport, NonlinearLawAndMprAreNamed) {
  const Capability cap = mujoco_capability(test::dual_pendulum(), "native");
  EXPECT_EQ(cap.support, Support::mapped);
  EXPECT_NE(cap.reason.find("lankarani_nikravesh"), std::string::npos) << cap.reason;
  EXPECT_NE(cap.reason.find("set each step"), std::string::npos) << cap.reason;
  EXPECT_NE(cap.reason.find("MPR"), std::string::npos) << cap.reason;
  // the oracle says what it calibrates on
  const Capability oracle = mujoco_capability(test::dual_pendulum(), "oracle");
  EXPECT_NE(oracle.reason.find("probe run"), std::string::npos) << oracle.reason;
  const Capability inject = mujoco_capability(test::dual_pendulum(), "inject");
  EXPECT_EQ(inject.support, Support::mapped);
  EXPECT_EQ(inject.reason.find("lankarani"), std::string::npos) << inject.reason;
}

TEST(MujocoSupport, RefusesWhatMujocoCannotBuild) {
  Case moving_plane = test::disk_drop(1.0);
  moving_plane.bodies[1].fixed = false;
  moving_plane.bodies[1].mass_kg = 1.0;
  moving_plane.bodies[1].inertia_kgm2 = 1.0;
  EXPECT_EQ(mujoco_capability(moving_plane, "native").support, Support::unsupported);

  Case two_joints = test::dual_pendulum();
  two_joints.joints[1].body = 0;
  EXPECT_EQ(mujoco_capability(two_joints, "native").support, Support::unsupported);
}

TEST(MujocoSupport, ConcavePolygonRunsAsConvexPieces) {
  Case concave = test::disk_drop(1.0);
  concave.bodies[0].shape =
      Polygon{{Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)}};
  const Capability c = mujoco_capability(concave, "native");
  EXPECT_EQ(c.support, Support::mapped);
  EXPECT_NE(c.reason.find("convex piece"), std::string::npos) << c.reason;
}

}  // namespace
}  // namespace pb::internal::mujoco
