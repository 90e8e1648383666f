// Tests for adapters/mujoco/mujoco_plan.cpp
#include "mujoco_plan.hpp"

#include <gtest/gtest.h>

#include <string>

#include "mujoco_mjcf.hpp"
#include "mujoco_model.hpp"
#include "mujoco_test_cases.hpp"
#include "planarbench/case_loader.hpp"

namespace pb::internal::mujoco {
namespace {

Case load(const std::string& name) {
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
}

// concave_arch's 8-point arch is cut into convex pieces once, and every
// stage of the build uses the plan's pieces: one geom and one mesh per piece
TEST(MujocoPlan, ConcaveBodyIsCutOnceAndWrittenFromThePlan) {
  const Case c = load("concave_arch");
  const MujocoPlan plan = plan_mujoco(c, 0.01);
  const int arch = c.body_index("arch");
  ASSERT_GE(arch, 0);
  const BodyPlan& bp = plan.bodies[static_cast<std::size_t>(arch)];
  EXPECT_EQ(bp.geom, GeomType::mesh);
  EXPECT_TRUE(bp.decomposed);
  ASSERT_GE(bp.pieces.size(), 2u);
  EXPECT_EQ(bp.apexes.size(), bp.pieces.size());
  MjcfOptions o;
  o.pairs.assign(c.contacts.size(), PairParams{});
  const std::string xml = write_mjcf(c, plan, o);
  std::size_t meshes = 0;
  for (std::size_t at = xml.find("<mesh "); at != std::string::npos; at = xml.find("<mesh ", at + 1)) {
    ++meshes;
  }
  EXPECT_EQ(meshes, bp.pieces.size());
  ModelLayout layout;
  const ModelPtr m = test::load_case(c, o, layout, 0.01);
  EXPECT_EQ(layout.bodies[static_cast<std::size_t>(arch)].geoms.size(), bp.pieces.size());
  // an exact collider (plane-mesh) reports ahead of touch: the margin
  EXPECT_EQ(plan.pairs[0].collider, Collider::exact);
  EXPECT_EQ(plan.pairs[0].margin_m, 0.01);
}

// a frictionless pair: condim 1; a pair with friction: condim 3 and mu on
// both tangents (MuJoCo's first tangent is world y, its second the plane's),
// as the compiled model holds them
TEST(MujocoPlan, FrictionGivesCondimThreeAndMuOnBothTangents) {
  Case c = test::disk_drop(1.0);
  EXPECT_EQ(plan_mujoco(c, 0.0).pairs[0].condim, 1);
  c.contacts[0].friction = 0.35;
  const MujocoPlan plan = plan_mujoco(c, 0.0);
  EXPECT_EQ(plan.pairs[0].condim, 3);
  MjcfOptions o;
  o.pairs.assign(1, PairParams{});
  o.cone = "elliptic";
  o.impratio = 7.0;
  o.noslip_iterations = 4;
  ModelLayout layout;
  const ModelPtr m = test::load_case(c, o, layout);
  ASSERT_EQ(m->npair, 1);
  EXPECT_EQ(m->pair_dim[0], 3);
  EXPECT_EQ(m->pair_friction[0], 0.35);
  EXPECT_EQ(m->pair_friction[1], 0.35);
  EXPECT_EQ(m->opt.cone, mjCONE_ELLIPTIC);
  EXPECT_EQ(m->opt.impratio, 7.0);
  EXPECT_EQ(m->opt.noslip_iterations, 4);
}

}  // namespace
}  // namespace pb::internal::mujoco
