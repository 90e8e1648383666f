// Tests for apps/sweep_plan.cpp
#include "sweep_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "planarbench/errors.hpp"

namespace {

using pb::cli::SeriesPlan;

// the number a settings text reads as
double number(const pb::SettingValue* v) {
  return v == nullptr ? -1.0 : std::strtod(v->text.c_str(), nullptr);
}

TEST(SweepPlan, DefaultLaddersRunCoarseToFine) {
  EXPECT_EQ(pb::cli::default_dt_ladder(),
            (std::vector<double>{1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5}));
  EXPECT_EQ(pb::cli::default_rtol_ladder(), (std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10}));
  // --quick: two rungs per series, the engines' default step 1e-4 s among them
  EXPECT_EQ(pb::cli::quick_dt_ladder(), (std::vector<double>{1e-3, 1e-4}));
  EXPECT_EQ(pb::cli::quick_rtol_ladder().size(), 2u);
}

TEST(SweepPlan, ParseLadderSortsCoarseToFine) {
  EXPECT_EQ(pb::cli::parse_ladder("1e-5,1e-3,2e-4", "--dt-ladder"),
            (std::vector<double>{1e-3, 2e-4, 1e-5}));
  EXPECT_EQ(pb::cli::parse_ladder("0.001", "--dt-ladder"), (std::vector<double>{1e-3}));
}

TEST(SweepPlan, ParseLadderRejectsWhatIsNotAPositiveNumberNamingTheOption) {
  for (const char* bad :
       {"", "1e-3,,1e-4", "abc", "1e-3x", "-1e-3", "0", "1e-3,1e-3", "nan", "inf", "1e-3,"}) {
    try {
      (void)pb::cli::parse_ladder(bad, "--dt-ladder");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const pb::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--dt-ladder"), std::string::npos) << e.what();
    }
  }
}

TEST(SweepPlan, TwoCoarsestKeepsTheTwoLargest) {
  EXPECT_EQ(pb::cli::two_coarsest({1e-5, 1e-3, 2e-4}), (std::vector<double>{1e-3, 2e-4}));
  EXPECT_EQ(pb::cli::two_coarsest({1e-4}), (std::vector<double>{1e-4}));
}

TEST(SweepPlan, ReferenceHasAnRk45AndAFixedStepSeries) {
  const auto s = pb::cli::series_for("reference", {1e-3, 1e-4}, {1e-4, 1e-6});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].name, "reference_rk45");
  EXPECT_EQ(s[0].knob, "rtol");
  EXPECT_EQ(s[0].knob_key, "reference.rtol");
  EXPECT_EQ(s[0].knob_unit, "1");
  EXPECT_EQ(s[0].values, (std::vector<double>{1e-4, 1e-6}));
  EXPECT_EQ(s[1].name, "reference_fixed");
  EXPECT_EQ(s[1].knob, "dt");
  EXPECT_EQ(s[1].knob_key, "reference.dt");
  EXPECT_EQ(s[1].knob_unit, "s");
  EXPECT_EQ(s[1].values, (std::vector<double>{1e-3, 1e-4}));
  for (const char* e : {"mujoco", "box2d", "ode"}) {
    const auto one = pb::cli::series_for(e, {1e-3}, {1e-4});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].knob_key, std::string(e) + ".dt");
    EXPECT_TRUE(one[0].fixed.empty());
  }
}

TEST(SweepPlan, AnalyticAndUnknownEnginesAreInputErrors) {
  EXPECT_THROW((void)pb::cli::series_for("analytic", {1e-3}, {1e-4}), pb::InputError);
  EXPECT_THROW((void)pb::cli::series_for("havok", {1e-3}, {1e-4}), pb::InputError);
}

TEST(SweepPlan, RungOverridesSetTheKnobTheFixedSettingsAndAtol) {
  pb::SettingsOverrides base;
  base.set("reference.geometry", "exact", {"--set", 0});
  const auto series = pb::cli::series_for("reference", {1e-3}, {1e-6});
  const auto rk45 = pb::cli::rung_overrides(base, series[0], 1e-6);
  EXPECT_EQ(rk45.find("reference.geometry")->text, "exact");  // the user's keys stay
  EXPECT_EQ(rk45.find("reference.integrator")->text, "rk45");
  EXPECT_EQ(number(rk45.find("reference.rtol")), 1e-6);
  // atol follows rtol: 1e-6 * 1e-2 = 1e-8 (to the last bit: both are decimal texts)
  EXPECT_EQ(number(rk45.find("reference.atol")), 1e-6 * pb::cli::kAtolPerRtol);
  const auto fixed = pb::cli::rung_overrides(base, series[1], 2e-4);
  EXPECT_EQ(fixed.find("reference.integrator")->text, "fixed");
  EXPECT_EQ(number(fixed.find("reference.dt")), 2e-4);
  EXPECT_EQ(fixed.find("reference.atol"), nullptr);
}

TEST(SweepPlan, RungOverridesReplaceACaseSettingOfTheKnob) {
  // a case's [settings] may state mujoco.dt; the rung's value replaces it
  pb::SettingsOverrides base;
  base.set("mujoco.dt", "5e-4", {"case.toml", 3});
  const auto s = pb::cli::series_for("mujoco", {1e-3}, {});
  EXPECT_EQ(number(pb::cli::rung_overrides(base, s[0], 1e-3).find("mujoco.dt")), 1e-3);
}

TEST(SweepPlan, FixedSettingsJsonNamesWhatEveryRungShares) {
  const auto s = pb::cli::series_for("reference", {1e-3}, {1e-6});
  EXPECT_EQ(pb::cli::fixed_settings_json(s[1]), R"({"reference.integrator":"fixed"})");
  EXPECT_NE(pb::cli::fixed_settings_json(s[0]).find("reference.atol"), std::string::npos);
}

TEST(SweepPlan, SweptKeysInSetAreRejectedOthersPass) {
  for (const char* key :
       {"dt", "rtol", "atol", "integrator", "mujoco.dt", "box2d.dt", "ode.dt", "reference.dt",
        "reference.rtol", "reference.atol", "reference.integrator"}) {
    pb::SettingsOverrides given;
    given.set(key, "1", {"--set", 0});
    EXPECT_THROW(pb::cli::reject_swept_keys(given), pb::InputError) << key;
  }
  pb::SettingsOverrides fine;
  fine.set("mujoco.integrator", "RK4", {"--set", 0});
  fine.set("reference.geometry", "exact", {"--set", 0});
  EXPECT_NO_THROW(pb::cli::reject_swept_keys(fine));
}

TEST(SweepPlan, TruthIsTheClosedFormOnlyWhereItHoldsOverTheWholeRun) {
  pb::Case c;
  c.truth = pb::TruthKind::analytic;
  EXPECT_EQ(pb::cli::truth_for(c).engine, "analytic");
  // dual_pendulum: the closed form stops at the first contact (SPEC §3)
  c.truth = pb::TruthKind::analytic_until_first_contact;
  auto t = pb::cli::truth_for(c);
  EXPECT_EQ(t.engine, "reference");
  EXPECT_NE(t.note.find("first contact"), std::string::npos);
  c.truth = pb::TruthKind::none;
  t = pb::cli::truth_for(c);
  EXPECT_EQ(t.engine, "reference");
  // the reference truth: exact geometry, rk45 at rtol 1e-10, atol 1e-12
  const std::vector<std::pair<std::string, std::string>> want = {{"reference.integrator", "rk45"},
                                                                 {"reference.rtol", "1e-10"},
                                                                 {"reference.atol", "1e-12"},
                                                                 {"reference.geometry", "exact"}};
  EXPECT_EQ(t.settings, want);
}

TEST(SweepPlan, MedianOfOddAndEvenCounts) {
  EXPECT_EQ(pb::cli::median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(pb::cli::median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(pb::cli::median({7.0}), 7.0);
  EXPECT_TRUE(std::isnan(pb::cli::median({})));
}

TEST(SweepPlan, CostModelOrdersFinerAndTighterRungsLater) {
  const auto ref = pb::cli::series_for("reference", {1e-3}, {1e-4});
  const auto mj = pb::cli::series_for("mujoco", {1e-3}, {});
  EXPECT_GT(pb::cli::rung_cost(mj[0], 1e-5, 1.0), pb::cli::rung_cost(mj[0], 1e-4, 1.0));
  EXPECT_GT(pb::cli::rung_cost(ref[1], 1e-4, 1.0), pb::cli::rung_cost(mj[0], 1e-4, 1.0));
  EXPECT_GT(pb::cli::rung_cost(ref[0], 1e-10, 1.0), pb::cli::rung_cost(ref[0], 1e-4, 1.0));
  EXPECT_GT(pb::cli::rung_cost(mj[0], 1e-4, 2.0), pb::cli::rung_cost(mj[0], 1e-4, 1.0));
}

}  // namespace

namespace {

// The ladder's stopping rule (issue 12), on hand-made error sequences: flat
// means the last three ok rungs agree within a tenth of the smaller error.
// Values exact in binary where the comparison is at the boundary.
TEST(SweepPlan, LadderStopsOnceTheErrorIsFlat) {
  using pb::cli::ladder_is_flat;
  const double nan = std::nan("");
  EXPECT_FALSE(ladder_is_flat({}));
  EXPECT_FALSE(ladder_is_flat({1.0, 1.0}));             // two rungs: not yet
  EXPECT_TRUE(ladder_is_flat({1.0, 1.0, 1.0}));         // a floor
  EXPECT_TRUE(ladder_is_flat({8.0, 1.0, 1.0, 1.0}));    // falling, then a floor
  EXPECT_FALSE(ladder_is_flat({1.0, 1.0, 0.5}));        // falling again
  EXPECT_TRUE(ladder_is_flat({1.0, 1.0, 1.0625}));      // 6.25 % apart: within a tenth
  EXPECT_FALSE(ladder_is_flat({1.0, 1.0, 1.125}));      // 12.5 % apart: not flat
  // ODE on dual_pendulum (landed sweep): rises, pauses, falls: never flat
  const std::vector<double> ode = {0.051, 0.12, 0.14, 0.14, 0.094, 0.026, 0.0069};
  for (std::size_t n = 1; n <= ode.size(); ++n) {
    EXPECT_FALSE(ladder_is_flat({ode.begin(), ode.begin() + static_cast<std::ptrdiff_t>(n)})) << n;
  }
  EXPECT_FALSE(ladder_is_flat({1.0, 1.0, 1.0, nan}));   // a diverged rung never stops it
  EXPECT_TRUE(ladder_is_flat({1.0, nan, 1.0, 1.0}));    // compared over the ok rungs
}

}  // namespace
