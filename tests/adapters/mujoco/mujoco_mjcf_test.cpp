// Tests for adapters/mujoco/mujoco_mjcf.cpp
//
// The MJCF of a case is compiled by MuJoCo and the compiled model is compared
// with the case: each body's centre of mass, angle, mass and planar inertia
// at the initial state, each plane's outward normal. The cases are small
// made-up scenes with one of every shape, a free body and a pendulum.
#include "mujoco_mjcf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mujoco_frame.hpp"
#include "mujoco_model.hpp"
#include "mujoco_test_cases.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {
namespace {

constexpr double kPi = std::numbers::pi;

MjcfOptions options_for(const Case& c) {
  MjcfOptions o;
  o.pairs.assign(c.contacts.size(), PairParams{});
  return o;
}

// ground tilted by -30 deg; a free ellipse turned by 30 deg; a free triangle;
// a pendulum disk hanging from (1, 2) at 20 deg
Case scene() {
  Case c;
  c.bodies.push_back(test::ground(-kPi / 6.0));
  Body e;
  e.name = "ellipse";
  e.shape = Ellipse{0.6, 0.2};
  e.mass_kg = 2.0;
  e.inertia_kgm2 = 2.0 * (0.36 + 0.04) / 4.0;
  e.position_m = Vec2(-1.0, 3.0);
  e.angle_rad = kPi / 6.0;
  c.bodies.push_back(e);
  Body t;
  t.name = "triangle";
  t.shape = Polygon{{Vec2(-0.3, -0.2), Vec2(0.3, -0.2), Vec2(0.0, 0.4)}};
  t.mass_kg = 0.5;
  t.inertia_kgm2 = 0.01;
  t.position_m = Vec2(2.0, 1.0);
  t.angle_rad = -0.4;
  c.bodies.push_back(t);
  Body d = test::disk("pendulum", 0.1, 3.0,
                      Vec2(1.0 + 0.8 * std::sin(0.35), 2.0 - 0.8 * std::cos(0.35)));
  d.angle_rad = 0.35;
  c.bodies.push_back(d);
  RevoluteJoint j;
  j.name = "pivot";
  j.body = 3;
  j.anchor_world_m = Vec2(1.0, 2.0);
  c.joints.push_back(j);
  c.contacts.push_back(test::kelvin_voigt_pair(0, 1, 1e4, 10.0));
  c.contacts.push_back(test::kelvin_voigt_pair(1, 2, 1e4, 10.0));
  return c;
}

class CompiledScene : public ::testing::Test {
 protected:
  void SetUp() override {
    c_ = scene();
    model_ = test::load_case(c_, options_for(c_), layout_);
    data_.reset(mj_makeData(model_.get()));
    set_initial_state(model_.get(), data_.get(), c_, layout_);
    mj_forward(model_.get(), data_.get());
  }
  Case c_;
  ModelPtr model_;
  ModelLayout layout_;
  DataPtr data_;
};

TEST_F(CompiledScene, BodiesStartAtTheCasePose) {
  for (std::size_t i = 1; i < c_.bodies.size(); ++i) {
    const BodyLayout& l = layout_.bodies[i];
    ASSERT_GT(l.mj_body, 0) << i;
    const Vec2 com = from_mj(&data_->xipos[3 * static_cast<std::size_t>(l.mj_body)]);
    // 1e-12 m: rounding of the pivot offset and of the hinge rotation
    EXPECT_NEAR(com.x(), c_.bodies[i].position_m.x(), 1e-12) << c_.bodies[i].name;
    EXPECT_NEAR(com.y(), c_.bodies[i].position_m.y(), 1e-12) << c_.bodies[i].name;
    EXPECT_NEAR(ccw_from_xmat(&data_->xmat[9 * static_cast<std::size_t>(l.mj_body)]),
                c_.bodies[i].angle_rad, 1e-14);  // atan2 of a rounded rotation
  }
}

TEST_F(CompiledScene, MassAndPlanarInertiaAreTheCases) {
  for (std::size_t i = 1; i < c_.bodies.size(); ++i) {
    const int b = layout_.bodies[i].mj_body;
    EXPECT_EQ(model_->body_mass[b], c_.bodies[i].mass_kg);
    // inertia about MuJoCo's y is the case's out-of-plane inertia; 1e-15
    // kg m^2: MuJoCo's diagonalisation of a diagonal inertia rounds only
    EXPECT_NEAR(model_->body_inertia[3 * b + 1], c_.bodies[i].inertia_kgm2, 1e-15);
  }
}

TEST_F(CompiledScene, JointsArePlanar) {
  // free bodies: slide x, slide z, hinge; the pendulum: its hinge only
  EXPECT_EQ(model_->nq, 3 + 3 + 1);
  EXPECT_GE(layout_.bodies[1].qpos_x, 0);
  EXPECT_EQ(layout_.bodies[3].qpos_x, -1);
  EXPECT_GE(layout_.bodies[3].qpos_hinge, 0);
  // the pendulum's hinge sits at its pivot; 1e-15 m: the body's pose and
  // the pivot offset are rounded sin/cos, so the sum rounds at ~2 eps
  const int jnt = mj_name2id(model_.get(), mjOBJ_JOINT, hinge_name(3).c_str());
  const Vec2 anchor = from_mj(&data_->xanchor[3 * static_cast<std::size_t>(jnt)]);
  EXPECT_NEAR(anchor.x(), 1.0, 1e-15);
  EXPECT_NEAR(anchor.y(), 2.0, 1e-15);
}

TEST_F(CompiledScene, PlaneNormalIsTheHalfPlanesOutwardNormal) {
  // ground at -30 deg: outward normal (sin 30, cos 30); MuJoCo's plane normal
  // is its local z, the third column of geom_xmat; 1e-15: rounded sin/cos
  const double* R = &data_->geom_xmat[9 * static_cast<std::size_t>(layout_.bodies[0].geom)];
  EXPECT_NEAR(R[2], std::sin(kPi / 6.0), 1e-15);
  EXPECT_NEAR(R[5], 0.0, 1e-15);
  EXPECT_NEAR(R[8], std::cos(kPi / 6.0), 1e-15);
}

TEST_F(CompiledScene, OnlyListedPairsCanCollide) {
  EXPECT_EQ(model_->npair, 2);
  for (int g = 0; g < model_->ngeom; ++g) {
    EXPECT_EQ(model_->geom_contype[g], 0);
    EXPECT_EQ(model_->geom_conaffinity[g], 0);
    EXPECT_EQ(model_->geom_condim[g], 1);
  }
  for (int p = 0; p < model_->npair; ++p) EXPECT_EQ(model_->pair_dim[p], 1);
}

TEST(Mjcf, PivotInBodyFrameUndoesTheInitialAngle) {
  // a body at (1, 0) turned 90 deg with its pivot at the origin: in its own
  // frame the pivot is at R(-90 deg)(-1, 0) = (0, 1)
  Case c;
  Body b = test::disk("d", 0.1, 1.0, Vec2(1.0, 0.0));
  b.angle_rad = kPi / 2.0;
  c.bodies.push_back(b);
  RevoluteJoint j;
  j.body = 0;
  c.joints.push_back(j);
  const Vec2 p = pivot_in_body_m(c, c.joints[0]);
  // 1e-15 m: cos(pi/2) rounds to 6e-17
  EXPECT_NEAR(p.x(), 0.0, 1e-15);
  EXPECT_NEAR(p.y(), 1.0, 1e-15);
}

TEST(Mjcf, MovingHalfPlaneIsRefused) {
  Case c;
  Body g = test::ground();
  g.fixed = false;
  g.mass_kg = 1.0;
  g.inertia_kgm2 = 1.0;
  c.bodies.push_back(g);
  EXPECT_THROW((void)write_mjcf(c, plan_mujoco(c, 0.01), MjcfOptions{}), EngineError);
}

}  // namespace
}  // namespace pb::internal::mujoco
