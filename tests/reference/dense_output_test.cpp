// Tests for core/reference/src/dense_output.cpp
#include "planarbench/reference/dense_output.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

TEST(DenseOutput, HermiteIsExactForCubics) {
  // y = t^3 - 2 t + 1 on [0.5, 0.9]: the cubic Hermite interpolant is exact
  auto y = [](double t) { return t * t * t - 2 * t + 1; };
  auto dy = [](double t) { return 3 * t * t - 2; };
  DenseSegment s;
  Eigen::VectorXd y0(1), y1(1), f0(1), f1(1), out(1);
  y0 << y(0.5);
  y1 << y(0.9);
  f0 << dy(0.5);
  f1 << dy(0.9);
  s.set_hermite(0.5, 0.4, y0, y1, f0, f1);
  for (const double t : {0.5, 0.61, 0.77, 0.9}) {
    s.evaluate(t, out);
    EXPECT_NEAR(out[0], y(t), 1e-15);  // |y| < 1: ~8 roundings of 1.1e-16
  }
}

TEST(DenseOutput, Dopri5FormEndsAtTheStepEnds) {
  DenseSegment s;
  s.kind = DenseSegment::Kind::dopri5;
  s.t0_s = 1.0;
  s.h_s = 0.1;
  s.c0 = Eigen::VectorXd::Constant(2, 3.0);
  s.c1 = Eigen::VectorXd::Constant(2, 0.5);
  s.c2 = Eigen::VectorXd::Constant(2, 7.0);
  s.c3 = Eigen::VectorXd::Constant(2, -2.0);
  s.c4 = Eigen::VectorXd::Constant(2, 11.0);
  Eigen::VectorXd out;
  s.evaluate(1.0, out);
  EXPECT_EQ(out[0], 3.0);  // theta = 0: c0
  s.evaluate(1.1, out);
  // theta = 1: c0 + c1; (1.1 - 1.0) / 0.1 is 1 - 9e-16 in doubles, times c's of 10
  EXPECT_NEAR(out[1], 3.5, 1e-13);
}

}  // namespace
}  // namespace pb
