// Tests for adapters/mujoco/mujoco_frame.cpp
//
// The one sign of the adapter: the case's counter-clockwise angle theta in
// the x-y plane is MuJoCo's hinge coordinate -theta about +y in the x-z plane.
// The truth is MuJoCo's own kinematics: a body on a hinge about +y, turned to
// hinge_from_ccw(theta), must carry its x axis to (cos theta, 0, sin theta),
// the case direction (cos theta, sin theta) in MuJoCo's axes.
#include "mujoco_frame.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mujoco_model.hpp"

namespace pb::internal::mujoco {
namespace {

constexpr double kPi = std::numbers::pi;

// A body on a hinge about +y at the origin (MJCF written here by hand, so
// that the test does not use the adapter's writer).
class HingeKinematics : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = load_mjcf(R"(<mujoco><compiler inertiafromgeom="false"/><worldbody>
      <body name="b"><joint name="h" type="hinge" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></worldbody></mujoco>)");
    data_.reset(mj_makeData(model_.get()));
  }
  // MuJoCo's rotation matrix of the body at hinge coordinate q
  const double* xmat_at(double q) {
    data_->qpos[0] = q;
    mj_kinematics(model_.get(), data_.get());
    return data_->xmat + 9;
  }
  ModelPtr model_;
  DataPtr data_;
};

TEST_F(HingeKinematics, CaseAngleTurnsBodyXTowardCaseY) {
  for (double theta : {0.3, kPi / 2.0, -1.2, 2.9}) {
    const double* R = xmat_at(hinge_from_ccw(theta));
    // first column: the image of body x; 1e-15: rounding of cos/sin
    EXPECT_NEAR(R[0], std::cos(theta), 1e-15) << theta;
    EXPECT_NEAR(R[3], 0.0, 1e-15) << theta;
    EXPECT_NEAR(R[6], std::sin(theta), 1e-15) << theta;
  }
}

TEST_F(HingeKinematics, AngleFromXmatInvertsTheMapping) {
  for (double theta : {0.0, 0.7, -2.5, 3.0}) {
    // 1e-14: atan2 of rounded cos/sin
    EXPECT_NEAR(ccw_from_xmat(xmat_at(hinge_from_ccw(theta))), theta, 1e-14);
  }
}

TEST_F(HingeKinematics, QuaternionMatchesTheHingeRotation) {
  // a frame given quat_from_ccw(theta) has the rotation the hinge gives
  for (double theta : {0.4, -1.9}) {
    const auto q = quat_from_ccw(theta);
    double from_quat[9];
    mju_quat2Mat(from_quat, q.data());
    const double* R = xmat_at(hinge_from_ccw(theta));
    // 1e-15: quaternion products of rounded half-angle sin/cos
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(from_quat[i], R[i], 1e-15) << i;
  }
}

TEST(Frame, PointsMapXYToXZ) {
  const auto p = to_mj(Vec2(1.5, -2.0));
  EXPECT_EQ(p[0], 1.5);
  EXPECT_EQ(p[1], 0.0);
  EXPECT_EQ(p[2], -2.0);
  const double back[3] = {1.5, 0.25, -2.0};
  EXPECT_EQ(from_mj(back), Vec2(1.5, -2.0));
}

TEST(Frame, RatesFollowTheAngleSign) {
  // omega_ccw > 0 turns counter-clockwise: the hinge about +y turns negative
  EXPECT_EQ(hinge_rate_from_ccw(2.0), -2.0);
  EXPECT_EQ(ccw_rate_from_hinge(-2.0), 2.0);
  const double w[3] = {0.0, -3.0, 0.0};
  EXPECT_EQ(ccw_rate_from_mj(w), 3.0);
  EXPECT_EQ(ccw_from_hinge(hinge_from_ccw(0.8)), 0.8);
}

}  // namespace
}  // namespace pb::internal::mujoco
