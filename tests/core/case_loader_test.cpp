// Tests for core/src/case_loader.cpp
#include "planarbench/case_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "planarbench/errors.hpp"

namespace pb {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

const fs::path kCasesDir = PB_CASES_DIR;
const fs::path kDataDir = fs::path(PB_SOURCE_DIR) / "tests" / "data" / "cases";

// ---- helpers -------------------------------------------------------------------

// unit outward normal of a half-plane body: body +y turned by the body angle
Vec2 halfplane_normal(const Body& ground) {
  return Vec2(-std::sin(ground.angle_rad), std::cos(ground.angle_rad));
}

// distance from a disk's surface to a half-plane's surface line (> 0: apart)
double disk_line_gap(const Body& ground, const Body& disk) {
  const double r = std::get<Circle>(disk.shape).radius_m;
  return halfplane_normal(ground).dot(disk.position_m - ground.position_m) - r;
}

// A small valid case, one field per line, so that each test below changes
// one line and knows the line number of the error:
const std::string kBase =
    "[case]\n"                                         // 1
    "description = \"test\"\n"                         // 2
    "duration = 1.0\n"                                 // 3
    "\n"                                               // 4
    "[[bodies]]\n"                                     // 5
    "name = \"ground\"\n"                              // 6
    "fixed = true\n"                                   // 7
    "shape = { type = \"halfplane\" }\n"               // 8
    "position = [0.0, 0.0]\n"                          // 9
    "\n"                                               // 10
    "[[bodies]]\n"                                     // 11
    "name = \"ball\"\n"                                // 12
    "shape = { type = \"circle\", radius = 0.5 }\n"    // 13
    "mass = 1.0\n"                                     // 14
    "position = [0.0, 1.0]\n"                          // 15
    "\n"                                               // 16
    "[[contacts]]\n"                                   // 17
    "name = \"c\"\n"                                   // 18
    "bodies = [\"ground\", \"ball\"]\n"                // 19
    "law = \"kelvin_voigt\"\n"                         // 20
    "stiffness = 1e4\n"                                // 21
    "damping = 10.0\n";                                // 22

// kBase with the first occurrence of `from` replaced by `to`
std::string with(const std::string& from, const std::string& to, std::string text = kBase) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test text lacks: " + from);
  return text.replace(at, from.size(), to);
}

Case parse(const std::string& text, const SettingsOverrides& o = {}) {
  return parse_case(text, "t.toml", "t", o);
}

// The error parse_case throws for `text`; fails the test if none.
InputError error_of(const std::string& text, const SettingsOverrides& o = {}) {
  try {
    (void)parse(text, o);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return InputError("(no error)");
}

// Checks file, line and field exactly and that the message contains `what`.
#define EXPECT_INPUT_ERROR(err, file_, line_, field_, fragment_)                        \
  do {                                                                                 \
    const InputError& e_ = (err);                                                      \
    const std::string message_ = e_.what();                                            \
    EXPECT_EQ(e_.file(), file_) << message_;                                           \
    EXPECT_EQ(e_.line(), line_) << message_;                                           \
    EXPECT_EQ(e_.field(), field_) << message_;                                         \
    EXPECT_NE(message_.find(fragment_), std::string::npos) << message_;                \
  } while (0)

SettingsOverrides overrides(std::initializer_list<std::pair<std::string, std::string>> kv) {
  SettingsOverrides o;
  for (const auto& [k, v] : kv) o.set(k, v, SettingSource{"--set", 0});
  return o;
}

// ---- the five case files against SPEC §2 ---------------------------------------------

// falling_ball: a disk R = 0.5 m at (2, 2) above the line through the origin
// declining toward +x at 30 deg. The centre is 2 sin30 + 2 cos30 from the
// line (normal (sin30, cos30)), so the gap is 2 sin30 + 2 cos30 - 0.5.
TEST(CaseFiles, FallingBallMatchesSpec) {
  const Case c = load_case(kCasesDir / "falling_ball.toml");
  EXPECT_EQ(c.name, "falling_ball");
  EXPECT_EQ(c.truth, TruthKind::analytic);
  EXPECT_EQ(c.duration_s, 2.5);
  EXPECT_EQ(c.output_interval_s, 1e-4);
  EXPECT_EQ(c.output_samples(), 25001);
  EXPECT_EQ(c.gravity_mps2, Vec2(0.0, -9.8066));
  EXPECT_FALSE(c.assumptions.empty());
  ASSERT_EQ(c.bodies.size(), 2u);
  const Body& ground = c.bodies[0];
  const Body& ball = c.bodies[1];
  EXPECT_TRUE(ground.fixed);
  ASSERT_TRUE(std::holds_alternative<HalfPlane>(ground.shape));
  // the line declines toward +x: its direction (cos, sin) of the angle has y < 0
  EXPECT_NEAR(ground.angle_rad, -kPi / 6.0, 1e-15);  // deg -> rad, one rounding
  EXPECT_FALSE(ball.fixed);
  EXPECT_EQ(std::get<Circle>(ball.shape).radius_m, 0.5);
  EXPECT_EQ(ball.outline_points, 180);
  EXPECT_EQ(ball.mass_kg, 1.0);
  EXPECT_DOUBLE_EQ(ball.inertia_kgm2, 0.5 * 1.0 * 0.25);  // 1/2 m R^2
  EXPECT_EQ(ball.position_m, Vec2(2.0, 2.0));
  EXPECT_EQ(ball.velocity_mps, Vec2::Zero());
  // gap to first contact; rounding of sin/cos of the stored angle (~1e-16 each)
  // summed over O(2 m) terms: 1e-14 m
  const double gap = 2.0 * std::sin(kPi / 6) + 2.0 * std::cos(kPi / 6) - 0.5;
  EXPECT_NEAR(disk_line_gap(ground, ball), gap, 1e-14);
  // the surface segment covers the slide: at t = 2.5 s the ball is
  // s0 + g sin30 t^2 / 2 down the line (s0 = centre . direction at t = 0)
  const Vec2 along(std::cos(ground.angle_rad), std::sin(ground.angle_rad));
  const double s_end = ball.position_m.dot(along) + 0.5 * 9.8066 * 0.5 * 2.5 * 2.5;
  EXPECT_GT(std::get<HalfPlane>(ground.shape).extent_m / 2.0, s_end + 1.0);

  ASSERT_EQ(c.contacts.size(), 1u);
  const ContactPair& p = c.contacts[0];
  EXPECT_EQ(p.body_a, 0);
  EXPECT_EQ(p.body_b, 1);
  EXPECT_EQ(p.threshold_m, 1e-10);
  const auto& kv = std::get<KelvinVoigt>(p.law);
  EXPECT_EQ(kv.stiffness_n_per_m, 1e4);
  EXPECT_EQ(kv.damping_ns_per_m, 10.0);
  EXPECT_EQ(kv.damping_depth_m, 0.0);
}

// sliding: a disk R = 0.25 m centred at (R sin45, R cos45) on the line
// declining toward +x at 45 deg: the centre is R along the unit normal
// (sin45, cos45), so the gap is exactly zero (to rounding).
TEST(CaseFiles, SlidingStartsTouchingTheLine) {
  const Case c = load_case(kCasesDir / "sliding.toml");
  EXPECT_EQ(c.truth, TruthKind::analytic);
  EXPECT_EQ(c.duration_s, 1.0);
  const Body& ground = c.bodies[0];
  const Body& ball = c.bodies[1];
  EXPECT_NEAR(ground.angle_rad, -kPi / 4.0, 1e-15);  // deg -> rad, one rounding
  EXPECT_EQ(std::get<Circle>(ball.shape).radius_m, 0.25);
  EXPECT_DOUBLE_EQ(ball.inertia_kgm2, 0.5 * 0.0625);
  // zero penetration to a few ulps of 0.25 m
  EXPECT_NEAR(disk_line_gap(ground, ball), 0.0, 1e-15);
  const auto& kv = std::get<KelvinVoigt>(c.contacts[0].law);
  EXPECT_EQ(kv.stiffness_n_per_m, 1e4);
  EXPECT_EQ(kv.damping_ns_per_m, 10.0);
  EXPECT_EQ(kv.damping_depth_m, 0.0);
}

// dual_pendulum: the ellipse (a = 0.7071, b = 0.25) at 45 deg with centre
// a (-cos45, -sin45) has its tip at the pivot (0, 0); the disk R = 0.5 hangs at
// (0.75, -0.7071) below its pivot (0.75, 0). K from eq. 3 with square root.
TEST(CaseFiles, DualPendulumMatchesSpec) {
  const Case c = load_case(kCasesDir / "dual_pendulum.toml");
  EXPECT_EQ(c.truth, TruthKind::analytic_until_first_contact);
  EXPECT_EQ(c.duration_s, 2.0);
  ASSERT_EQ(c.bodies.size(), 2u);
  const Body& ellipse = c.bodies[static_cast<std::size_t>(c.body_index("ellipse"))];
  const Body& disk = c.bodies[static_cast<std::size_t>(c.body_index("disk"))];
  const auto& e = std::get<Ellipse>(ellipse.shape);
  EXPECT_EQ(e.semi_axis_a_m, 0.7071);
  EXPECT_EQ(e.semi_axis_b_m, 0.25);
  EXPECT_DOUBLE_EQ(ellipse.inertia_kgm2, (0.7071 * 0.7071 + 0.25 * 0.25) / 4.0);  // m(a^2+b^2)/4
  EXPECT_DOUBLE_EQ(disk.inertia_kgm2, 0.125);                                      // m R^2 / 2
  // tip = centre + a (cos, sin) of the angle; 0.7071 rounds sqrt(2)/2 by
  // 6.8e-6, which moves the tip by 4.8e-6 m
  const Vec2 tip = ellipse.position_m +
                   e.semi_axis_a_m * Vec2(std::cos(ellipse.angle_rad), std::sin(ellipse.angle_rad));
  EXPECT_NEAR(tip.x(), 0.0, 1e-15);  // exact to the case file's 16 digits
  EXPECT_NEAR(tip.y(), 0.0, 1e-15);
  // hanging vertically, the ellipse's side x = b meets the disk's side x = 0.75 - R
  EXPECT_NEAR(disk.position_m.x() - std::get<Circle>(disk.shape).radius_m, e.semi_axis_b_m, 1e-15);

  ASSERT_EQ(c.joints.size(), 2u);
  EXPECT_EQ(c.joints[0].body, c.body_index("ellipse"));
  EXPECT_EQ(c.joints[0].anchor_world_m, Vec2(0.0, 0.0));
  // anchor in the ellipse frame: its tip, a = 0.7071 m along the major axis
  // (the case puts the centre at a (-cos45, -sin45) to 16 digits)
  // world -> body frame rotation by 45 deg: a few ulps of 0.7 m
  EXPECT_NEAR(c.joints[0].anchor_local_m.x(), 0.7071, 1e-15);
  EXPECT_NEAR(c.joints[0].anchor_local_m.y(), 0.0, 1e-15);
  EXPECT_EQ(c.joints[1].body, c.body_index("disk"));
  EXPECT_EQ(c.joints[1].anchor_world_m, Vec2(0.75, 0.0));
  // the disk is not rotated: exact up to one subtraction
  EXPECT_NEAR(c.joints[1].anchor_local_m.x(), 0.0, 1e-15);
  EXPECT_NEAR(c.joints[1].anchor_local_m.y(), 0.7071, 1e-15);

  ASSERT_EQ(c.contacts.size(), 1u);
  const auto& ln = std::get<LankaraniNikravesh>(c.contacts[0].law);
  EXPECT_EQ(ln.restitution, 0.7);
  EXPECT_EQ(ln.exponent, 1.5);
  ASSERT_TRUE(ln.material.has_value());
  EXPECT_EQ(ln.material->young_modulus_i_pa, 210e9);
  EXPECT_EQ(ln.material->poisson_ratio_j, 0.33);
  EXPECT_EQ(ln.material->radius_i_m, 0.0085);
  // eqs. 3-4 written out here: h = (1 - nu^2)/(pi E), K = 4/(3 pi 2h) sqrt(R/2)
  const double h = (1.0 - 0.33 * 0.33) / (kPi * 210e9);
  const double k = 4.0 / (3.0 * kPi * 2.0 * h) * std::sqrt(0.0085 * 0.0085 / 0.017);
  EXPECT_NEAR(ln.stiffness / k, 1.0, 1e-12);  // same formula, different rounding
  // SPEC §2 prints K ~ 1.024e10: half a unit of the last digit, 0.0005e10
  EXPECT_NEAR(ln.stiffness, 1.024e10, 0.0005e10);
}

// The paper-fidelity variants differ from the canonical cases only in the
// damping ramp depth (Table 1/3 "Depth 0.1 m"); having no closed form, their truth is
// the independent truth (truth = converged, issue 31).
TEST(CaseFiles, PaperVariantsAddOnlyTheDampingRamp) {
  for (const char* name : {"falling_ball", "sliding"}) {
    SCOPED_TRACE(name);
    const Case canonical = load_case(kCasesDir / (std::string(name) + ".toml"));
    const Case paper = load_case(kCasesDir / (std::string(name) + "_paper.toml"));
    EXPECT_EQ(paper.truth, TruthKind::converged);
    EXPECT_EQ(paper.duration_s, canonical.duration_s);
    EXPECT_EQ(paper.output_interval_s, canonical.output_interval_s);
    ASSERT_EQ(paper.bodies.size(), canonical.bodies.size());
    for (std::size_t i = 0; i < paper.bodies.size(); ++i) {
      EXPECT_EQ(paper.bodies[i].position_m, canonical.bodies[i].position_m);
      EXPECT_EQ(paper.bodies[i].angle_rad, canonical.bodies[i].angle_rad);
      EXPECT_EQ(paper.bodies[i].mass_kg, canonical.bodies[i].mass_kg);
      EXPECT_EQ(paper.bodies[i].inertia_kgm2, canonical.bodies[i].inertia_kgm2);
      EXPECT_EQ(paper.bodies[i].shape.index(), canonical.bodies[i].shape.index());
    }
    const auto& kv_p = std::get<KelvinVoigt>(paper.contacts[0].law);
    const auto& kv_c = std::get<KelvinVoigt>(canonical.contacts[0].law);
    EXPECT_EQ(kv_p.damping_depth_m, 0.1);
    EXPECT_EQ(kv_p.stiffness_n_per_m, kv_c.stiffness_n_per_m);
    EXPECT_EQ(kv_p.damping_ns_per_m, kv_c.damping_ns_per_m);
  }
}

TEST(CaseFiles, SourceTextIsKeptVerbatim) {
  const Case c = load_case(kCasesDir / "sliding.toml");
  EXPECT_EQ(c.source_path, (kCasesDir / "sliding.toml").string());
  EXPECT_NE(c.source_text.find("# sliding: paper §3.3"), std::string::npos);
}

// ---- resolve_cases ------------------------------------------------------------------

TEST(ResolveCases, AllGivesEveryCaseFileSorted) {
  const auto paths = resolve_cases("all", kCasesDir);
  std::vector<std::string> names;
  for (const auto& p : paths) names.push_back(p.stem().string());
  EXPECT_EQ(names, (std::vector<std::string>{
                       "block_hold", "block_slide", "block_stop", "concave_arch", "concave_corner",
                       "concave_seam_face", "disk_backspin",
                       "disk_oblique_roll", "disk_oblique_slide", "disk_roll", "disk_slip",
                       "disk_throw", "dual_pendulum", "ellipse_incline", "falling_ball",
                       "falling_ball_paper", "head_on", "incline_launch", "pendulum_wall",
                       "sliding", "sliding_friction", "sliding_paper", "square_hold",
                       "square_landing", "square_slide", "square_stop"}));
}

// tests/data/cases/dir holds two cases and one TOML file without [case]
TEST(ResolveCases, AllSkipsTomlFilesWithoutACaseTable) {
  const auto paths = resolve_cases("all", kDataDir / "dir");
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0].filename(), "alpha.toml");
  EXPECT_EQ(paths[1].filename(), "beta.toml");
}

TEST(ResolveCases, NameAndPath) {
  EXPECT_EQ(resolve_cases("sliding", kCasesDir),
            std::vector<fs::path>{kCasesDir / "sliding.toml"});
  const fs::path file = kDataDir / "dir" / "alpha.toml";
  EXPECT_EQ(resolve_cases(file.string(), kCasesDir), std::vector<fs::path>{file});
}

TEST(ResolveCases, UnknownNameListsTheCases) {
  try {
    (void)resolve_cases("slidng", kCasesDir);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(e.field(), "slidng");
    EXPECT_NE(msg.find("block_hold, block_slide, block_stop, concave_arch, concave_corner, "
                       "concave_seam_face, disk_backspin, "
                       "disk_oblique_roll, disk_oblique_slide, disk_roll, disk_slip, disk_throw, "
                       "dual_pendulum, ellipse_incline, falling_ball, falling_ball_paper, "
                       "head_on, incline_launch, pendulum_wall, sliding, sliding_friction, "
                       "sliding_paper, square_hold, square_landing, square_slide, square_stop"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("did you mean 'sliding'?"), std::string::npos) << msg;
  }
}

// ---- a valid case and what the loader derives ---------------------------------------------

TEST(ParseCase, BaseCaseAndDefaults) {
  const Case c = parse(kBase);
  EXPECT_EQ(c.name, "t");
  EXPECT_EQ(c.source_path, "t.toml");
  EXPECT_EQ(c.source_text, kBase);
  EXPECT_EQ(c.output_interval_s, 1e-4);
  EXPECT_EQ(c.gravity_mps2, Vec2(0.0, -9.8066));
  EXPECT_EQ(c.truth, TruthKind::none);
  EXPECT_EQ(std::get<HalfPlane>(c.bodies[0].shape).extent_m, 20.0);
  EXPECT_EQ(c.bodies[0].mass_kg, 0.0);
  EXPECT_EQ(c.bodies[1].outline_points, 180);
  EXPECT_EQ(c.bodies[1].angle_rad, 0.0);
  EXPECT_EQ(c.contacts[0].threshold_m, 1e-10);
  // absent friction is frictionless (SPEC §7)
  EXPECT_EQ(c.contacts[0].friction, 0.0);
  EXPECT_FALSE(c.contacts[0].has_friction());
  EXPECT_EQ(c.first_pair_with_friction(), nullptr);
}

// friction on a pair, in every law; and --set contact.friction on every pair
TEST(ParseCase, FrictionIsReadForEveryLaw) {
  const Case kv = parse(with("damping = 10.0\n", "damping = 10.0\nfriction = 0.5\n"));
  EXPECT_EQ(kv.contacts[0].friction, 0.5);
  EXPECT_EQ(kv.first_pair_with_friction(), &kv.contacts[0]);
  const Case hz = parse(with("law = \"kelvin_voigt\"\nstiffness = 1e4\ndamping = 10.0\n",
                             "law = \"hertz\"\nstiffness = 1e9\nfriction = 0.25\n"));
  EXPECT_EQ(hz.contacts[0].friction, 0.25);
  SettingsOverrides o;
  o.set("contact.friction", "0.125", SettingSource{"--set", 0});
  EXPECT_EQ(parse(kBase, o).contacts[0].friction, 0.125);
}

// density is areal (kg/m^2): m = rho pi R^2, I = m R^2 / 2 for the exact disk
TEST(ParseCase, DensityGivesMassFromTheExactArea) {
  const Case c = parse(with("mass = 1.0", "density = 2.0"));
  EXPECT_DOUBLE_EQ(c.bodies[1].mass_kg, 2.0 * kPi * 0.25);
  EXPECT_DOUBLE_EQ(c.bodies[1].inertia_kgm2, c.bodies[1].mass_kg * 0.25 / 2.0);
}

// inertia = "outline" uses the N-gon inscribed in the disk: J/A of a regular
// N-gon with circumradius R is R^2 (2 + cos(2 pi/N)) / 6 (from the polygon
// moment formula, see outline_test.cpp)
TEST(ParseCase, OutlineInertiaUsesTheOutlinePolygon) {
  const Case c = parse(with("mass = 1.0", "mass = 1.0\ninertia = \"outline\"\noutline_points = 12"));
  const double expected = 0.25 * (2.0 + std::cos(2.0 * kPi / 12.0)) / 6.0;
  EXPECT_NEAR(c.bodies[1].inertia_kgm2, expected, 1e-15);  // 12 terms, rounding ~1e-16
  const Case n = parse(with("mass = 1.0", "mass = 1.0\ninertia = 0.3"));
  EXPECT_EQ(n.bodies[1].inertia_kgm2, 0.3);
}

// a square of side 2 centred on the origin: area 4, J = b h (b^2 + h^2)/12 = 8/3
TEST(ParseCase, PolygonBodyTakesItsOwnPointsAndMoments) {
  const Case c = parse(with("shape = { type = \"circle\", radius = 0.5 }\nmass = 1.0",
                            "shape = { type = \"polygon\", points = [[-1, -1], [1, -1], [1, 1], "
                            "[-1, 1]] }\ndensity = 0.5"));
  const Body& b = c.bodies[1];
  EXPECT_EQ(b.outline_points, 4);
  EXPECT_EQ(std::get<Polygon>(b.shape).points_m.size(), 4u);
  EXPECT_EQ(b.mass_kg, 2.0);  // 0.5 kg/m^2 x 4 m^2
  EXPECT_NEAR(b.inertia_kgm2, 0.5 * 8.0 / 3.0, 1e-15);
}

// the anchor in the body frame is R(theta)^T (anchor - position) at t = 0
TEST(ParseCase, JointAnchorIsExpressedInTheBodyFrame) {
  const Case c = parse(with("position = [0.0, 1.0]", "position = [0.0, 1.0]\nangle_deg = 90.0") +
                       "\n[[joints]]\nname = \"pivot\"\ntype = \"revolute\"\nbody = \"ball\"\n"
                       "anchor = [0.0, 2.0]\n");
  ASSERT_EQ(c.joints.size(), 1u);
  // the world offset (0, 1) seen from a frame turned by 90 deg is (1, 0)
  EXPECT_NEAR(c.joints[0].anchor_local_m.x(), 1.0, 1e-15);
  EXPECT_NEAR(c.joints[0].anchor_local_m.y(), 0.0, 1e-15);
}

TEST(ParseCase, SettingsAreKeptAsKeyAndText) {
  const Case c = parse(kBase +
                       "\n[settings]\n\"reference.geometry\" = \"outline\"\ndt = 1e-4\n"
                       "\"mujoco.solimp\" = [0.9, 0.95, 0.001, 0.5, 2]\n");
  using KV = std::pair<std::string, std::string>;
  // toml++ keeps table keys sorted
  EXPECT_EQ(c.settings, (std::vector<KV>{{"dt", "0.0001"},
                                         {"mujoco.solimp", "[0.9, 0.95, 0.001, 0.5, 2]"},
                                         {"reference.geometry", "outline"}}));
}

TEST(ParseCase, HertzMaterialGivesStiffnessByEquation3) {
  const Case c = parse(with("law = \"kelvin_voigt\"\nstiffness = 1e4\ndamping = 10.0",
                            "law = \"hertz\"\nyoung_modulus = [1e9, 2e9]\npoisson_ratio = [0.3, 0.2]\n"
                            "radius = [0.01, 0.02]\nexponent = 1.5"));
  const auto& hz = std::get<Hertz>(c.contacts[0].law);
  const double hi = (1 - 0.09) / (kPi * 1e9);
  const double hj = (1 - 0.04) / (kPi * 2e9);
  const double k = 4.0 / (3.0 * kPi * (hi + hj)) * std::sqrt(0.01 * 0.02 / 0.03);
  EXPECT_NEAR(hz.stiffness / k, 1.0, 1e-12);  // same formula, different rounding
}

// ---- one test per kind of bad input ------------------------------------------------------

TEST(BadInput, TomlSyntaxErrorGivesItsLine) {
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = ")), "t.toml", 3, "",
                     "t.toml:3:");
}

TEST(BadInput, UnknownKeyWithDidYouMean) {
  EXPECT_INPUT_ERROR(error_of(with("radius = 0.5", "radus = 0.5")), "t.toml", 13,
                     "bodies[1].shape.radus", "unknown key (did you mean 'radius'?)");
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0", "mas = 1.0")), "t.toml", 14, "bodies[1].mas",
                     "did you mean 'mass'?");
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1.0\ndurration = 2")), "t.toml",
                     4, "case.durration", "did you mean 'duration'?");
  // far from every key: no guess, but the list of allowed keys
  EXPECT_INPUT_ERROR(error_of(kBase + "[extras]\nx = 1\n"), "t.toml", 23, "extras",
                     "unknown key; allowed: case, bodies, generate, joints, contacts, contact_groups, settings");
}

TEST(BadInput, KeyOfAnotherLaw) {
  EXPECT_INPUT_ERROR(error_of(with("damping = 10.0", "damping = 10.0\nrestitution = 0.5")),
                     "t.toml", 23, "contacts[0].restitution", "not a field of a kelvin_voigt contact");
}

TEST(BadInput, WrongType) {
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0", "mass = \"heavy\"")), "t.toml", 14,
                     "bodies[1].mass", "must be a finite number > 0 (got \"heavy\"), in kg");
  EXPECT_INPUT_ERROR(error_of(with("fixed = true", "fixed = 1")), "t.toml", 7, "bodies[0].fixed",
                     "must be true or false (got 1)");
  EXPECT_INPUT_ERROR(error_of(with("position = [0.0, 1.0]", "position = [0.0, 1.0, 2.0]")),
                     "t.toml", 15, "bodies[1].position", "(got an array of 3)");
  EXPECT_INPUT_ERROR(error_of(with("name = \"ball\"", "name = \"2ball\"")), "t.toml", 12,
                     "bodies[1].name", "a name of letters, digits and '_'");
  EXPECT_INPUT_ERROR(error_of("joints = 3\n" + kBase), "t.toml", 1, "joints",
                     "must be an array of tables ([[joints]]) (got 3)");
}

TEST(BadInput, MissingRequiredFieldPointsAtItsTable) {
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0\n", "")), "t.toml", 1, "case.duration",
                     "missing; give a finite number in (0, 10000], in s");
  EXPECT_INPUT_ERROR(error_of(with("[case]\ndescription = \"test\"\nduration = 1.0\n", "")),
                     "t.toml", 1, "case", "missing; give a [case] table");
  EXPECT_INPUT_ERROR(error_of(with("damping = 10.0", "")), "t.toml", 17, "contacts[0].damping",
                     "missing");
}

TEST(BadInput, NotFinite) {
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0", "mass = nan")), "t.toml", 14, "bodies[1].mass",
                     "(got nan)");
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1.0\ngravity = [0.0, -inf]")),
                     "t.toml", 4, "case.gravity[1]", "must be a finite number (got -inf)");
}

TEST(BadInput, NonPositiveQuantities) {
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0", "mass = -1")), "t.toml", 14, "bodies[1].mass",
                     "t.toml:14: bodies[1].mass: must be a finite number > 0 (got -1), in kg");
  EXPECT_INPUT_ERROR(error_of(with("radius = 0.5", "radius = 0.0")), "t.toml", 13,
                     "bodies[1].shape.radius", "must be a finite number in [1e-09, 10000] (got 0)");
  EXPECT_INPUT_ERROR(
      error_of(with("type = \"circle\", radius = 0.5", "type = \"ellipse\", semi_axes = [1.0, -0.5]")),
      "t.toml", 13, "bodies[1].shape.semi_axes[1]", "(got -0.5)");
  EXPECT_INPUT_ERROR(error_of(with("stiffness = 1e4", "stiffness = 0")), "t.toml", 21,
                     "contacts[0].stiffness", "must be a finite number > 0 (got 0), in N/m");
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0", "mass = 1.0\ninertia = -2")), "t.toml", 15,
                     "bodies[1].inertia", "(got -2)");
}

TEST(BadInput, NegativeDampingAndDepth) {
  EXPECT_INPUT_ERROR(error_of(with("damping = 10.0", "damping = -1.0")), "t.toml", 22,
                     "contacts[0].damping", "must be a finite number >= 0 (got -1)");
  EXPECT_INPUT_ERROR(error_of(with("damping = 10.0", "damping = 10.0\ndamping_depth = -0.1")),
                     "t.toml", 23, "contacts[0].damping_depth", "(got -0.1)");
}

const std::string kLn = with("law = \"kelvin_voigt\"\nstiffness = 1e4\ndamping = 10.0",
                             "law = \"lankarani_nikravesh\"\nstiffness = 1e9\nrestitution = 0.7");

TEST(BadInput, RestitutionOutsideZeroOne) {
  EXPECT_NO_THROW((void)parse(with("restitution = 0.7", "restitution = 1.0", kLn)));
  EXPECT_INPUT_ERROR(error_of(with("restitution = 0.7", "restitution = 0.0", kLn)), "t.toml", 22,
                     "contacts[0].restitution", "must be a finite number in (0, 1] (got 0)");
  EXPECT_INPUT_ERROR(error_of(with("restitution = 0.7", "restitution = 1.2", kLn)), "t.toml", 22,
                     "contacts[0].restitution", "(got 1.2)");
  EXPECT_INPUT_ERROR(error_of(with("restitution = 0.7\n", "", kLn)), "t.toml", 17,
                     "contacts[0].restitution", "missing");
}

TEST(BadInput, HertzStiffnessXorMaterial) {
  EXPECT_INPUT_ERROR(
      error_of(with("stiffness = 1e9", "stiffness = 1e9\nyoung_modulus = [1e9, 1e9]", kLn)),
      "t.toml", 21, "contacts[0].stiffness", "not both");
  EXPECT_INPUT_ERROR(error_of(with("stiffness = 1e9", "young_modulus = [1e9, 1e9]", kLn)),
                     "t.toml", 17, "contacts[0].poisson_ratio", "missing");
  EXPECT_INPUT_ERROR(error_of(with("stiffness = 1e9",
                                   "young_modulus = [1e9, 1e9]\npoisson_ratio = [0.3, 0.5]\n"
                                   "radius = [0.01, 0.01]",
                                   kLn)),
                     "t.toml", 22, "contacts[0].poisson_ratio[1]",
                     "must be a finite number in (-1, 0.5) (got 0.5)");
  EXPECT_INPUT_ERROR(error_of(with("stiffness = 1e9", "stiffness = 1e9\nexponent = 3.5", kLn)),
                     "t.toml", 22, "contacts[0].exponent", "in (1, 3]");
}

TEST(BadInput, UnknownWordWithDidYouMean) {
  EXPECT_INPUT_ERROR(error_of(with("law = \"kelvin_voigt\"", "law = \"kelvin_voight\"")), "t.toml",
                     20, "contacts[0].law", "did you mean 'kelvin_voigt'?");
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1.0\ntruth = \"exact\"")),
                     "t.toml", 4, "case.truth",
                     "must be one of \"analytic\", \"analytic_until_first_contact\", \"converged\", \"none\"");
}

TEST(BadInput, DuplicateNames) {
  EXPECT_INPUT_ERROR(error_of(with("name = \"ball\"", "name = \"ground\"")), "t.toml", 12,
                     "bodies[1].name", "duplicate body name 'ground' (also bodies[0])");
  const std::string second = "\n[[contacts]]\nname = \"c\"\nbodies = [\"ground\", \"ball\"]\n"
                             "law = \"kelvin_voigt\"\nstiffness = 1\ndamping = 0\n";
  EXPECT_INPUT_ERROR(error_of(kBase + second), "t.toml", 25, "contacts[1].name",
                     "duplicate contact name 'c'");
}

TEST(BadInput, ContactBodies) {
  EXPECT_INPUT_ERROR(error_of(with("[\"ground\", \"ball\"]", "[\"ground\", \"bal\"]")), "t.toml", 19,
                     "contacts[0].bodies[1]",
                     "no body named 'bal' (did you mean 'ball'?); bodies: ground, ball");
  EXPECT_INPUT_ERROR(error_of(with("[\"ground\", \"ball\"]", "[\"ball\", \"ground\"]")), "t.toml", 19,
                     "contacts[0].bodies", "list the fixed body first");
  EXPECT_INPUT_ERROR(error_of(with("[\"ground\", \"ball\"]", "[\"ball\", \"ball\"]")), "t.toml", 19,
                     "contacts[0].bodies", "cannot touch itself");
  const std::string two_fixed = with("mass = 1.0\n", "", with("name = \"ball\"", "name = \"ball\"\nfixed = true"));
  EXPECT_INPUT_ERROR(error_of(two_fixed), "t.toml", 19, "contacts[0].bodies", "both fixed");
}

TEST(BadInput, MovingBodyWithoutMass) {
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0\n", "")), "t.toml", 11, "bodies[1].mass",
                     "missing; give mass (kg, > 0) or density (kg/m^2, > 0)");
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0", "mass = 1.0\ndensity = 3.0")), "t.toml", 15,
                     "bodies[1].density", "not both");
}

TEST(BadInput, FixedBodiesTakeNoMassAndHalfPlanesAreFixed) {
  EXPECT_INPUT_ERROR(error_of(with("fixed = true", "fixed = true\nmass = 1.0")), "t.toml", 8,
                     "bodies[0].mass", "a fixed body (fixed = true) never moves");
  EXPECT_INPUT_ERROR(error_of(with("fixed = true", "mass = 1.0")), "t.toml", 8, "bodies[0].shape",
                     "a halfplane has no finite area or mass: it must be fixed");
}

TEST(BadInput, AngleGivenTwice) {
  EXPECT_INPUT_ERROR(error_of(with("mass = 1.0", "mass = 1.0\nangle = 0.1\nangle_deg = 5")),
                     "t.toml", 16, "bodies[1].angle_deg", "give angle (rad) or angle_deg, not both");
}

TEST(BadInput, Joints) {
  const std::string joint = "\n[[joints]]\nname = \"j\"\ntype = \"revolute\"\nbody = \"ground\"\n"
                            "anchor = [0.0, 0.0]\n";
  EXPECT_INPUT_ERROR(error_of(kBase + joint), "t.toml", 27, "joints[0].body",
                     "body 'ground' is fixed");
  EXPECT_INPUT_ERROR(error_of(kBase + with("\"revolute\"", "\"prismatic\"", joint)), "t.toml", 26,
                     "joints[0].type", "must be one of \"revolute\"");
  EXPECT_INPUT_ERROR(error_of(kBase + with("\"ground\"", "\"nobody\"", joint)), "t.toml", 27,
                     "joints[0].body", "no body named 'nobody'");
}

// polygons: each element is [x, y]; the messages name the first problem
const std::string kPolygonLine = "shape = { type = \"circle\", radius = 0.5 }";
InputError polygon_error(const std::string& points) {
  return error_of(with(kPolygonLine, "shape = { type = \"polygon\", points = " + points + " }"));
}

TEST(BadInput, PolygonTooFewOrRepeatedPoints) {
  EXPECT_INPUT_ERROR(polygon_error("[[0, 0], [1, 0]]"), "t.toml", 13, "bodies[1].shape.points",
                     "must be an array of 3 to 10000 [x, y] points (got an array of 2)");
  EXPECT_INPUT_ERROR(polygon_error("[[-1, -1], [1, -1], [1, -1], [1, 1], [-1, 1]]"), "t.toml", 13,
                     "bodies[1].shape.points", "points 1 and 2 are the same point (1, -1)");
  EXPECT_INPUT_ERROR(polygon_error("[[-1, -1], [1, -1], [1, 1], [-1, 1], [-1, -1]]"), "t.toml", 13,
                     "bodies[1].shape.points", "the last point repeats the first");
}

TEST(BadInput, PolygonZeroAreaClockwiseSelfIntersecting) {
  EXPECT_INPUT_ERROR(polygon_error("[[0, 0], [1, 0], [2, 0]]"), "t.toml", 13,
                     "bodies[1].shape.points", "encloses zero area");
  EXPECT_INPUT_ERROR(polygon_error("[[-1, -1], [-1, 1], [1, 1], [1, -1]]"), "t.toml", 13,
                     "bodies[1].shape.points",
                     "points are clockwise; the format wants counter-clockwise: reverse them");
  // a figure eight with unequal lobes: area 1, edges 2-3 and 4-0 cross at (-0.5, 0)
  EXPECT_INPUT_ERROR(polygon_error("[[0, 0], [2, 0], [0, 1], [-1, -1], [-1, 0]]"), "t.toml", 13,
                     "bodies[1].shape.points", "intersect: the outline must be a simple polygon");
}

TEST(BadInput, PolygonCentroidNotAtTheOrigin) {
  EXPECT_INPUT_ERROR(polygon_error("[[0, 0], [1, 0], [1, 1], [0, 1]]"), "t.toml", 13,
                     "bodies[1].shape.points", "centroid is at (0.5, 0.5), not at the body origin");
  // 1e-12 off a size-2.8 square is within the 1e-9 x size tolerance
  EXPECT_NO_THROW((void)parse(with(kPolygonLine, "shape = { type = \"polygon\", points = [[-1, -1], "
                                                 "[1, -1], [1, 1.000000000002], [-1, 1]] }")));
}

TEST(BadInput, OutputIntervalAndAbsurdSizes) {
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1.0\noutput_interval = 2.0")),
                     "t.toml", 4, "case.output_interval", "must be <= duration = 1 s (got 2 s)");
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1e4\noutput_interval = 1e-4")),
                     "t.toml", 4, "case.output_interval", "gives 1e+08 output samples");
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1e9")), "t.toml", 3,
                     "case.duration", "in (0, 10000]");
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1.0\noutline_points = 1000000")),
                     "t.toml", 4, "case.outline_points", "must be an integer in [3, 100000]");
  EXPECT_INPUT_ERROR(error_of(with("radius = 0.5", "radius = 1e9")), "t.toml", 13,
                     "bodies[1].shape.radius", "(got 1000000000)");
  EXPECT_INPUT_ERROR(error_of(with("position = [0.0, 1.0]", "position = [0.0, 1e12]")), "t.toml",
                     15, "bodies[1].position[1]", "in [-1000000, 1000000]");
}

TEST(BadInput, SettingsTakeEngineKeysAndPlainValues) {
  EXPECT_INPUT_ERROR(error_of(kBase + "[settings]\nduration = 2.0\n"), "t.toml", 24,
                     "settings.duration", "a case key, not an engine setting");
  EXPECT_INPUT_ERROR(error_of(kBase + "[settings]\ndt = [{ a = 1 }]\n"), "t.toml", 24,
                     "settings.dt", "must be a number, string, boolean or array of them");
}

// files of tests/data/cases/bad: the error names the file path and its line
TEST(BadInput, FilesNameTheirPathAndLine) {
  const fs::path bad = kDataDir / "bad";
  const auto check = [&](const char* file, int line, const std::string& field, const std::string& what) {
    SCOPED_TRACE(file);
    try {
      (void)load_case(bad / file);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_INPUT_ERROR(e, (bad / file).string(), line, field, what);
    }
  };
  check("unterminated_array.toml", 6, "", "");
  check("duplicate_key.toml", 5, "", "redefine");
  check("clockwise_polygon.toml", 11, "bodies[0].shape.points", "points are clockwise");
  check("missing_case_table.toml", 1, "case", "missing; give a [case] table");
  check("no_such_file.toml", 0, "", "no such case file");
}

// ---- overrides (--set) ----------------------------------------------------------------------

TEST(IsCaseKey, CaseKeysAndEngineKeys) {
  for (const char* k : {"duration", "output_interval", "gravity", "outline_points", "truth",
                        "contact.stiffness", "contacts.c.damping", "bodies.ball.mass",
                        "bodies.ball.shape.radius"}) {
    EXPECT_TRUE(is_case_key(k)) << k;
  }
  for (const char* k : {"dt", "geometry", "mujoco.solimp", "reference.geometry", "contact",
                        "contact.", "contacts.c", "bodies.ball", "bodies..mass", "description"}) {
    EXPECT_FALSE(is_case_key(k)) << k;
  }
}

TEST(Overrides, ContactFieldAppliesToEveryContact) {
  const Case c = parse(kBase, overrides({{"contact.stiffness", "2e4"}}));
  EXPECT_EQ(std::get<KelvinVoigt>(c.contacts[0].law).stiffness_n_per_m, 2e4);
  EXPECT_EQ(c.source_text, kBase);  // the file's text stays verbatim
}

TEST(Overrides, CaseBodyAndNestedFields) {
  const Case c = parse(kBase, overrides({{"duration", "3"},
                                         {"truth", "analytic"},  // bare word: a string
                                         {"gravity", "[0, -10]"},
                                         {"bodies.ball.shape.radius", "0.25"},
                                         {"bodies.ball.velocity", "[1.5, 0]"},
                                         {"contacts.c.damping", "0"}}));
  EXPECT_EQ(c.duration_s, 3.0);
  EXPECT_EQ(c.truth, TruthKind::analytic);
  EXPECT_EQ(c.gravity_mps2, Vec2(0.0, -10.0));
  EXPECT_EQ(std::get<Circle>(c.bodies[1].shape).radius_m, 0.25);
  EXPECT_EQ(c.bodies[1].velocity_mps, Vec2(1.5, 0.0));
  EXPECT_EQ(std::get<KelvinVoigt>(c.contacts[0].law).damping_ns_per_m, 0.0);
  // the inertia follows the overridden radius: m R^2 / 2
  EXPECT_DOUBLE_EQ(c.bodies[1].inertia_kgm2, 0.5 * 0.0625);
}

TEST(Overrides, NamedContactWinsOverEveryContact) {
  const Case c = parse(kBase, overrides({{"contacts.c.stiffness", "3e4"}, {"contact.stiffness", "2e4"}}));
  EXPECT_EQ(std::get<KelvinVoigt>(c.contacts[0].law).stiffness_n_per_m, 3e4);
}

TEST(Overrides, AnOverrideReplacesTheFilesAlternative) {
  const Case c = parse(with("mass = 1.0", "density = 1.0"), overrides({{"bodies.ball.mass", "2"}}));
  EXPECT_EQ(c.bodies[1].mass_kg, 2.0);
  const Case d = parse(kLn, overrides({{"contact.young_modulus", "[1e9, 1e9]"},
                                       {"contact.poisson_ratio", "[0.3, 0.3]"},
                                       {"contact.radius", "[0.01, 0.01]"}}));
  EXPECT_TRUE(std::get<LankaraniNikravesh>(d.contacts[0].law).material.has_value());
}

TEST(Overrides, BadValueNamesTheOverride) {
  EXPECT_INPUT_ERROR(error_of(kBase, overrides({{"bodies.ball.mass", "-1"}})),
                     "--set bodies.ball.mass", 0, "bodies[1].mass",
                     "--set bodies.ball.mass: bodies[1].mass: must be a finite number > 0 (got -1)");
  EXPECT_INPUT_ERROR(error_of(kBase, overrides({{"duration", "abc"}})), "--set duration", 0,
                     "case.duration", "(got \"abc\")");
  EXPECT_INPUT_ERROR(error_of(kBase, overrides({{"bodies.ball.mas", "2"}})), "--set bodies.ball.mas",
                     0, "bodies[1].mas", "did you mean 'mass'?");
  // an override that leaves a file value inconsistent still names the file's line
  EXPECT_INPUT_ERROR(error_of(with("duration = 1.0", "duration = 1.0\noutput_interval = 0.5"),
                              overrides({{"duration", "0.1"}})),
                     "t.toml", 4, "case.output_interval", "must be <= duration = 0.1 s");
}

TEST(Overrides, UnknownNamesAreRejected) {
  EXPECT_INPUT_ERROR(error_of(kBase, overrides({{"bodies.bal.mass", "2"}})), "--set bodies.bal.mass",
                     0, "", "the case has no body named 'bal' (did you mean 'ball'?); bodies: ground, ball");
  EXPECT_INPUT_ERROR(error_of(kBase, overrides({{"contacts.d.stiffness", "2"}})),
                     "--set contacts.d.stiffness", 0, "", "no contact named 'd'");
  EXPECT_INPUT_ERROR(error_of(kBase, overrides({{"bodies.ball.mass.x", "2"}})),
                     "--set bodies.ball.mass.x", 0, "", "'mass' is 1, not a table");
}

TEST(Overrides, EngineKeysAreNotCaseOverrides) {
  EXPECT_INPUT_ERROR(error_of(kBase, overrides({{"dt", "1e-4"}})), "--set", 0, "dt",
                     "not a case key");
}

TEST(Overrides, ApplyToTheCaseFilesByLoadCase) {
  const Case c = load_case(kCasesDir / "dual_pendulum.toml",
                           overrides({{"outline_points", "360"}, {"contact.restitution", "0.9"}}));
  EXPECT_EQ(c.bodies[0].outline_points, 360);
  EXPECT_EQ(std::get<LankaraniNikravesh>(c.contacts[0].law).restitution, 0.9);
}

}  // namespace
}  // namespace pb
