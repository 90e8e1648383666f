// Tests for core/reference/src/rk4.cpp
// The harmonic oscillator y'' = -y: the global error of classic RK4 falls as h^4.
#include "planarbench/reference/rk4.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

class Oscillator final : public OdeSystem {
 public:
  void derivative(const Eigen::VectorXd& y, Eigen::VectorXd& dy) override {
    dy.resize(2);
    dy << y[1], -y[0];
  }
};

double global_error(double h) {
  Oscillator sys;
  ClassicRk4 rk(2);
  Eigen::VectorXd y(2), f(2), y1(2), f1(2);
  y << 1.0, 0.0;
  sys.derivative(y, f);
  const int n = static_cast<int>(std::lround(2.0 / h));
  for (int i = 0; i < n; ++i) {
    rk.step(sys, y, f, h, y1, f1);
    y = y1;
    f = f1;
  }
  return std::abs(y[0] - std::cos(2.0));
}

TEST(ClassicRk4, FourthOrder) {
  const double e1 = global_error(0.1), e2 = global_error(0.05), e3 = global_error(0.025);
  // +-0.1 in the order: the next error term is O(h) <= 0.1 relative to the
  // leading one at these steps; orders 3 or 5 are 10 times outside
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.1);
  EXPECT_NEAR(std::log2(e2 / e3), 4.0, 0.1);
}

TEST(ClassicRk4, OneStepMatchesTheTaylorSeries) {
  // for y' = A y, RK4 is the Taylor polynomial of exp(hA) of degree 4
  Oscillator sys;
  ClassicRk4 rk(2);
  Eigen::VectorXd y(2), f(2), y1(2), f1(2);
  y << 1.0, 0.0;
  sys.derivative(y, f);
  const double h = 0.3;
  rk.step(sys, y, f, h, y1, f1);
  // 1e-15 on O(1) values: a dozen roundings of 1.1e-16 on each side
  EXPECT_NEAR(y1[0], 1.0 - h * h / 2 + h * h * h * h / 24, 1e-15);
  EXPECT_NEAR(y1[1], -h + h * h * h / 6, 1e-15);
  EXPECT_EQ(f1[1], -y1[0]);  // f(y1) is a sign change of y1 here: bit-exact
}

}  // namespace
}  // namespace pb
