// Tests for core/reference/include/planarbench/reference/event_location.hpp
#include "planarbench/reference/event_location.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace pb {
namespace {

// g(x) = x^3 + 2 x - 1 has one real root in (0, 1), by Cardano's formula for
// x^3 + p x + q = 0 (p = 2, q = -1, discriminant q^2/4 + p^3/27 > 0):
// x* = cbrt(-q/2 + sqrt(D)) + cbrt(-q/2 - sqrt(D)), about 0.45340
double cardano_root() {
  const double p = 2.0, q = -1.0;
  const double sd = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
  return std::cbrt(-q / 2.0 + sd) + std::cbrt(-q / 2.0 - sd);
}
const double kRoot = cardano_root();

// the bracket width asked for; the checks allow twice it, for a few ulps
// (5.6e-17 each near 0.45) of rounding in Cardano's cube roots
constexpr double kRootTol = 1e-15;

TEST(EventLocation, IllinoisFindsTheRootToTolerance) {
  int calls = 0;
  auto probe = [&](double x) {
    ++calls;
    const double g = x * x * x + 2 * x - 1;
    return std::pair<double, bool>(g, g > 0.0);  // the event: g turns positive
  };
  const Bracket b = locate_event(probe, 0.0, -1.0, 1.0, 2.0, kRootTol, RootMethod::illinois);
  EXPECT_LE(b.hi - b.lo, kRootTol);  // the width asked for
  EXPECT_NEAR(b.hi, kRoot, 2.0 * kRootTol);  // bracket width + Cardano rounding
  EXPECT_GT(b.hi * b.hi * b.hi + 2 * b.hi - 1, 0.0);  // hi is on the event's side
  EXPECT_LT(calls, 20);  // superlinear, unlike bisection's ~50
}

TEST(EventLocation, BisectionFindsTheSameRoot) {
  auto probe = [](double x) {
    const double g = x * x * x + 2 * x - 1;
    return std::pair<double, bool>(g, g > 0.0);
  };
  const Bracket b = locate_event(probe, 0.0, -1.0, 1.0, 2.0, kRootTol, RootMethod::bisection);
  EXPECT_NEAR(b.hi, kRoot, 2.0 * kRootTol);  // bracket width + Cardano rounding
  EXPECT_GE(b.iterations, 49);  // log2(1 / 1e-15)
}

TEST(EventLocation, RootAtTheStartConvergesToIt) {
  // g(x) = -x^2: the predicate "g < 0" holds everywhere after 0
  auto probe = [](double x) { return std::pair<double, bool>(-x * x, -x * x < 0.0); };
  const Bracket b = locate_event(probe, 0.0, 0.0, 1e-3, -1e-6, 1e-20, RootMethod::illinois);
  EXPECT_LT(b.hi, 1e-19);  // within the bracket width 1e-20 asked for, 10x spare
}

}  // namespace
}  // namespace pb
