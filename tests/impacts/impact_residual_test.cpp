// Tests for core/impacts/src/impact_residual.cpp (issue 34 item 3): the
// kernel ridge regression under the learned-residual row. Truths: the
// leave-one-out predictions against an independent refit without each point
// (Eigen's LDLT on the n - 1 system, no eigendecomposition), the dual
// coefficients against the linear system they solve, and the untrained
// model predicting nothing.
#include "planarbench/impacts/impact_residual.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

namespace pb {
namespace {

struct Data {
  std::vector<std::vector<double>> x;
  std::vector<std::vector<double>> y;
};

// 40 points in 3-D, two smooth targets with noise (seeded)
Data data() {
  std::mt19937 g(7);
  std::normal_distribution<double> n(0.0, 1.0);
  Data d;
  for (int i = 0; i < 40; ++i) {
    std::vector<double> x = {n(g), n(g), n(g)};
    d.y.push_back({std::sin(x[0]) + 0.1 * n(g), x[1] * x[2] + 0.1 * n(g)});
    d.x.push_back(std::move(x));
  }
  return d;
}

Eigen::MatrixXd gram(const KernelRidge& k, const std::vector<std::vector<double>>& x) {
  const auto n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd m(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      m(i, j) = k.kernel(x[static_cast<std::size_t>(i)], x[static_cast<std::size_t>(j)]);
    }
  }
  return m;
}

TEST(KernelRidge, LeaveOneOutIsTheRefitWithoutThePoint) {
  const Data d = data();
  for (const double l : {0.5, 2.0}) {
    const KernelRidge k(d.x, l);
    const Eigen::MatrixXd full = gram(k, d.x);
    for (const double lambda : {1e-2, 1.0}) {
      const auto loo = k.loo(d.y, lambda);
      for (std::size_t i = 0; i < d.x.size(); i += 7) {
        // refit on the other 39 points and predict point i
        std::vector<Eigen::Index> keep;
        for (Eigen::Index j = 0; j < full.rows(); ++j) {
          if (static_cast<std::size_t>(j) != i) keep.push_back(j);
        }
        const auto m = static_cast<Eigen::Index>(keep.size());
        Eigen::MatrixXd a(m, m);
        Eigen::MatrixXd y(m, 2);
        Eigen::RowVectorXd kstar(m);
        for (Eigen::Index r = 0; r < m; ++r) {
          for (Eigen::Index c = 0; c < m; ++c) a(r, c) = full(keep[r], keep[c]);
          a(r, r) += lambda;
          for (Eigen::Index c = 0; c < 2; ++c) {
            y(r, c) = d.y[static_cast<std::size_t>(keep[r])][static_cast<std::size_t>(c)];
          }
          kstar(r) = full(static_cast<Eigen::Index>(i), keep[r]);
        }
        const Eigen::RowVectorXd refit = kstar * a.ldlt().solve(y);
        for (int c = 0; c < 2; ++c) {
          // 1e-8: two factorisations of a system whose condition number is
          // at most (n + lambda) / lambda = 4e3 at lambda = 1e-2
          EXPECT_NEAR(loo[i][static_cast<std::size_t>(c)], refit(c), 1e-8)
              << "l " << l << " lambda " << lambda << " point " << i;
        }
      }
    }
  }
}

TEST(KernelRidge, CoefficientsSolveTheRegularisedSystem) {
  const Data d = data();
  const KernelRidge k(d.x, 1.0);
  const Eigen::MatrixXd full = gram(k, d.x);
  const auto alpha = k.coefficients(d.y, 0.1);
  for (std::size_t i = 0; i < d.x.size(); ++i) {
    for (std::size_t c = 0; c < 2; ++c) {
      double lhs = 0.1 * alpha[i][c];
      for (std::size_t j = 0; j < d.x.size(); ++j) {
        lhs += full(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) * alpha[j][c];
      }
      // (K + lambda I) alpha = y to the rounding of a 40 x 40 solve
      EXPECT_NEAR(lhs, d.y[i][c], 1e-10);
    }
  }
}

TEST(LearnedResidual, UntrainedPredictsNothingAndSaysWhy) {
  const auto m = learned_residual_model();
  EXPECT_EQ(m->kind(), "learned");
  EXPECT_NE(m->description().find("DATA-DRIVEN"), std::string::npos);
  ImpactTable t;
  const ImpactOutcome o = m->predictor()->predict(t, 0, {});
  EXPECT_FALSE(o.ok());
  EXPECT_NE(o.failure.find("after training"), std::string::npos) << o.failure;
}

}  // namespace
}  // namespace pb
