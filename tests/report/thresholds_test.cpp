// Tests for reports/src/thresholds.cpp: the gate's verdicts
//
// A threshold band holds or not (numpy assert_allclose semantics); a known
// breach (an engine's own model cannot meet the band, said before the run)
// is shown and does not fail the gate, but its pass does ("unexpected pass":
// the stated reason no longer holds), and a metric that was not computed
// fails whatever the threshold expects.
#include "planarbench/reports/thresholds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "planarbench/errors.hpp"
#include "report_files.hpp"

namespace pb {
namespace {

namespace fs = std::filesystem;

Threshold band(const std::string& engine, double rtol, const std::string& known = "") {
  Threshold t;
  t.case_name = "falling_ball";
  t.engine = engine;
  t.against = "truth";
  t.metric = "restitution";
  t.rtol = rtol;
  t.why = "test";
  t.known_breach = known;
  if (!known.empty()) {
    // a known breach states its expected range (issue 31); these tests' values lie in it
    t.expected_min = 0.0;
    t.expected_max = 1.0;
    t.expected_why = "test";
  }
  return t;
}

MetricValue value(const std::string& engine, double actual, double desired) {
  MetricValue m;
  m.case_name = "falling_ball";
  m.engine = engine;
  m.against = "truth";
  m.metric = "restitution";
  m.episode = 0;
  m.actual = actual;
  m.desired = desired;
  return m;
}

TEST(Thresholds, VerdictsOfPlainAndKnownBreaches) {
  // desired 0.8: rtol 0.01 allows 0.008
  const auto out = check_thresholds(
      {band("mujoco", 0.01), band("ode", 0.01), band("box2d", 0.01, "impulsive restitution"),
       band("reference", 0.01, "stale reason")},
      {value("mujoco", 0.805, 0.8),     // inside: pass
       value("ode", 0.81, 0.8),         // 0.01 > 0.008: fail
       value("box2d", 0.70, 0.8),       // outside, as declared: known breach
       value("reference", 0.8, 0.8)},   // inside, declared not to be: unexpected pass
      {});
  ASSERT_EQ(out.size(), 4u);
  EXPECT_STREQ(outcome_label(out[0]), "pass");
  EXPECT_FALSE(fails_gate(out[0]));
  EXPECT_STREQ(outcome_label(out[1]), "fail");
  EXPECT_TRUE(fails_gate(out[1]));
  EXPECT_STREQ(outcome_label(out[2]), "known breach");
  EXPECT_FALSE(fails_gate(out[2]));
  EXPECT_NE(out[2].message.find("known breach: impulsive restitution"), std::string::npos);
  EXPECT_STREQ(outcome_label(out[3]), "unexpected pass");
  EXPECT_TRUE(fails_gate(out[3]));
  EXPECT_NE(out[3].message.find("remove known_breach"), std::string::npos) << out[3].message;
}

TEST(Thresholds, MissingMetricFailsEvenAsAKnownBreach) {
  const auto out = check_thresholds({band("box2d", 0.01, "impulsive restitution")},
                                    {value("mujoco", 0.8, 0.8)}, {});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(fails_gate(out[0]));
  EXPECT_STREQ(outcome_label(out[0]), "fail");
  EXPECT_NE(out[0].message.find("not computed"), std::string::npos);
}

TEST(Thresholds, NanIsABreachNotAKnownOne) {
  const auto out =
      check_thresholds({band("mujoco", 0.01)},
                       {value("mujoco", std::numeric_limits<double>::quiet_NaN(), 0.8)}, {});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(fails_gate(out[0]));
}

// issue 31: a known breach is a value outside the band, not a value that is
// not a number (a lost episode, a friction figure never reached, NaN from
// either side): that fails the gate like any other check, labelled "fail"
TEST(Thresholds, NanFailsAKnownBreachToo) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& [actual, desired] : {std::pair{nan, 0.8}, std::pair{0.5, nan}, std::pair{inf, 0.8}}) {
    const auto out = check_thresholds({band("mujoco", 0.01, "soft contact flicker")},
                                      {value("mujoco", actual, desired)}, {});
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(fails_gate(out[0])) << actual << " " << desired;
    EXPECT_STREQ(outcome_label(out[0]), "fail");
  }
  // a finite value outside the band stays the known breach it is
  const auto finite = check_thresholds({band("mujoco", 0.01, "soft contact flicker")},
                                       {value("mujoco", 0.5, 0.8)}, {});
  EXPECT_FALSE(fails_gate(finite[0]));
  EXPECT_STREQ(outcome_label(finite[0]), "known breach");
}

// issue 31: a known breach can fail: a finite value outside its expected
// range is "beyond its known breach" and fails the gate, on either side
TEST(Thresholds, AKnownBreachBeyondItsExpectedRangeFails) {
  Threshold t = band("box2d", 0.01, "impulsive restitution");
  t.expected_min = 0.6;
  t.expected_max = 0.75;
  t.expected_why = "the rigid 1-D restitution";
  for (const auto& [actual, beyond] : {std::pair{0.70, false}, std::pair{0.6, false},
                                       std::pair{0.75, false}, std::pair{0.5, true},
                                       std::pair{0.76, true}, std::pair{-0.7, true}}) {
    const auto out = check_thresholds({t}, {value("box2d", actual, 0.8)}, {});
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(fails_gate(out[0]), beyond) << actual;
    EXPECT_STREQ(outcome_label(out[0]), beyond ? "beyond its known breach" : "known breach")
        << actual;
    if (beyond) {
      EXPECT_NE(out[0].message.find("outside the expected range [0.6, 0.75]"), std::string::npos)
          << out[0].message;
      EXPECT_NE(out[0].message.find("the rigid 1-D restitution"), std::string::npos);
    }
  }
  // the range does not excuse a pass: inside the band is still an unexpected pass
  const auto inside = check_thresholds({t}, {value("box2d", 0.8, 0.8)}, {});
  EXPECT_STREQ(outcome_label(inside[0]), "unexpected pass");
  EXPECT_TRUE(fails_gate(inside[0]));
}

// issue 31: a band's assumption on the run's own steps is checked on the run
TEST(Thresholds, AStepAssumptionBrokenFailsWhateverTheValue) {
  Threshold t = band("reference", 0.01);
  t.steps_at_most = 1200;
  Threshold known = band("box2d", 0.01, "impulsive restitution");
  known.steps_at_most = 1200;
  auto out = check_thresholds({t, known}, {value("reference", 0.8, 0.8), value("box2d", 0.7, 0.8)},
                              {});
  check_run_assumptions(out, [](const std::string&, const std::string& engine) {
    return RunFigures{engine == "reference" ? 1201L : 1200L, -1.0};
  });
  EXPECT_STREQ(outcome_label(out[0]), "assumption broken");
  EXPECT_TRUE(fails_gate(out[0]));
  EXPECT_NE(out[0].message.find("at most 1200 accepted steps"), std::string::npos) << out[0].message;
  EXPECT_NE(out[0].message.find("took 1201"), std::string::npos) << out[0].message;
  EXPECT_STREQ(outcome_label(out[1]), "known breach");  // 1200 steps: the assumption holds
  EXPECT_FALSE(fails_gate(out[1]));
}

// issue 31: a band's assumption on the collider's depth error, checked on the
// figure the run records (MuJoCo's MPR against the exact depth)
TEST(Thresholds, ADepthErrorAssumptionIsCheckedOnTheRunsRecord) {
  Threshold t = band("mujoco", 0.01);
  t.depth_error_at_most_m = 1e-6;
  for (const auto& [recorded, broken] : {std::pair{3.9e-7, false}, std::pair{1e-6, false},
                                         std::pair{1.2e-6, true}, std::pair{-1.0, true}}) {
    auto out = check_thresholds({t}, {value("mujoco", 0.8, 0.8)}, {});
    check_run_assumptions(out, [r = recorded](const std::string&, const std::string&) {
      return RunFigures{100, r};
    });
    EXPECT_EQ(fails_gate(out[0]), broken) << recorded;
    if (broken) {
      EXPECT_STREQ(outcome_label(out[0]), "assumption broken");
    }
  }
}

// issue 31: summary.md lists every known breach, not the first 50
TEST(Thresholds, TheSummaryListsEveryKnownBreach) {
  std::vector<Threshold> bands;
  std::vector<MetricValue> values;
  for (int k = 0; k < 70; ++k) {
    bands.push_back(band("engine" + std::to_string(k), 0.01, "breach " + std::to_string(k)));
    values.push_back(value("engine" + std::to_string(k), 0.5, 0.8));
  }
  const std::string md = markdown_summary(check_thresholds(bands, values, {}), {}, {});
  for (int k = 0; k < 70; ++k) {
    EXPECT_NE(md.find("| breach " + std::to_string(k) + " |"), std::string::npos) << k;
  }
}

TEST(Thresholds, JunitSkipsKnownBreachesAndFailsTheRest) {
  const auto out = check_thresholds(
      {band("ode", 0.01), band("box2d", 0.01, "impulsive restitution")},
      {value("ode", 0.81, 0.8), value("box2d", 0.70, 0.8)}, {});
  const std::string x = junit_xml(out, {}, {});
  EXPECT_NE(x.find("tests=\"2\" failures=\"1\""), std::string::npos) << x;
  EXPECT_NE(x.find("<skipped message="), std::string::npos);
  EXPECT_NE(x.find("<property name=\"outcome\" value=\"known breach\"/>"), std::string::npos);
}

// Issue 49: a why or a run's reason holding a control character made the
// JUnit file stop being XML (XML 1.0 has no way to write U+0007), and markup
// reached the Markdown summary. The XML holds no raw control character but
// the newlines between its elements, its text's newline as &#10;, the BEL as
// U+FFFD; the summary shows the markup as text.
TEST(Thresholds, ControlCharactersAndMarkupStayText) {
  Threshold t = band("ode", 0.01);
  t.why = "a\x07" "bell <b>\nline";
  const auto out = check_thresholds({t}, {value("ode", 0.5, 0.8)}, {});
  const std::vector<std::string> diverged = {"c.e: <img src=x onerror=alert(1)>\x01"};
  const std::string x = junit_xml(out, diverged, {});
  for (const char ch : x) {
    EXPECT_FALSE(static_cast<unsigned char>(ch) < 0x20 && ch != '\n') << static_cast<int>(ch);
  }
  EXPECT_NE(x.find("a\xEF\xBF\xBD" "bell &lt;b&gt;&#10;line"), std::string::npos) << x;
  EXPECT_EQ(x.find("<img"), std::string::npos) << x;
  const std::string md = markdown_summary(out, diverged, {});
  EXPECT_EQ(md.find("<img"), std::string::npos) << md;
  EXPECT_EQ(md.find("<b>"), std::string::npos) << md;
  EXPECT_NE(md.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos) << md;
}

class ThresholdsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("pb_thresholds_test_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& text) {
    const fs::path p = dir_ / "t.toml";
    internal::write_text_atomically(p, text);
    return p;
  }
  fs::path dir_;
};

constexpr const char* kEntry = R"([[threshold]]
case = "falling_ball"
engine = "box2d"
against = "truth"
metric = "restitution"
rtol = 0.01
why = "1 % of e"
)";

constexpr const char* kRange =
    "expected = [0.5, 0.9]\nexpected_bound = [\"0.5\", \"0.9\"]\nexpected_why = \"rigid\"\n";

TEST_F(ThresholdsFile, ReadsKnownBreachAndByConstruction) {
  const auto t = load_thresholds(write(std::string(kEntry) + "known_breach = \"impulsive\"\n" +
                                       kRange + "by_construction = true\n"));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].known_breach, "impulsive");
  EXPECT_EQ(t[0].expected_min, 0.5);
  EXPECT_EQ(t[0].expected_max, 0.9);
  EXPECT_EQ(t[0].expected_why, "rigid");
  EXPECT_TRUE(t[0].by_construction);
  const auto plain = load_thresholds(write(kEntry));
  EXPECT_TRUE(plain[0].known_breach.empty());
  EXPECT_FALSE(plain[0].by_construction);
}

// issue 31: a known breach without a range could never fail; a range belongs
// to a known breach only; a range is two finite numbers, min <= max
TEST_F(ThresholdsFile, RefusesAKnownBreachWithoutItsRangeAndBadRanges) {
  const std::string known = "known_breach = \"impulsive\"\n";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {known, "expected: missing"},
      {known + "expected = [0.9, 0.5]\nexpected_why = \"w\"\n", "min <= max"},
      {known + "expected = [0.5]\nexpected_why = \"w\"\n", "two finite numbers"},
      {known + "expected = [\"0\", 1]\nexpected_why = \"w\"\n", "two finite numbers"},
      {known + "expected = [0.5, nan]\nexpected_why = \"w\"\n", "two finite numbers"},
      {known + "expected = [0.5, 0.9]\n", "expected_why"},
      {known + "expected = [0.5, 0.9]\nexpected_why = \"w\"\nexpected_bound = \"0.5\"\n",
       "expected_bound"},
      {std::string(kRange), "belongs to a known breach only"},
  };
  for (const auto& [text, says] : bad) {
    try {
      (void)load_thresholds(write(std::string(kEntry) + text));
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

TEST_F(ThresholdsFile, RefusesBadKnownBreachAndByConstruction) {
  for (const char* bad : {"known_breach = \"\"\n", "known_breach = 1\n",
                          "by_construction = \"yes\"\n", "by_construction = 1\n"}) {
    const fs::path p = write(std::string(kEntry) + bad);
    try {
      (void)load_thresholds(p);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("t.toml:8"), std::string::npos) << what;
      EXPECT_NE(what.find(std::string(bad).substr(0, std::string(bad).find(' '))),
                std::string::npos)
          << what;
    }
  }
}

TEST_F(ThresholdsFile, ReadsBoundAndConstants) {
  const auto t = load_thresholds(write("[constants]\nh = \"1e-4\"  # s\nwh = \"100 * h\"\n\n" +
                                       std::string(kEntry) + "bound = \"wh\"\n"));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].bound, "wh");
  EXPECT_TRUE(load_thresholds(write(kEntry))[0].bound.empty());
}

TEST_F(ThresholdsFile, RefusesBadBoundAndConstants) {
  // each: the file's text, the line and the field the message must name
  const std::vector<std::tuple<std::string, std::string, std::string>> bad = {
      {std::string(kEntry) + "bound = 0.01\n", "t.toml:8", "bound"},
      {std::string(kEntry) + "bound = \"\"\n", "t.toml:8", "bound"},
      {"[constants]\nh = 1e-4\n" + std::string(kEntry), "t.toml:2", "constants.h"},
      {"constants = 3\n" + std::string(kEntry), "t.toml:1", "constants"},
      {"[constant]\nh = \"1\"\n" + std::string(kEntry), "t.toml:1", "did you mean 'constants'"}};
  for (const auto& [text, line, field] : bad) {
    try {
      (void)load_thresholds(write(text));
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(line), std::string::npos) << what;
      EXPECT_NE(what.find(field), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace pb
