// Tests for core/impacts/src/impact_identification.cpp: the grouped
// jackknife over the fold fits, against the arithmetic done by hand.
#include "planarbench/impacts/impact_identification.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace pb {
namespace {

ImpactParameter linear(const char* name) { return {name, "-", 0.0, 1.0, 0.5, false, ""}; }
ImpactParameter logarithmic(const char* name) { return {name, "N/m", 1e3, 1e6, 1e4, true, ""}; }

TEST(ParameterSpread, GroupedJackknifeOfFiveFolds) {
  // five fold fits of (zeta, mu, K): zeta 0.5 +- a spread that sums d^2 to
  // 0.02, mu to 0.0002, log K to 0.5
  const std::vector<ImpactParameter> specs = {linear("zeta"), linear("mu"), logarithmic("k")};
  const std::vector<std::vector<double>> folds = {{0.5, 0.2, 1e4},
                                                  {0.6, 0.21, 1e4 * std::exp(0.5)},
                                                  {0.4, 0.19, 1e4 * std::exp(-0.5)},
                                                  {0.5, 0.2, 1e4},
                                                  {0.5, 0.2, 1e4}};
  const auto s = parameter_spread(specs, {0.5, 0.2, 1e4}, folds);
  ASSERT_EQ(s.size(), 3u);
  // SE^2 = (k - 1) / k sum d^2 = 4/5 x 0.02 = 0.016
  EXPECT_NEAR(s[0].jackknife_se, std::sqrt(0.016), 1e-15);
  EXPECT_NEAR(s[0].half_width, 2 * std::sqrt(0.016) / 0.5, 1e-14);  // 0.506: not identified
  EXPECT_FALSE(s[0].identified);
  EXPECT_EQ(s[0].fold_min, 0.4);
  EXPECT_EQ(s[0].fold_max, 0.6);
  EXPECT_EQ(s[0].folds, 5);
  // mu: SE = sqrt(4/5 x 0.0002) = 0.01265, +-2 SE = 12.6 % of 0.2: identified
  EXPECT_NEAR(s[1].half_width, 2 * std::sqrt(0.00016) / 0.2, 1e-12);
  EXPECT_TRUE(s[1].identified);
  // K on log K: SE = sqrt(4/5 x 0.5), the interval a factor exp(2 SE) = 3.54
  EXPECT_NEAR(s[2].jackknife_se, std::sqrt(0.4), 1e-14);
  EXPECT_NEAR(s[2].half_width, std::exp(2 * std::sqrt(0.4)) - 1, 1e-12);
  EXPECT_FALSE(s[2].identified);
  EXPECT_FALSE(s[2].whole_outside_folds);
}

TEST(ParameterSpread, FixedParametersAreNoneAndAnOptimumOutsideTheFoldsIsFlagged) {
  ImpactParameter fixed = logarithmic("k");
  fixed.lower = fixed.upper = 3e4;  // Box2D's K: no parameter of its rigid contact
  const auto s = parameter_spread({fixed, linear("mu")}, {3e4, 0.3},
                                  {{3e4, 0.2}, {3e4, 0.21}, {3e4, 0.22}});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].name, "mu");
  EXPECT_TRUE(s[0].whole_outside_folds);
  EXPECT_THROW((void)parameter_spread({linear("mu")}, {0.2}, {{0.2}}), std::invalid_argument);
}

}  // namespace
}  // namespace pb

namespace pb {
namespace {

// a value fitted to 0 (a slope, e_t): its width relative to the search range
// (2 SE / (upper - lower)), as a relative width of 0 would be 0 / 0
TEST(ParameterSpread, AValueAtZeroIsJudgedAgainstTheSearchRange) {
  const std::vector<ImpactParameter> specs = {{"slope", "s/m", -1.0, 1.0, 0.0, false, ""}};
  const std::vector<std::vector<double>> folds = {{0.0}, {0.01}, {-0.01}, {0.02}, {-0.02}};
  const auto s = parameter_spread(specs, {0.0}, folds);
  ASSERT_EQ(s.size(), 1u);
  // mean 0, sum of squares 1e-3: SE = sqrt(4/5 x 1e-3) = 0.028284
  EXPECT_NEAR(s[0].jackknife_se, std::sqrt(0.8e-3), 1e-15);
  EXPECT_NEAR(s[0].half_width, 2.0 * std::sqrt(0.8e-3) / 2.0, 1e-15);
  EXPECT_EQ(s[0].relative_to, "range");
  EXPECT_TRUE(s[0].identified);  // 2.8 % of the range
}

}  // namespace
}  // namespace pb
