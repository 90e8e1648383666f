// Dormand-Prince 5(4), the embedded explicit Runge-Kutta pair of
// J. R. Dormand and P. J. Prince (1980), as in Hairer, Norsett, Wanner,
// Solving Ordinary Differential Equations I (2nd ed., 1993), §II.4-II.5
// (Table 5.2) and their code dopri5: 7 stages, first same as last (the last
// stage is f at the new point), local extrapolation (the 5th-order solution
// is propagated), error estimated by the embedded 4th-order solution.
#pragma once

#include <Eigen/Core>

#include "planarbench/reference/dense_output.hpp"
#include "planarbench/reference/ode_system.hpp"

namespace pb {

class DormandPrince5 {
 public:
  explicit DormandPrince5(int n);

  // One step of size h from (y0, f0 = f(y0)). Writes y1 and f1 = f(y1) (the
  // 7th stage) and returns the scaled error norm (HNW I, eq. II.4.11):
  // sqrt(mean(((y1 - y1_hat)_i / (atol + rtol max(|y0_i|, |y1_i|)))^2)),
  // <= 1 means the step meets the tolerance.
  double step(OdeSystem& sys, const Eigen::VectorXd& y0, const Eigen::VectorXd& f0, double h,
              double rtol, double atol, Eigen::VectorXd& y1, Eigen::VectorXd& f1);

  // dense output of the last step taken (same y0, f0, y1, f1 as that step)
  void dense(double t0_s, double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
             const Eigen::VectorXd& f0, const Eigen::VectorXd& f1, DenseSegment& out) const;

  // Starting step size (HNW I, §II.4, "Starting Step Size", order 5).
  double initial_step(OdeSystem& sys, const Eigen::VectorXd& y0, const Eigen::VectorXd& f0,
                      double rtol, double atol, double h_max);

 private:
  Eigen::VectorXd k2_, k3_, k4_, k5_, k6_, tmp_;
};

}  // namespace pb
