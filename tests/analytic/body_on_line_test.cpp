// Tests for core/analytic/body_on_line.cpp
#include "body_on_line.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "independent_integrators.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal {
namespace {

// A disk (R = 0.3 m, 2 kg, spinning at 4 rad/s) thrown at a line that passes
// through (3, -1) at 20 degrees; Kelvin-Voigt K = 2e4 N/m, c = 30 N s/m.
// Nothing in this set-up is aligned with the world axes, so the test checks
// the frame of the line as well as the motion in it.
Case tilted_case(bool disk_is_body_a) {
  Case c;
  c.name = "tilted";
  c.truth = TruthKind::analytic;
  c.duration_s = 1.5;
  Body ground;
  ground.name = "ground";
  ground.shape = HalfPlane{};
  ground.fixed = true;
  ground.position_m = Vec2(3.0, -1.0);
  ground.angle_rad = 20.0 * std::numbers::pi / 180.0;
  Body disk;
  disk.name = "disk";
  disk.shape = Circle{0.3};
  disk.mass_kg = 2.0;
  disk.inertia_kgm2 = 0.09;
  disk.position_m = Vec2(2.0, 1.5);
  disk.angle_rad = 0.7;
  disk.velocity_mps = Vec2(1.5, 0.5);
  disk.angular_velocity_radps = 4.0;
  c.bodies = {ground, disk};
  ContactPair p;
  p.name = "pair";
  p.body_a = disk_is_body_a ? 1 : 0;
  p.body_b = disk_is_body_a ? 0 : 1;
  p.law = KelvinVoigt{2e4, 30.0, 0.0};
  c.contacts = {p};
  return c;
}

testing::DiskLineProblem problem_of(const Case& c) {
  testing::DiskLineProblem p;
  const Body& g = c.bodies[0];
  const Body& d = c.bodies[1];
  const auto& kv = std::get<KelvinVoigt>(c.contacts[0].law);
  p.mass_kg = d.mass_kg;
  p.radius_m = std::get<Circle>(d.shape).radius_m;
  p.stiffness_n_per_m = kv.stiffness_n_per_m;
  p.damping_ns_per_m = kv.damping_ns_per_m;
  p.gravity_mps2 = c.gravity_mps2;
  p.line_point_m = g.position_m;
  // outward normal of the half-plane: body +y turned by the body angle
  p.line_normal = testing::V2(-std::sin(g.angle_rad), std::cos(g.angle_rad));
  p.position0_m = d.position_m;
  p.velocity0_mps = d.velocity_mps;
  return p;
}

// Body states and contact samples against the independent x-y integration
// (RK4, h = 2e-6 s, located switches) every 5 ms.
TEST(BodyOnLine, TiltedLineMatchesIndependentIntegration) {
  const Case c = tilted_case(false);
  BodyOnLine d(c, 1, 0, 0);
  d.extend_to(c.duration_s);
  testing::DiskLineIntegrator ref(problem_of(c), 2e-6);
  std::vector<BodyState> states;
  std::vector<ContactSample> contacts;
  int contact_samples = 0;
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.005 * k;
    ref.advance_to(t);
    d.body_states(t, states);
    ASSERT_EQ(states.size(), 2u);
    // the ground stays where it is
    EXPECT_EQ(states[0].position_m, c.bodies[0].position_m);
    EXPECT_EQ(states[0].angle_rad, c.bodies[0].angle_rad);
    EXPECT_EQ(states[0].velocity_mps, Vec2::Zero());
    // 1e-9 relative to the scales of the motion (a few m, a few m/s): the
    // acceptance criterion of issue 2; they agree to ~1e-12
    EXPECT_LE((states[1].position_m - ref.position()).norm(), 1e-9) << "t=" << t;
    EXPECT_LE((states[1].velocity_mps - ref.velocity()).norm(), 1e-9) << "t=" << t;
    // no friction, normal force through the centre: the spin never changes
    EXPECT_DOUBLE_EQ(states[1].angle_rad, 0.7 + 4.0 * t);
    EXPECT_EQ(states[1].angular_velocity_radps, 4.0);

    d.contacts(t, contacts);
    if (ref.penetration() > 1e-9) {
      ASSERT_EQ(contacts.size(), 1u) << "t=" << t;
      ++contact_samples;
      const ContactSample& cs = contacts[0];
      EXPECT_EQ(cs.body_a, 0);
      EXPECT_EQ(cs.body_b, 1);
      EXPECT_NEAR(cs.penetration_m, ref.penetration(), 1e-12);
      EXPECT_NEAR(cs.force_n, ref.force(), 1e-9 * 2e4 * 0.05);  // scale K * 5 cm
      // normal from the ground (a) to the disk (b): the line's outward normal
      EXPECT_NEAR((cs.normal - problem_of(c).line_normal).norm(), 0.0, 1e-15);
      // midpoint of the deepest point c - R n and its projection on the line
      const Vec2 n = problem_of(c).line_normal;
      const Vec2 deepest = ref.position() - 0.3 * n;
      const Vec2 on_line = ref.position() - ((ref.position() - c.bodies[0].position_m).dot(n)) * n;
      EXPECT_LE((cs.point_m - 0.5 * (deepest + on_line)).norm(), 1e-9);
    } else if (ref.penetration() < -1e-9) {
      EXPECT_TRUE(contacts.empty()) << "t=" << t;
    }
  }
  EXPECT_GT(contact_samples, 3);  // the set-up does hit the line
}

// With the disk as body_a, the normal points from the disk into the ground.
TEST(BodyOnLine, NormalFollowsThePairOrder) {
  const Case c = tilted_case(true);
  BodyOnLine d(c, 1, 0, 0);
  d.extend_to(c.duration_s);
  const auto eps = d.episodes(c.duration_s);
  ASSERT_FALSE(eps.empty());
  EXPECT_EQ(eps[0].body_a, 1);
  EXPECT_EQ(eps[0].body_b, 0);
  const double t = eps[0].onset_time_s + 0.5 * (eps[0].offset_time_s - eps[0].onset_time_s);
  std::vector<ContactSample> contacts;
  d.contacts(t, contacts);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].body_a, 1);
  const Vec2 n(-std::sin(20.0 * std::numbers::pi / 180.0),
               std::cos(20.0 * std::numbers::pi / 180.0));
  EXPECT_NEAR((contacts[0].normal + n).norm(), 0.0, 1e-15);  // unit vectors: a few ulps
}

// The sliding case's "touching" start: the centre R n is one ulp off, the
// computed gap is rounding (~1e-17 m) and counts as zero: the contact starts
// at t = 0. A real gap of 1 nm does not.
TEST(BodyOnLine, RoundingOfATouchingStartIsZero) {
  Case c = tilted_case(false);
  const double r = 0.25;
  c.bodies[0].position_m = Vec2::Zero();
  c.bodies[0].angle_rad = -std::numbers::pi / 4.0;
  c.bodies[1].shape = Circle{r};
  c.bodies[1].velocity_mps = Vec2::Zero();
  const double s = r * std::sin(std::numbers::pi / 4.0);
  c.bodies[1].position_m = Vec2(std::nextafter(s, 1.0), s);
  BodyOnLine touching(c, 1, 0, 0);
  EXPECT_EQ(touching.normal_motion().params().gap0_m, 0.0);
  EXPECT_EQ(touching.normal_motion().phases()[0].kind, NormalPhaseKind::pressed);

  const Vec2 n(std::sqrt(0.5), std::sqrt(0.5));
  c.bodies[1].position_m = (r + 1e-9) * n;
  BodyOnLine apart(c, 1, 0, 0);
  // |c| - r with |c| ~ 0.25 m: rounding ~3e-17 m, well under the 1e-9 m gap
  EXPECT_NEAR(apart.normal_motion().params().gap0_m, 1e-9, 1e-16);
  EXPECT_EQ(apart.normal_motion().phases()[0].kind, NormalPhaseKind::separated);
}

// The mapping states the closed form and its parameters.
TEST(BodyOnLine, MappingDescribesTheClosedForm) {
  const Case c = tilted_case(false);
  BodyOnLine d(c, 1, 0, 0);
  const nlohmann::json j = d.mapping();
  EXPECT_EQ(j.at("closed_form"), "body_on_line");
  EXPECT_EQ(j.at("law"), "kelvin_voigt");
  EXPECT_DOUBLE_EQ(j.at("damping_ratio").get<double>(), 30.0 / (2.0 * std::sqrt(2e4 * 2.0)));
  // static penetration m |g.n| / K
  const double gn = 9.8066 * std::cos(20.0 * std::numbers::pi / 180.0);
  // ~9e-4 m: 1e-18 m is a few ulps of it
  EXPECT_NEAR(j.at("static_penetration_m").get<double>(), 2.0 * gn / 2e4, 1e-18);
  EXPECT_TRUE(j.at("not_expressed").empty());
}

// phases_begun counts the phases of the normal motion started so far.
TEST(BodyOnLine, PhasesBegun) {
  const Case c = tilted_case(false);
  BodyOnLine d(c, 1, 0, 0);
  d.extend_to(c.duration_s);
  EXPECT_EQ(d.phases_begun(0.0), 1);
  const auto& ph = d.normal_motion().phases();
  ASSERT_GE(ph.size(), 3u);
  EXPECT_EQ(d.phases_begun(ph[1].start_s), 2);
  EXPECT_EQ(d.phases_begun(c.duration_s),
            static_cast<long>(d.normal_motion().phase_index_at(1.5) + 1));
}

// square_landing.toml's square (side 0.2 m, 1.5 kg) turned by `angle`,
// released from rest above a horizontal line (or `line_angle`)
Case square_case(double angle, double line_angle, double spin) {
  Case c;
  c.name = "square";
  c.truth = TruthKind::analytic;
  c.duration_s = 1.2;
  Body ground;
  ground.name = "ground";
  ground.shape = HalfPlane{};
  ground.fixed = true;
  ground.angle_rad = line_angle;
  Body sq;
  sq.name = "square";
  sq.shape = Polygon{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
  sq.mass_kg = 1.5;
  sq.inertia_kgm2 = 0.01;
  sq.angle_rad = angle;
  sq.angular_velocity_radps = spin;
  // the centre 0.6 m above the line along its normal: the face 0.5 m above
  const Vec2 n(-std::sin(line_angle), std::cos(line_angle));
  sq.position_m = 0.6 * n;
  c.bodies = {ground, sq};
  ContactPair p;
  p.name = "pair";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  return c;
}

// A square landing flat moves like a disk of radius half its side: the same
// independent integration (a disk of radius 0.1 m) every 5 ms, and it never
// turns; its contact point is the face's middle.
TEST(BodyOnLine, SquareLandingFlatIsATranslatingFace) {
  const double line_angle = -0.3;  // not aligned with the world axes
  const Case c = square_case(line_angle, line_angle, 0.0);
  std::string why;
  const Vec2 n(-std::sin(line_angle), std::cos(line_angle));
  const auto support = translating_support(c.bodies[1], n, &why);
  ASSERT_TRUE(support.has_value()) << why;
  // the face at 0.1 m from the centre, the top face 0.2 m above it (a few
  // roundings of a rotated coordinate: 1e-15 m)
  EXPECT_NEAR(support->support_m, 0.1, 1e-15);
  EXPECT_NEAR(support->clearance_m, 0.2, 1e-15);
  EXPECT_EQ(support->face_vertices, 2);
  BodyOnLine d(c, 1, 0, 0);
  d.extend_to(c.duration_s);
  testing::DiskLineProblem p;
  p.mass_kg = 1.5;
  p.radius_m = 0.1;
  p.line_normal = n;
  p.position0_m = c.bodies[1].position_m;
  testing::DiskLineIntegrator ref(p, 2e-6);
  std::vector<BodyState> states;
  std::vector<ContactSample> contacts;
  int contact_samples = 0;
  for (int k = 0; k <= 240; ++k) {
    const double t = 0.005 * k;
    ref.advance_to(t);
    d.body_states(t, states);
    // as for the disk above: 1e-9 relative to the motion's scales
    EXPECT_LE((states[1].position_m - ref.position()).norm(), 1e-9) << "t=" << t;
    EXPECT_LE((states[1].velocity_mps - ref.velocity()).norm(), 1e-9) << "t=" << t;
    EXPECT_EQ(states[1].angle_rad, line_angle);
    EXPECT_EQ(states[1].angular_velocity_radps, 0.0);
    d.contacts(t, contacts);
    if (ref.penetration() > 1e-9) {
      ASSERT_EQ(contacts.size(), 1u);
      ++contact_samples;
      // the face's middle: the centre minus the support, and its projection
      const Vec2 middle = ref.position() - 0.1 * n;
      EXPECT_LE((contacts[0].point_m - (middle + 0.5 * ref.penetration() * n)).norm(), 1e-9);
    }
  }
  EXPECT_GT(contact_samples, 3);
  EXPECT_EQ(d.mapping().at("shape"), "polygon");
}

// Where the closed form does not hold, it says why: a tilted square lands on
// a corner beside its centre; a spinning square's lowest point moves; an L
// on its long face has the face's middle beside its centre of mass.
TEST(BodyOnLine, RefusesBodiesThatWouldTurn) {
  std::string why;
  const Vec2 up(0, 1);
  EXPECT_FALSE(translating_support(square_case(0.1, 0.0, 0.0).bodies[1], up, &why).has_value());
  EXPECT_NE(why.find("beside its centre of mass"), std::string::npos) << why;
  EXPECT_FALSE(translating_support(square_case(0.0, 0.0, 2.0).bodies[1], up, &why).has_value());
  EXPECT_NE(why.find("spins"), std::string::npos) << why;
  Body l;
  l.name = "l";
  // the L [0,3] x [0,1] u [0,1] x [0,3] about its centroid (7/6, 7/6)
  const Vec2 g(7.0 / 6.0, 7.0 / 6.0);
  l.shape = Polygon{{Vec2(0, 0) - g, Vec2(3, 0) - g, Vec2(3, 1) - g, Vec2(1, 1) - g,
                     Vec2(1, 3) - g, Vec2(0, 3) - g}};
  EXPECT_FALSE(translating_support(l, up, &why).has_value());
  // a diamond on its tip: one lowest vertex straight below the centre
  Body diamond;
  diamond.name = "diamond";
  diamond.shape = Polygon{{Vec2(0, -1), Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0)}};
  const auto tip = translating_support(diamond, up, &why);
  ASSERT_TRUE(tip.has_value()) << why;
  EXPECT_EQ(tip->face_vertices, 1);
}

// Issue 49: a 0.1 x 0.3 m block standing on its short face on an incline
// holds its face while tan(incline) <= w / h (the moments about its centre
// of mass: friction m g sin a, 0.15 m below it, against the normal force's
// offset, at most the face's half-width 0.05 m). The premise is checked
// against that closed-form limit, on both sides of it: on 18.43 deg
// (tan = 1/3.03 < 1/3) it holds, on 22 deg (tan 0.404 > 1/3, mu 0.8 holds
// it from sliding) it tips and the closed form is refused, saying so. A
// thrown block slides with f = mu N: it tips where mu > w / h.
TEST(BodyOnLine, ATallBlockThatWouldTipIsRefused) {
  Body block;
  block.name = "block";
  block.mass_kg = 1.0;
  block.shape = Polygon{{Vec2(-0.05, -0.15), Vec2(0.05, -0.15), Vec2(0.05, 0.15), Vec2(-0.05, 0.15)}};
  ContactPair pair;
  pair.friction = 0.8;
  const auto judge = [&](double incline_rad, const Vec2& velocity) {
    Case c;
    c.gravity_mps2 = Vec2(0.0, -9.8066);
    const Vec2 n(-std::sin(incline_rad), std::cos(incline_rad));
    Body b = block;
    b.angle_rad = incline_rad;
    b.velocity_mps = velocity;
    std::string why;
    const auto support = translating_support(b, n, &why);
    EXPECT_TRUE(support.has_value()) << why;
    return support ? tipping_reason(c, b, pair, n, *support) : std::string("no support");
  };
  const double holds = std::atan(1.0 / 3.03);
  EXPECT_EQ(judge(holds, Vec2::Zero()), "");
  const std::string tips = judge(22.0 * std::numbers::pi / 180.0, Vec2::Zero());
  EXPECT_NE(tips.find("would tip"), std::string::npos) << tips;
  EXPECT_NE(tips.find("it holds"), std::string::npos) << tips;
  // thrown along level ground: f/N = mu = 0.8 > 1/3 tips it; mu = 0.3 not
  const Vec2 thrown(1.0, 0.0);
  EXPECT_NE(judge(0.0, thrown).find("mu: it slides"), std::string::npos);
  pair.friction = 0.3;
  EXPECT_EQ(judge(0.0, thrown), "");
  // frictionless: nothing turns it
  pair.friction = 0.0;
  EXPECT_EQ(judge(22.0 * std::numbers::pi / 180.0, Vec2::Zero()), "");
}

// A block held by friction rests tilted in its compliant static pose
// (scripts/block_cases.py): the closed form takes it as its rigid limit, a
// face, while its ends differ in height by at most the static penetration
// m g_n / K (static_level_m); without friction nothing tilts a face, and a
// square tilted by as little is a corner beside its centre.
TEST(BodyOnLine, AFrictionHeldFaceInItsStaticPoseIsAFace) {
  const Vec2 up(0, 1);
  Case c = square_case(0.0, 0.0, 0.0);
  c.contacts[0].friction = 0.5;
  const double level = static_level_m(c, 1, 0, 0);
  const auto& kv = std::get<KelvinVoigt>(c.contacts[0].law);
  // m g / K on level ground, one rounding
  EXPECT_NEAR(level, c.bodies[1].mass_kg * 9.8066 / kv.stiffness_n_per_m, 1e-15 * level);
  // ends 0.9 and 1.1 of the level apart (the 0.2 m face turned by asin(d / 0.2))
  for (const double f : {0.9, 1.1}) {
    Body tilted = c.bodies[1];
    tilted.angle_rad = std::asin(f * level / 0.2);
    std::string why;
    EXPECT_EQ(translating_support(tilted, up, &why, level).has_value(), f < 1.0) << f << why;
    EXPECT_FALSE(translating_support(tilted, up, &why).has_value());
  }
  c.contacts[0].friction = 0.0;
  EXPECT_EQ(static_level_m(c, 1, 0, 0), 0.0);
}

// A penetration deeper than the next vertex level is not this closed form:
// a flat triangle's apex 1 cm above its base, dropped hard
TEST(BodyOnLine, StopsWhereAnotherVertexWouldTouch) {
  Case c = square_case(0.0, 0.0, 0.0);
  // base (-0.1, -0.004)..(0.1, -0.004), apex (0, 0.008): centroid at the origin
  c.bodies[1].shape = Polygon{{Vec2(-0.1, -0.004), Vec2(0.1, -0.004), Vec2(0.0, 0.008)}};
  c.bodies[1].velocity_mps = Vec2(0, -20.0);  // ~0.2 m into a 1e4 N/m spring
  std::string why;
  ASSERT_TRUE(translating_support(c.bodies[1], Vec2(0, 1), &why).has_value()) << why;
  BodyOnLine d(c, 1, 0, 0);
  EXPECT_THROW(d.extend_to(c.duration_s), EngineError);
}

}  // namespace
}  // namespace pb::internal
