// Tests for adapters/mujoco/mujoco_solref_rule.cpp
//
// The rule's solref against effective masses worked out by hand: a square
// pressed flat into the ground moves its whole mass (m_set = m, sigma = 1),
// one corner alone 1 / (1/m + r^2/I); and the law's force against MuJoCo's
// own constraint force at a uniform penetration.
#include "mujoco_solref_rule.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mujoco_frame.hpp"
#include "mujoco_mjcf.hpp"
#include "mujoco_stepping.hpp"
#include "mujoco_test_cases.hpp"

namespace pb::internal::mujoco {
namespace {

// the square of square_landing.toml (side 0.2 m, 1.5 kg, I = 0.01 kg m^2)
// over the ground, turned by `angle`, its lowest point `depth` into it
Case square(double angle, double depth) {
  Case c;
  Body sq;
  sq.name = "square";
  sq.shape = Polygon{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
  sq.mass_kg = 1.5;
  sq.inertia_kgm2 = 0.01;
  sq.angle_rad = angle;
  const double low = 0.1 * (std::cos(angle) + std::abs(std::sin(angle)));
  sq.position_m = Vec2(0.0, low - depth);
  c.bodies.push_back(test::ground());
  c.bodies.push_back(sq);
  c.contacts.push_back(test::kelvin_voigt_pair(0, 1, 1e4, 10.0));
  return c;
}

struct Ruled {
  explicit Ruled(const Case& c) : case_(c) {
    MjcfOptions o;
    PairParams p;
    p.solref = {0.0, 0.0};
    p.solimp = {0.9999, 0.9999, 0.001, 0.5, 2.0};
    o.pairs.push_back(p);
    model.reset(test::load_case(case_, o, layout).release());
    data.reset(mj_makeData(model.get()));
    set_initial_state(model.get(), data.get(), case_, layout);
    rule.emplace(case_, model.get(), layout);
    forward_checked(model.get(), data.get(), &SolrefRule::hook, &*rule);
  }
  Case case_;
  ModelPtr model;
  ModelLayout layout;
  DataPtr data;
  std::optional<SolrefRule> rule;
};

TEST(SolrefRule, FlatFaceMovesTheWholeMass) {
  Ruled r(square(0.0, 0.002));
  const SolrefRule::Last& last = r.rule->last(0);
  ASSERT_EQ(last.rows, 2);  // MuJoCo's plane-mesh collider: the two bottom corners
  // MuJoCo stores mesh vertices in float: the lever arms carry 6e-8 relative
  EXPECT_NEAR(last.mass_kg, 1.5, 1.5 * 1e-6);
  EXPECT_NEAR(last.scale, 1.0, 1e-6);
  EXPECT_NEAR(last.solref_k, -1e4 / 1.5, 1e4 / 1.5 * 1e-6);
  EXPECT_NEAR(last.solref_b, -10.0 / 1.5, 10.0 / 1.5 * 1e-6);
  // the same solref went to the pair for the RK4 stages
  EXPECT_EQ(r.model->pair_solref[0], last.solref_k);
  EXPECT_EQ(r.model->pair_solref[1], last.solref_b);
}

TEST(SolrefRule, OneCornerMovesItsEffectiveMass) {
  // turned 30 deg: one corner in, 0.1 (cos 30 - sin 30) m beside the centre
  const double a = std::acos(-1.0) / 6.0;
  Ruled r(square(a, 0.002));
  const SolrefRule::Last& last = r.rule->last(0);
  ASSERT_EQ(last.rows, 1);
  const double lever = 0.1 * (std::cos(a) - std::sin(a));  // m, horizontal offset
  const double m_eff = 1.0 / (1.0 / 1.5 + lever * lever / 0.01);
  EXPECT_NEAR(last.mass_kg, m_eff, m_eff * 1e-6);
  EXPECT_EQ(last.scale, 1.0);
}

// The law's force on a uniform penetration, worked out from MuJoCo 2.2.2's
// constraint equations (engine_core_constraint.c, mj_makeImpedance: direct
// solref gives K = -solref[0] / dmax^2, aref = -K imp r at rest; R = (1 - imp)
// / imp * diagApprox): the flat square's two condim-1 rows at x = +-0.1 m have
// A = J M^-1 J^T with row sums 2 / m (the lever terms cancel), so each row
// solves (2 / m + R) f = K imp delta + g and the pair carries
//   2 f = (k delta / dmax + m g) / (1 + R m / 2)
// with k delta the law's force and R read from MuJoCo's data (at imp = dmax
// = 0.9999 it takes 3e-5 of the load)
TEST(SolrefRule, UniformPenetrationGivesTheLawsForce) {
  Ruled r(square(0.0, 0.002));
  double f = 0.0;
  int rows = 0;
  double R = 0.0;
  for (int i = 0; i < r.data->ncon; ++i) {
    const int row = r.data->contact[i].efc_address;
    if (row < 0) continue;
    mjtNum f6[6];
    mj_contactForce(r.model.get(), r.data.get(), i, f6);
    f += f6[0];
    R = r.data->efc_R[row];
    ++rows;
  }
  ASSERT_EQ(rows, 2);
  const double m = 1.5;                  // kg
  const double g = -r.model->opt.gravity[2];  // m/s^2, case y is MuJoCo z
  const double dmax = 0.9999;            // solimp of Ruled
  const double law = 1e4 * 0.002;        // N, k delta
  const double expected = (law / dmax + m * g) / (1.0 + R * m / 2.0);
  // the float mesh vertices: 6e-8 of 0.1 m on a 2 mm depth is 3e-6 of the
  // law's 20 N (6e-5 N); the solver's tolerance (1e-8) is far below
  EXPECT_NEAR(f, expected, 1e-4);
  // and the rule's part is the law's: without it the pair would carry m g
  EXPECT_GT(f - m * g, 0.99 * law);
}

}  // namespace
}  // namespace pb::internal::mujoco
