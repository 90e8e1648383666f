// Tests for core/impacts/src/impact_fit.cpp and impact_study.cpp: the fold
// split, the NLopt fit recovering the parameters that made a set of impacts,
// and the study's tables (every impact judged once, by a fit that did not
// see it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "planarbench/impacts/impact_fit.hpp"
#include "planarbench/impacts/impact_study.hpp"
#include "planarbench/impacts/rigid_impact.hpp"
#include "synthetic_impacts.hpp"

namespace {

const pb::ImpactObject kObject;

// impacts made by the rigid law at e = 0.55, mu = 0.1 (the truth of the fit):
// mu low enough that most impacts slide throughout, so that the median error
// depends on it (with most impacts sticking, any larger mu fits them as well)
pb::ImpactTable rigid_table(std::size_t n) {
  const pb::ImpactSet set = pb::test::synthetic_impacts(n, 5, [](const pb::ImpactState& s) {
    return pb::rigid_impact(kObject, s, 0.55, 0.1);
  });
  return pb::make_impact_table(set, kObject, {-1.0, -1.0});
}

}  // namespace

// a model whose predictor fails on impact 5, as a broken engine build would
class FailingModel final : public pb::ImpactModel {
 public:
  std::string name() const override { return "failing"; }
  std::string kind() const override { return "engine"; }
  std::string description() const override { return "throws on impact 5"; }
  std::vector<pb::ImpactParameter> parameters() const override {
    return {{"x", "-", 0.0, 1.0, 0.5, false, "nothing"}};
  }
  std::unique_ptr<pb::ImpactPredictor> predictor() const override {
    struct P final : pb::ImpactPredictor {
      pb::ImpactOutcome predict(const pb::ImpactTable&, std::size_t i, const std::vector<double>&) override {
        if (i == 5) throw std::length_error("impact 5 cannot be built");
        return {};
      }
    };
    return std::make_unique<P>();
  }
};

TEST(ImpactFit, AFailureInAWorkerReachesTheCallerAsItself) {
  // the exception of a worker thread, and of NLopt's objective, arrives as
  // thrown (not std::terminate, not NLopt's bare "nlopt failure")
  const pb::ImpactTable t = rigid_table(12);
  std::vector<std::size_t> all(t.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  const FailingModel m;
  for (int jobs : {1, 2}) {
    EXPECT_THROW((void)pb::predict_impacts(m, t, all, {0.5}, jobs), std::length_error) << jobs;
    pb::FitOptions o;
    o.jobs = jobs;
    EXPECT_THROW((void)pb::fit_impacts(m, t, all, o), std::length_error) << jobs;
  }
}

TEST(ImpactFolds, APartitionOfBalancedSizesFixedByTheSeed) {
  const auto folds = pb::impact_folds(103, 5, 23);
  ASSERT_EQ(folds.size(), 5u);
  std::set<std::size_t> seen;
  for (const auto& f : folds) {
    EXPECT_TRUE(f.size() == 20u || f.size() == 21u) << f.size();
    EXPECT_TRUE(std::is_sorted(f.begin(), f.end()));
    for (std::size_t i : f) EXPECT_TRUE(seen.insert(i).second) << i << " in two folds";
  }
  EXPECT_EQ(seen.size(), 103u);
  EXPECT_EQ(pb::impact_folds(103, 5, 23), folds);
  EXPECT_NE(pb::impact_folds(103, 5, 24), folds);
  // a shuffle, not blocks: fold 0 is not the first fifth
  EXPECT_NE(folds[0].back(), 20u);
  const auto rest = pb::complement(103, folds[2]);
  EXPECT_EQ(rest.size() + folds[2].size(), 103u);
}

TEST(ImpactFit, RecoversTheParametersThatMadeTheImpacts) {
  const pb::ImpactTable t = rigid_table(300);
  std::vector<std::size_t> all(t.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  pb::FitOptions o;
  o.max_evaluations = 200;
  const auto model = pb::rigid_impact_model();
  const pb::FitResult r = pb::fit_impacts(*model, t, all, o);
  // the data are exact: the median error falls to the optimiser's resolution
  // (xtol 1e-4 of the unit range: e and mu within ~1e-3, eps ~1e-3)
  EXPECT_LT(r.objective, 5e-3);
  EXPECT_NEAR(r.parameters[0], 0.55, 5e-3);
  EXPECT_NEAR(r.parameters[1], 0.1, 5e-3);
  EXPECT_LE(r.evaluations, 200);
}

TEST(ImpactStudy, EveryImpactIsJudgedOnceByAFitThatDidNotSeeIt) {
  const pb::ImpactTable t = rigid_table(60);
  const auto folds = pb::impact_folds(t.size(), 3, 1);
  const auto model = pb::rigid_impact_model();
  pb::FitOptions o;
  o.max_evaluations = 30;
  std::vector<pb::FoldFit> fits;
  for (int f = 0; f < 3; ++f) fits.push_back(pb::run_fold_fit(*model, t, folds, f, o));
  fits.push_back(pb::run_fold_fit(*model, t, folds, pb::kWholeFile, o));
  for (int f = 0; f < 3; ++f) EXPECT_EQ(fits[static_cast<std::size_t>(f)].predicted, folds[static_cast<std::size_t>(f)]);
  EXPECT_EQ(fits[3].predicted.size(), t.size());

  // JSON round trip of a task is exact
  const pb::FoldFit back = pb::fold_fit_from_json(nlohmann::json::parse(pb::fold_fit_json(fits[1]).dump()));
  EXPECT_EQ(back.fit.parameters, fits[1].fit.parameters);
  ASSERT_EQ(back.outcomes.size(), fits[1].outcomes.size());
  for (std::size_t k = 0; k < back.outcomes.size(); ++k) {
    EXPECT_EQ(back.outcomes[k].after.velocities(), fits[1].outcomes[k].after.velocities());
  }

  pb::ImpactSet set;
  set.path = "synthetic";
  set.sha256 = std::string(64, '0');
  set.pre.resize(t.size());
  const pb::ConventionCheck cc{};
  pb::ImpactStudyHeader h;
  h.kind = "impacts_fit";
  h.data = &set;
  h.convention = &cc;
  h.folds = 3;
  const pb::CampaignTable table = pb::impact_study_table(h, {model.get()}, t, fits);
  // one row per impact: the cross-validated predictions only
  ASSERT_EQ(table.runs.size(), t.size());
  std::set<double> drops;
  for (const auto& r : table.runs) {
    EXPECT_EQ(r.series, "cross_validated");
    drops.insert(r.metrics[0]);
  }
  EXPECT_EQ(drops.size(), t.size());
  const auto& m = table.description.at("models").at(0);
  EXPECT_EQ(m.at("fits").size(), 4u);
  EXPECT_TRUE(m.contains("cross_validated"));
  EXPECT_TRUE(m.contains("in_sample"));
  // the frozen parameters are the whole-file fit's
  const pb::FrozenParameters frozen = pb::frozen_parameters(table, "fit.h5");
  ASSERT_EQ(frozen.models.size(), 1u);
  EXPECT_EQ(frozen.models[0].second, fits[3].fit.parameters);
}

// The objectives by hand: eps {0.1, 0.2, NaN, 3}: a failure is +inf in the
// median, so the sorted {0.1, 0.2, 3, inf} have median (0.2 + 3) / 2 = 1.6;
// the mean of min(eps, 1) with the failure as 1 is (0.1 + 0.2 + 1 + 1) / 4 =
// 0.575. Their words and names read back as themselves.
TEST(ImpactFit, TheObjectivesAreTheMedianAndTheCappedMean) {
  const std::vector<double> eps = {0.1, 0.2, std::nan(""), 3.0};
  // 1e-15: two additions and a division on numbers near 1
  EXPECT_NEAR(pb::fit_objective(eps, pb::FitObjective::median), 1.6, 1e-15);
  EXPECT_NEAR(pb::fit_objective(eps, pb::FitObjective::median_plus_mean), 1.6 + 0.575, 1e-15);
  for (pb::FitObjective o : {pb::FitObjective::median, pb::FitObjective::median_plus_mean}) {
    EXPECT_EQ(pb::parse_fit_objective(pb::fit_objective_words(o)), o);
    EXPECT_EQ(pb::parse_fit_objective(pb::fit_objective_name(o)), o);
  }
  EXPECT_FALSE(pb::parse_fit_objective("mean").has_value());
}
