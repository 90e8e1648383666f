// Tests for adapters/mujoco/mujoco_shared_vertex.cpp
//
// A vertex two convex pieces of one body share is one contact: the L of
// concave_corner.toml on its outer corner (both pieces' vertex) gives one
// constraint row with the corner's effective mass, and the boot of
// concave_seam_face.toml flat on its sole (heel in both pieces, toe in one)
// two rows that move the whole mass.
#include "mujoco_shared_vertex.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "mujoco_mjcf.hpp"
#include "mujoco_solref_rule.hpp"
#include "mujoco_stepping.hpp"
#include "mujoco_test_cases.hpp"

namespace pb::internal::mujoco {
namespace {

constexpr double kPi = 3.14159265358979323846;

// a polygon body over the ground, turned by `angle`, its lowest vertex
// `depth` into it
Case polygon_on_ground(const std::vector<Vec2>& points, double inertia, double angle,
                       double depth) {
  Case c;
  Body b;
  b.name = "body";
  b.shape = Polygon{points};
  b.mass_kg = 1.0;
  b.inertia_kgm2 = inertia;
  b.angle_rad = angle;
  double low = 1e300;
  for (const Vec2& p : points) {
    low = std::min(low, std::sin(angle) * p.x() + std::cos(angle) * p.y());
  }
  b.position_m = Vec2(0.0, -low - depth);
  c.bodies.push_back(test::ground());
  c.bodies.push_back(b);
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
  [[nodiscard]] int included() const {
    int n = 0;
    for (int i = 0; i < data->ncon; ++i) n += data->contact[i].exclude == 0 ? 1 : 0;
    return n;
  }
  Case case_;
  ModelPtr model;
  ModelLayout layout;
  DataPtr data;
  std::optional<SolrefRule> rule;
};

// the L: arms 0.3 m x 0.1 m, centroid at the origin, I = 217/15000 kg m^2
const std::vector<Vec2> kL = {{-0.11, -0.11}, {0.19, -0.11}, {0.19, -0.01},
                              {-0.01, -0.01}, {-0.01, 0.19}, {-0.11, 0.19}};

// Both pieces report the outer corner: one is fused (exclude = 2), one row
// remains, and its mass is the corner's 1 / (1/m + r_x^2 / I) with
// r_x = 0.11 (cos 20 - sin 20) m. Before the fusion the two rows at one point
// (a float rounding apart) made m_set the whole 1 kg. 1e-6 relative: MuJoCo's
// float mesh vertices (6e-8 relative) in the lever arm.
TEST(SharedVertex, CornerOfTwoPiecesIsOneContactWithItsEffectiveMass) {
  const double angle = kPi / 9.0;
  Ruled r(polygon_on_ground(kL, 217.0 / 15000.0, angle, 0.002));
  EXPECT_EQ(r.rule->most_fused(), 1);
  EXPECT_EQ(r.included(), 1);
  const SolrefRule::Last& last = r.rule->last(0);
  ASSERT_EQ(last.rows, 1);
  const double rx = 0.11 * (std::cos(angle) - std::sin(angle));
  const double m_eff = 1.0 / (1.0 + rx * rx / (217.0 / 15000.0));
  EXPECT_NEAR(last.mass_kg, m_eff, m_eff * 1e-6);
  EXPECT_EQ(last.scale, 1.0);
}

// The boot flat on its sole: heel (both pieces) and toe (one piece): three
// contacts, one fused, two rows a whole sole apart that move the whole mass
// (m_set = m, sigma = 1: a uniform penetration accelerates both alike).
// m_set to 1e-6 relative: float mesh vertices (6e-8 relative) in the lever
// arms. sigma = delta / delta_w to 1e-5: the two depths differ by the float
// rounding of two vertices of different meshes, up to 2 x 6e-8 x 0.2 m =
// 2.4e-8 m, 1.2e-5 of the 2 mm depth at most, half of it in delta_w.
TEST(SharedVertex, SoleWithASharedHeelMovesTheWholeMass) {
  const std::vector<Vec2> boot = {{-0.2, -0.09982758620689655}, {0.2, -0.09982758620689655},
                                  {0.2, 0.14017241379310344},   {-0.12, -0.039827586206896554},
                                  {-0.12, 0.17017241379310344}, {-0.2, 0.17017241379310344}};
  Ruled r(polygon_on_ground(boot, 0.0214747, 0.0, 0.002));
  EXPECT_EQ(r.rule->most_fused(), 1);
  const SolrefRule::Last& last = r.rule->last(0);
  ASSERT_EQ(last.rows, 2);
  EXPECT_NEAR(last.mass_kg, 1.0, 1e-6);
  EXPECT_NEAR(last.scale, 1.0, 1e-5);
}

// Contacts of one geom pair are never fused (distinct points of one piece),
// nor are contacts of different case pairs: a convex square has nothing to fuse.
TEST(SharedVertex, ConvexBodyHasNothingToFuse) {
  const std::vector<Vec2> square = {{-0.1, -0.1}, {0.1, -0.1}, {0.1, 0.1}, {-0.1, 0.1}};
  Ruled r(polygon_on_ground(square, 0.01 / 1.5, 0.0, 0.002));
  EXPECT_EQ(r.rule->most_fused(), 0);
  EXPECT_EQ(r.included(), 2);
}

}  // namespace
}  // namespace pb::internal::mujoco
