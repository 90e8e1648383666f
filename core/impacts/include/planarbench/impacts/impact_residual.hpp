// The learned-residual row of the measured impacts (issue 34 item 3):
// DATA-DRIVEN, not physics. Over the best physics law of the project
// (rigid_compliant, rigid_impact.hpp), a kernel ridge regression learns what
// that law leaves out: the measured post-impact velocities minus the law's,
// as a function of the pre-impact state. Fitted on a fold's training impacts
// only (the law's parameters too), then judged on the held-out fold like
// every model. Kernel ridge is written here on Eigen (Debian's Eigen 3.4,
// already the project's): no C++ library of Debian 12 that the project uses
// offers kernel ridge or GP regression (mlpack 4's regressors are linear,
// Bayesian linear and LARS; Shark and libgp are not packaged), and the whole
// model is one n x n symmetric eigendecomposition per length scale.
//
// Features (standardised on the training impacts): x', y', theta', the
// contact point's slip u_t, cos 2 theta and sin 2 theta (the ellipse is the
// same turned by pi), the contact point's offset r_x. Gaussian kernel
// exp(-|a - b|^2 / (2 l^2)); l and the ridge lambda chosen among a fixed grid
// by the fit's objective (impact_fit.hpp) of the leave-one-out predictions over the training
// impacts, in closed form from K = Q L Q^T: the LOO residual of impact i is
// r_i / (1 - H_ii), H = K (K + lambda I)^-1 (Hastie, Tibshirani & Friedman,
// "The Elements of Statistical Learning", 2009, eq. 7.52, for linear
// smoothers).
#pragma once

#include <memory>
#include <vector>

#include "planarbench/impacts/impact_model.hpp"

namespace pb {

// "learned_residual": untrained, it predicts nothing (each outcome a failure:
// it is refitted from a training set, which `impacts score` does not have)
[[nodiscard]] std::unique_ptr<ImpactModel> learned_residual_model();

// the grids of the selection, for the tests
inline constexpr double kResidualLengthScales[] = {0.5, 1.0, 2.0, 4.0};
inline constexpr double kResidualRidges[] = {1e-3, 1e-2, 1e-1, 1.0, 10.0};

// Kernel ridge regression in closed form (exposed for its tests): features
// x (n x d, already standardised) and targets y (n x c); for one l and each
// lambda, the fitted values' LOO predictions.
struct KernelRidge {
  explicit KernelRidge(const std::vector<std::vector<double>>& x, double length_scale);
  // leave-one-out predictions of every target column for ridge `lambda`
  [[nodiscard]] std::vector<std::vector<double>> loo(const std::vector<std::vector<double>>& y,
                                                     double lambda) const;
  // dual coefficients alpha = (K + lambda I)^-1 y, n x c
  [[nodiscard]] std::vector<std::vector<double>> coefficients(
      const std::vector<std::vector<double>>& y, double lambda) const;
  // k(a, b), the Gaussian kernel of this length scale
  [[nodiscard]] double kernel(const std::vector<double>& a, const std::vector<double>& b) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
  double length_scale_;
};

}  // namespace pb
