// Tests for core/src/scene_loader.cpp: [[generate]] and [[contact_groups]]
// (SPEC §11). Positions are checked against the arithmetic of each layout,
// written out here; errors name the file, the line and the field.
#include "planarbench/case_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "planarbench/contact_pairs.hpp"
#include "planarbench/errors.hpp"

namespace pb {
namespace {

// 1e-12 m: the layouts add a few numbers of size <= 10 m, ~1e-15 relative each
constexpr double kTol_m = 1e-12;

const std::string kGround =
    "[case]\n"
    "description = \"scene\"\n"
    "duration = 1.0\n"
    "[[bodies]]\n"
    "name = \"ground\"\n"
    "fixed = true\n"
    "shape = { type = \"halfplane\" }\n"
    "position = [0.0, 0.0]\n";

const std::string kBox = "shape = { type = \"polygon\", points = [[-0.2, -0.05], [0.2, -0.05], "
                         "[0.2, 0.05], [-0.2, 0.05]] }\n";

std::string group(const std::string& bodies, double stiffness = 1e6) {
  return "[[contact_groups]]\nname = \"all\"\nbodies = [" + bodies +
         "]\nlaw = \"kelvin_voigt\"\nstiffness = " + std::to_string(stiffness) +
         "\ndamping = 10.0\n";
}

Case parse(const std::string& text) { return parse_case(text, "scene.toml", "scene"); }

std::string error_of(const std::string& text) {
  try {
    (void)parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Generate, StackTouchingStandsBoxOnBox) {
  const Case c = parse(kGround + "[[generate]]\nkind = \"stack\"\nname = \"box\"\ncount = 3\n" + kBox +
                       "mass = 1.0\non = \"ground\"\nat = 0.5\n" + group("\"ground\", \"box\""));
  ASSERT_EQ(c.bodies.size(), 4u);
  ASSERT_EQ(c.generated.size(), 1u);
  EXPECT_EQ(c.generated[0].first_body, 1);
  EXPECT_EQ(c.generated[0].count, 3);
  for (int k = 0; k < 3; ++k) {
    const Body& b = c.bodies[static_cast<std::size_t>(1 + k)];
    EXPECT_EQ(b.name, "box_" + std::to_string(k + 1));
    // centre heights h/2 + k h for h = 0.1 m, at x = 0.5 m along the surface
    EXPECT_NEAR(b.position_m.x(), 0.5, kTol_m);
    EXPECT_NEAR(b.position_m.y(), 0.05 + 0.1 * k, kTol_m);
  }
}

TEST(Generate, StackRestingSinksEachInterfaceByTheWeightAbove) {
  // K = 1e4 N/m: interface k from the bottom carries (3 - k) m g, pressed (3 - k) m g / K
  const Case c = parse(kGround + "[[generate]]\nkind = \"stack\"\nname = \"box\"\ncount = 3\n" + kBox +
                       "mass = 2.0\non = \"ground\"\nstart = \"resting\"\n" +
                       group("\"ground\", \"box\"", 1e4));
  const double w = 2.0 * 9.8066;  // N, one box's weight
  double y = 0.05 - 3.0 * w / 1e4;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(c.bodies[static_cast<std::size_t>(1 + k)].position_m.y(), y, kTol_m) << k;
    y += 0.1 - (2.0 - k) * w / 1e4;
  }
  EXPECT_EQ(c.generated[0].start, SceneStart::resting);
}

TEST(Generate, PyramidRowsSitOverTheGapsBelow) {
  const Case c = parse(kGround + "[[generate]]\nkind = \"pyramid\"\nname = \"brick\"\nrows = 3\n" +
                       kBox + "mass = 1.0\non = \"ground\"\n" + group("\"ground\", \"brick\""));
  ASSERT_EQ(c.bodies.size(), 1u + 6u);
  // bottom row x = -0.4, 0, 0.4; second -0.2, 0.2; top 0 (pitch 0.4 m, height 0.1 m)
  const double x[6] = {-0.4, 0.0, 0.4, -0.2, 0.2, 0.0};
  const double y[6] = {0.05, 0.05, 0.05, 0.15, 0.15, 0.25};
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(c.bodies[static_cast<std::size_t>(1 + k)].position_m.x(), x[k], kTol_m) << k;
    EXPECT_NEAR(c.bodies[static_cast<std::size_t>(1 + k)].position_m.y(), y[k], kTol_m) << k;
  }
}

TEST(Generate, RowSpacesSurfacesByTheGap) {
  const Case c = parse(
      "[case]\ndescription = \"row\"\nduration = 1.0\ngravity = [0.0, 0.0]\n"
      "[[generate]]\nkind = \"row\"\nname = \"disk\"\ncount = 3\n"
      "shape = { type = \"circle\", radius = 0.1 }\nmass = 1.0\nfirst = [1.0, 2.0]\n"
      "direction = [0.0, 2.0]\ngap = 0.05\nfirst_velocity = [0.0, 1.0]\n" +
      group("\"disk\""));
  for (int k = 0; k < 3; ++k) {
    const Body& b = c.bodies[static_cast<std::size_t>(k)];
    EXPECT_NEAR(b.position_m.x(), 1.0, kTol_m);
    EXPECT_NEAR(b.position_m.y(), 2.0 + 0.25 * k, kTol_m);  // 2 r + gap
    EXPECT_EQ(b.velocity_mps.y(), k == 0 ? 1.0 : 0.0);
  }
}

TEST(Generate, GridIsSeededAndTheSameOnEveryLoad) {
  const std::string text = kGround +
                           "[[generate]]\nkind = \"grid\"\nname = \"disk\"\ncount = 7\ncolumns = 3\n"
                           "shape = { type = \"circle\", radius = 0.05 }\nmass = 0.1\n"
                           "origin = [0.0, 1.0]\nspacing = [0.2, 0.3]\njitter = 0.01\nseed = 4\n" +
                           group("\"ground\", \"disk\"");
  const Case a = parse(text);
  const Case b = parse(text);
  ASSERT_EQ(a.bodies.size(), 8u);
  for (int k = 0; k < 7; ++k) {
    const Vec2& p = a.bodies[static_cast<std::size_t>(1 + k)].position_m;
    EXPECT_EQ(p, b.bodies[static_cast<std::size_t>(1 + k)].position_m);  // same bits
    // within the jitter of its grid point: column k % 3, row k / 3
    EXPECT_LE(std::abs(p.x() - 0.2 * (k % 3)), 0.01 + kTol_m);
    EXPECT_LE(std::abs(p.y() - (1.0 + 0.3 * (k / 3))), 0.01 + kTol_m);
  }
  // another seed moves them
  std::string other = text;
  other.replace(other.find("seed = 4"), 8, "seed = 5");
  EXPECT_NE(parse(other).bodies[1].position_m, a.bodies[1].position_m);
}

TEST(ContactGroups, AGeneratorNameStandsForItsBodies) {
  const Case c = parse(kGround + "[[generate]]\nkind = \"stack\"\nname = \"box\"\ncount = 2\n" + kBox +
                       "mass = 1.0\non = \"ground\"\n" + group("\"ground\", \"box\""));
  ASSERT_EQ(c.contact_groups.size(), 1u);
  EXPECT_EQ(c.contact_groups[0].bodies, (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(c.contacts.empty());
}

TEST(ContactGroups, ErrorsNameTheFieldAndWhatIsAllowed) {
  const std::string stack = kGround + "[[generate]]\nkind = \"stack\"\nname = \"box\"\ncount = 2\n" +
                            kBox + "mass = 1.0\non = \"ground\"\n";
  EXPECT_NE(error_of(stack + group("\"ground\", \"bx\"")).find("contact_groups[0].bodies[1]: no body or [[generate]] named 'bx' (did you mean 'box'?)"),
            std::string::npos)
      << error_of(stack + group("\"ground\", \"bx\""));
  EXPECT_NE(error_of(stack + group("\"box\", \"box_1\"")).find("names body 'box_1' twice"), std::string::npos);
  EXPECT_NE(error_of(stack + group("\"ground\"")).find("at least two bodies, one of them moving"),
            std::string::npos);
  // two groups sharing a moving pair
  const std::string two = stack + group("\"ground\", \"box\"") +
                          "[[contact_groups]]\nname = \"more\"\nbodies = [\"box\"]\nlaw = \"kelvin_voigt\"\n"
                          "stiffness = 1.0\ndamping = 0.0\n";
  EXPECT_NE(error_of(two).find("shares bodies 'box_1' and 'box_2' with contact_groups[0] 'all'"),
            std::string::npos)
      << error_of(two);
  // a body name past the results file's 32 characters
  const std::string long_name = kGround + "[[generate]]\nkind = \"stack\"\nname = \"a_generator_name_of_thirty_one\"\ncount = 10\n" +
                                kBox + "mass = 1.0\non = \"ground\"\n";
  EXPECT_NE(error_of(long_name).find("generate[0].name:"), std::string::npos) << error_of(long_name);
  // a stack must stand on a half-plane
  EXPECT_NE(error_of(kGround + "[[generate]]\nkind = \"stack\"\nname = \"box\"\ncount = 2\n" + kBox +
                     "mass = 1.0\non = \"floor\"\n")
                .find("generate[0].on: must name a fixed halfplane"),
            std::string::npos);
  // resting needs a rule for every interface
  EXPECT_NE(error_of(stack + "start = \"resting\"\n").find("no [[contacts]] pair or [[contact_groups]] lets them touch"),
            std::string::npos)
      << error_of(stack + "start = \"resting\"\n");
  // a key of another kind
  EXPECT_NE(error_of(stack + "spacing = [1.0, 1.0]\n").find("of a stack"), std::string::npos)
      << error_of(stack + "spacing = [1.0, 1.0]\n");
}

TEST(ContactGroups, ACentreInsideAPartnerIsRefused) {
  // two disks of a grid at one point: the broad phase finds them
  const std::string text = kGround +
                           "[[generate]]\nkind = \"grid\"\nname = \"disk\"\ncount = 2\n"
                           "shape = { type = \"circle\", radius = 0.05 }\nmass = 0.1\n"
                           "origin = [0.0, 1.0]\nspacing = [0.01, 0.0]\n" +
                           group("\"ground\", \"disk\"");
  EXPECT_NE(error_of(text).find("generate[0].spacing: body 'disk_1' (made by this [[generate]]): the "
                            "centre of 'disk_1' (0, 1) m starts inside 'disk_2'"),
            std::string::npos)
      << error_of(text);
}

TEST(ContactGroups, OverridesReachGroupsAndGenerators) {
  const std::string text = kGround + "[[generate]]\nkind = \"stack\"\nname = \"box\"\ncount = 2\n" + kBox +
                           "mass = 1.0\non = \"ground\"\n" + group("\"ground\", \"box\"");
  SettingsOverrides o;
  o.set("generate.box.count", "4", SettingSource{"--set", 0});
  o.set("groups.all.damping", "20.0", SettingSource{"--set", 0});
  const Case c = parse_case(text, "scene.toml", "scene", o);
  EXPECT_EQ(c.generated[0].count, 4);
  EXPECT_EQ(std::get<KelvinVoigt>(c.contact_groups[0].law).damping_ns_per_m, 20.0);
  SettingsOverrides every;
  every.set("contact.stiffness", "5e5", SettingSource{"--set", 0});
  EXPECT_EQ(std::get<KelvinVoigt>(parse_case(text, "scene.toml", "scene", every).contact_groups[0].law)
                .stiffness_n_per_m,
            5e5);
  SettingsOverrides body;
  body.set("bodies.box_1.mass", "3.0", SettingSource{"--set", 0});
  try {
    (void)parse_case(text, "scene.toml", "scene", body);
    FAIL() << "a generated body is set through its generator";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("generate.<name>.<field>"), std::string::npos) << e.what();
  }
}

TEST(ContactPairs, DeclaredFirstThenGroupPairsAsFound) {
  const Case c = parse(kGround + "[[generate]]\nkind = \"stack\"\nname = \"box\"\ncount = 3\n" + kBox +
                       "mass = 1.0\non = \"ground\"\n" + group("\"ground\", \"box\"") +
                       "[[contacts]]\nname = \"special\"\nbodies = [\"ground\", \"box_3\"]\n"
                       "law = \"kelvin_voigt\"\nstiffness = 7.0\ndamping = 0.0\n");
  ContactPairs pairs(c);
  EXPECT_EQ(pairs.size(), 1);
  EXPECT_EQ(pairs.declared(), 1);
  EXPECT_EQ(pairs.find(3, 0), 0);        // the declared pair, either order
  EXPECT_EQ(pairs.find(1, 2), -1);       // not found yet
  const int k = pairs.find_or_add(2, 1);
  EXPECT_EQ(k, 1);
  EXPECT_EQ(pairs[k].body_a, 1);         // the lower index first
  EXPECT_EQ(pairs[k].body_b, 2);
  EXPECT_EQ(pairs.find_or_add(1, 2), 1);  // kept
  const int g = pairs.find_or_add(1, 0);
  EXPECT_EQ(pairs[g].body_a, 0);         // the fixed body first
  EXPECT_EQ(pairs.group_of_pair(g), 0);
  EXPECT_EQ(pairs.group_of_pair(0), -1);
  // the declared pair's law wins over the group's
  EXPECT_EQ(std::get<KelvinVoigt>(*pairs.law_between(0, 3)).stiffness_n_per_m, 7.0);
  EXPECT_EQ(std::get<KelvinVoigt>(*pairs.law_between(2, 3)).stiffness_n_per_m, 1e6);
  EXPECT_EQ(pairs.rule_name(2, 3), "group all");
  EXPECT_EQ(pairs.find_or_add(0, 0), -1);
}

}  // namespace
}  // namespace pb
