// Tests for adapters/mujoco/mujoco_model.cpp
#include "mujoco_model.hpp"

#include <gtest/gtest.h>

#include <string>

#include "mujoco_frame.hpp"
#include "mujoco_mjcf.hpp"
#include "mujoco_test_cases.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {
namespace {

TEST(MujocoModel, LoadsFromMemory) {
  const ModelPtr m =
      load_mjcf(R"(<mujoco><worldbody><geom type="sphere" size="1"/></worldbody></mujoco>)");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->ngeom, 1);
}

TEST(MujocoModel, CompileErrorBecomesEngineErrorWithMujocosMessage) {
  try {
    (void)load_mjcf("<mujoco><worldbody><geom type=\"nosuchtype\"/></worldbody></mujoco>");
    FAIL() << "an unknown geom type must not compile";
  } catch (const EngineError& e) {
    EXPECT_NE(std::string(e.what()).find("mj_loadXML failed"), std::string::npos) << e.what();
  }
}

TEST(MujocoModel, InitialStateMapsVelocitiesAndAngle) {
  // a free disk at (0, 2) moving at (1, -2) m/s, turned 0.5 rad, spinning at 3 rad/s
  Case c = test::disk_drop(1.0);
  c.bodies[0].velocity_mps = Vec2(1.0, -2.0);
  c.bodies[0].angle_rad = 0.5;
  c.bodies[0].angular_velocity_radps = 3.0;
  MjcfOptions o;
  o.pairs.assign(1, PairParams{});
  ModelLayout L;
  const ModelPtr m = test::load_case(c, o, L);
  DataPtr d(mj_makeData(m.get()));
  set_initial_state(m.get(), d.get(), c, L);
  mj_forward(m.get(), d.get());
  const BodyLayout& b = L.bodies[0];
  EXPECT_EQ(d->qvel[b.dof_x], 1.0);
  EXPECT_EQ(d->qvel[b.dof_z], -2.0);
  EXPECT_EQ(d->qpos[b.qpos_hinge], -0.5);
  EXPECT_EQ(d->qvel[b.dof_hinge], -3.0);
  // MuJoCo's own body velocity: angular about +y is -omega; 1e-15: the
  // body's frame is the world's at angle -0.5 rad about y, rotated back
  mjtNum v[6];
  mj_objectVelocity(m.get(), d.get(), mjOBJ_BODY, b.mj_body, v, 0);
  EXPECT_NEAR(ccw_rate_from_mj(v), 3.0, 1e-15);
  EXPECT_NEAR(from_mj(v + 3).x(), 1.0, 1e-15);
  EXPECT_NEAR(from_mj(v + 3).y(), -2.0, 1e-15);
  // the ground is the world body; the pair knows both geoms
  EXPECT_EQ(L.bodies[1].mj_body, 0);
  EXPECT_EQ(L.pair_of(L.bodies[0].geom, L.bodies[1].geom), 0);
  EXPECT_EQ(L.pair_of(L.bodies[1].geom, L.bodies[0].geom), 0);
  EXPECT_EQ(L.pair_of(L.bodies[0].geom, L.bodies[0].geom), -1);
}

}  // namespace
}  // namespace pb::internal::mujoco
