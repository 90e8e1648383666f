// Tests for adapters/mujoco/mujoco_pair_state.cpp
//
// Static scenes with known geometry: a disk sunk 3 mm into the ground, a
// pendulum disk pressed against a wall, an ellipse touching a disk. The
// truths are the geometry (penetration, normal, midpoint), the rigid-body
// kinematics of the contact point, and the effective mass of a pendulum
// along a normal, I_pivot / (r x n)^2 (a textbook impulse relation).
#include "mujoco_pair_state.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "mujoco_frame.hpp"
#include "mujoco_mjcf.hpp"
#include "mujoco_test_cases.hpp"

namespace pb::internal::mujoco {
namespace {

constexpr double kPi = std::numbers::pi;

// compiles `c` with margin 0, every pair inactive (or
// active, with a stiff direct solref), runs mj_forward at the initial state
struct Compiled {
  Compiled(const Case& c, bool active) {
    MjcfOptions o;
    for (std::size_t k = 0; k < c.contacts.size(); ++k) {
      PairParams p;
      p.gap_m = active ? 0.0 : 1e3;
      p.solref = {-1e4, -10.0};
      p.solimp = {0.9999, 0.9999, 0.001, 0.5, 2.0};
      o.pairs.push_back(p);
    }
    model.reset(test::load_case(c, o, layout).release());
    data.reset(mj_makeData(model.get()));
    set_initial_state(model.get(), data.get(), c, layout);
    mj_forward(model.get(), data.get());
    scratch.emplace(model.get());
  }
  std::vector<PairObservation> observe(bool with_force) {
    std::vector<PairObservation> out;
    observe_pairs(model.get(), data.get(), layout, with_force, *scratch, out);
    return out;
  }
  ModelPtr model;
  ModelLayout layout;
  DataPtr data;
  std::optional<Scratch> scratch;
};

// a disk R = 0.5, m = 1.5 whose centre is 3 mm too low over the ground,
// moving down at 2 m/s
Case sunk_disk(bool ground_first) {
  Case c;
  c.bodies.push_back(test::disk("disk", 0.5, 1.5, Vec2(0.7, 0.497)));
  c.bodies[0].velocity_mps = Vec2(0.4, -2.0);
  c.bodies.push_back(test::ground());
  c.contacts.push_back(ground_first ? test::kelvin_voigt_pair(1, 0, 1e4, 10.0)
                                    : test::kelvin_voigt_pair(0, 1, 1e4, 10.0));
  return c;
}

TEST(PairState, PenetrationNormalAndPointOfASunkDisk) {
  Compiled s(sunk_disk(true), false);
  const auto obs = s.observe(false);
  ASSERT_TRUE(obs[0].reported);
  // 1e-15 m: one subtraction of rounded coordinates
  EXPECT_NEAR(obs[0].penetration_m, 0.003, 1e-15);
  // normal from body_a (ground) to body_b (disk): up
  EXPECT_NEAR(obs[0].normal_ab.x(), 0.0, 1e-15);
  EXPECT_NEAR(obs[0].normal_ab.y(), 1.0, 1e-15);
  // MuJoCo's point is the midpoint of the two surfaces: y = -0.0015
  EXPECT_NEAR(obs[0].point_m.x(), 0.7, 1e-15);
  EXPECT_NEAR(obs[0].point_m.y(), -0.0015, 1e-15);
  // approaching at 2 m/s along the normal (the tangential 0.4 m/s does not count)
  EXPECT_NEAR(obs[0].approach_speed_mps, 2.0, 1e-15);
}

TEST(PairState, NormalFollowsThePairOrderNotMujocosGeomOrder) {
  // MuJoCo always puts the plane first; the case pair decides the direction
  Compiled s(sunk_disk(false), false);
  const auto obs = s.observe(false);
  EXPECT_NEAR(obs[0].normal_ab.y(), -1.0, 1e-15);
  EXPECT_NEAR(obs[0].approach_speed_mps, 2.0, 1e-15);
}

TEST(PairState, ForceOnlyFromActiveContacts) {
  Compiled inactive(sunk_disk(true), false);
  EXPECT_EQ(inactive.observe(true)[0].force_n, 0.0);
  Compiled active(sunk_disk(true), true);
  // pushed apart: MuJoCo's soft contact at impedance d gives the force
  // m (aref - d a0) / (m A + (1 - d) / d (...)), aref = k delta + c delta_dot
  // per unit mass (direct solref), a0 = -g: to O(1 - d) = 1e-4, m (k delta +
  // c delta_dot + g) (ENGINES.md; the same model as the engine's drop test).
  // 1e-3 relative: a few O(1 - d) terms (impedance, MuJoCo's approximate
  // regulariser diagonal, dmax scaling of the direct solref)
  const double expected = 1.5 * (1e4 * 0.003 + 10.0 * 2.0 + 9.8066);
  EXPECT_NEAR(active.observe(true)[0].force_n, expected, 1e-3 * expected);
}

TEST(PairState, EffectiveMassOfAFreeDiskIsItsMass) {
  Compiled s(sunk_disk(true), false);
  const auto obs = s.observe(false);
  const auto p = to_mj(obs[0].point_m);
  const auto n = to_mj(obs[0].normal_ab);
  const PairLayout& L = s.layout.pairs[0];
  // the normal passes through the centre: rotation does not couple; 1e-12
  // kg: MuJoCo's factorised M^-1, rounding only
  EXPECT_NEAR(effective_mass_kg(s.model.get(), s.data.get(), L.mj_body_a, L.mj_body_b, p.data(),
                                n.data(), *s.scratch),
              1.5, 1e-12);
}

TEST(PairState, EffectiveMassOfAPendulumAgainstAWall) {
  // disk R = 0.5, m = 1, I = 0.125 hanging 1 m below its pivot at the origin,
  // pressed 2 mm into a wall whose outward normal is -x (a half-plane turned
  // 90 deg, surface at x = 0.498). The contact at height -1 has a lever arm of
  // 1 m about the pivot: m_eff = I_pivot / 1^2 = 0.125 + 1 * 1^2 = 1.125 kg.
  Case c;
  c.bodies.push_back(test::disk("disk", 0.5, 1.0, Vec2(0.0, -1.0)));
  Body wall = test::ground(kPi / 2.0);
  wall.position_m = Vec2(0.498, 0.0);
  c.bodies.push_back(wall);
  RevoluteJoint j;
  j.body = 0;
  j.anchor_world_m = Vec2(0.0, 0.0);
  c.joints.push_back(j);
  c.contacts.push_back(test::kelvin_voigt_pair(1, 0, 1e4, 10.0));
  Compiled s(c, false);
  const auto obs = s.observe(false);
  ASSERT_TRUE(obs[0].reported);
  // 1e-15 m: one subtraction of rounded coordinates, as above
  EXPECT_NEAR(obs[0].penetration_m, 0.002, 1e-15);
  // from the wall to the disk: the wall's outward normal (-sin 90, cos 90)
  EXPECT_NEAR(obs[0].normal_ab.x(), -1.0, 1e-15);
  const auto p = to_mj(obs[0].point_m);
  const auto n = to_mj(obs[0].normal_ab);
  const PairLayout& L = s.layout.pairs[0];
  EXPECT_NEAR(effective_mass_kg(s.model.get(), s.data.get(), L.mj_body_a, L.mj_body_b, p.data(),
                                n.data(), *s.scratch),
              1.125, 1e-12);  // as above: rounding of MuJoCo's M^-1
}

TEST(PairState, FlatPolygonTouchesWithItsTwoLowestVerticesOnly) {
  // a square of side 0.4 m lying flat, sunk 2 mm: MuJoCo's plane-mesh collider
  // reports the two bottom corners (a prism would add two more at y = +-w)
  Case c;
  Body sq;
  sq.name = "square";
  sq.shape = Polygon{{Vec2(-0.2, -0.2), Vec2(0.2, -0.2), Vec2(0.2, 0.2), Vec2(-0.2, 0.2)}};
  sq.mass_kg = 1.0;
  sq.inertia_kgm2 = 1.0 * (0.16 + 0.16) / 12.0;
  sq.position_m = Vec2(0.0, 0.198);
  c.bodies.push_back(sq);
  c.bodies.push_back(test::ground());
  c.contacts.push_back(test::kelvin_voigt_pair(1, 0, 1e4, 10.0));
  Compiled s(c, false);
  const auto obs = s.observe(false);
  ASSERT_TRUE(obs[0].reported);
  EXPECT_EQ(obs[0].contacts, 2);
  // 2e-8 m: MuJoCo stores mesh vertices as float (mjModel::mesh_vert), a
  // relative rounding of 6e-8 on coordinates of 0.2 m
  EXPECT_NEAR(obs[0].penetration_m, 0.002, 2e-8);
  EXPECT_NEAR(obs[0].normal_ab.y(), 1.0, 1e-15);
  // both corners pressed in alike: the pair's point is their depth-weighted
  // centroid, the face's middle (SPEC §1), to the float rounding above
  EXPECT_EQ(obs[0].pressed, 2);
  EXPECT_NEAR(obs[0].point_m.x(), 0.0, 2e-8);
}

TEST(PairState, EllipseDiskNormalPointsFromAToB) {
  // the dual pendulum's two bodies nudged 0.1 mm into each other, the ellipse
  // hanging vertically (its side at x = 0.25), the disk's side at 0.2499
  Case c = test::dual_pendulum();
  c.joints.clear();
  c.bodies[0].angle_rad = kPi / 2.0;
  c.bodies[0].position_m = Vec2(0.0, -0.7071);
  c.bodies[1].position_m = Vec2(0.7499, -0.7071);
  Compiled s(c, false);
  const auto obs = s.observe(false);
  ASSERT_TRUE(obs[0].reported);
  // libccd MPR: depth to ~1e-6 m (ENGINES.md), normal to ~1e-6
  EXPECT_NEAR(obs[0].penetration_m, 1e-4, 2e-6);
  EXPECT_NEAR(obs[0].normal_ab.x(), 1.0, 1e-6);
  EXPECT_NEAR(obs[0].normal_ab.y(), 0.0, 1e-5);
  EXPECT_NEAR(obs[0].point_m.x(), 0.24995, 2e-6);
  EXPECT_NEAR(obs[0].point_m.y(), -0.7071, 1e-5);
}

}  // namespace
}  // namespace pb::internal::mujoco
