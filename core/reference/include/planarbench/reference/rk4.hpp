// The classic fourth-order Runge-Kutta method (Kutta 1901; HNW I, §II.1,
// Table 1.2), used with a fixed step (integrator=fixed) and by the paper's
// step-size control (integrator=paper).
#pragma once

#include <Eigen/Core>

#include "planarbench/reference/ode_system.hpp"

namespace pb {

class ClassicRk4 {
 public:
  explicit ClassicRk4(int n);

  // One step of size h from (y0, f0 = f(y0)); writes y1 and f1 = f(y1) (the
  // next step's first stage, and the slope for Hermite dense output).
  void step(OdeSystem& sys, const Eigen::VectorXd& y0, const Eigen::VectorXd& f0, double h,
            Eigen::VectorXd& y1, Eigen::VectorXd& f1);

 private:
  Eigen::VectorXd k2_, k3_, k4_, tmp_;
};

}  // namespace pb
