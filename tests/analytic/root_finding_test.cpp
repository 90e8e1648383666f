// Tests for core/analytic/root_finding.cpp
#include "root_finding.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace pb::internal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The first double x in [1, 2] with x * x >= 2: the predicate flips there and
// not one double earlier, which is what "to the last bit" means.
TEST(FirstTrueByBisection, FindsTheLastBitOfSqrt2) {
  const auto pred = [](double x) { return x * x >= 2.0; };
  const double r = first_true_by_bisection(pred, 1.0, 2.0);
  EXPECT_TRUE(pred(r));
  EXPECT_FALSE(pred(std::nextafter(r, 0.0)));
  // and that is the correctly rounded sqrt(2) or its neighbour
  EXPECT_LE(std::abs(r - std::sqrt(2.0)), 2.0 * std::numeric_limits<double>::epsilon());
}

// A bracket near zero still converges (the halving is relative to the bracket).
TEST(FirstTrueByBisection, TinyRoot) {
  const double root = 3e-300;
  const double r = first_true_by_bisection([&](double x) { return x >= root; }, 0.0, 1.0);
  EXPECT_EQ(r, root);
}

// (tau - 1)(tau - 3) = tau^2 - 4 tau + 3 goes down through 0 at 1, up at 3.
TEST(FirstQuadraticCrossing, DirectionSelectsTheRoot) {
  EXPECT_DOUBLE_EQ(first_quadratic_crossing(3.0, -4.0, 1.0, Crossing::downward), 1.0);
  EXPECT_DOUBLE_EQ(first_quadratic_crossing(3.0, -4.0, 1.0, Crossing::upward), 3.0);
  // the mirrored parabola -(tau - 1)(tau - 3): up at 1, down at 3
  EXPECT_DOUBLE_EQ(first_quadratic_crossing(-3.0, 4.0, -1.0, Crossing::upward), 1.0);
  EXPECT_DOUBLE_EQ(first_quadratic_crossing(-3.0, 4.0, -1.0, Crossing::downward), 3.0);
}

// tau^2 - 1e8 tau + 1: the small root 1e-8 (1 + 1e-16) is lost entirely by
// the textbook formula (1e8 - sqrt(1e16 - 4)) / 2 in doubles; the stable form
// keeps it to the last bits (Numerical Recipes §5.6). Its slope there is
// negative: a downward crossing.
TEST(FirstQuadraticCrossing, NoCancellationForTheSmallRoot) {
  const double r = first_quadratic_crossing(1.0, -1e8, 1.0, Crossing::downward);
  EXPECT_NEAR(r, 1e-8, 4e-24);  // a few ulp of 1e-8
  EXPECT_DOUBLE_EQ(first_quadratic_crossing(1.0, -1e8, 1.0, Crossing::upward), 1e8);
}

// A free fall from rest at height h reaches 0 after sqrt(2 h / g).
TEST(FirstQuadraticCrossing, FreeFall) {
  const double h = 2.0;
  const double g = 9.8066;
  EXPECT_NEAR(first_quadratic_crossing(h, 0.0, -0.5 * g, Crossing::downward),
              std::sqrt(2.0 * h / g), 1e-15);
}

// A throw up from u = 0: the root at tau = 0 is not "after the start"; the
// landing at 2 v / g is.
TEST(FirstQuadraticCrossing, RootAtZeroIsSkipped) {
  const double v = 3.0;
  const double g = 9.8066;
  EXPECT_NEAR(first_quadratic_crossing(0.0, v, -0.5 * g, Crossing::downward), 2.0 * v / g, 1e-15);
  EXPECT_EQ(first_quadratic_crossing(0.0, v, -0.5 * g, Crossing::upward), kInf);
}

// linear, no real root, tangency, and roots only in the past
TEST(FirstQuadraticCrossing, DegenerateCases) {
  EXPECT_DOUBLE_EQ(first_quadratic_crossing(2.0, -4.0, 0.0, Crossing::downward), 0.5);
  EXPECT_EQ(first_quadratic_crossing(2.0, -4.0, 0.0, Crossing::upward), kInf);
  EXPECT_EQ(first_quadratic_crossing(2.0, 0.0, 0.0, Crossing::downward), kInf);
  EXPECT_EQ(first_quadratic_crossing(1.0, 0.0, 1.0, Crossing::downward), kInf);   // no real root
  EXPECT_EQ(first_quadratic_crossing(1.0, -2.0, 1.0, Crossing::downward), kInf);  // (tau-1)^2
  EXPECT_EQ(first_quadratic_crossing(3.0, 4.0, 1.0, Crossing::upward), kInf);     // roots -1, -3
}

}  // namespace
}  // namespace pb::internal
