#include "planarbench/reference/rk4.hpp"

namespace pb {

ClassicRk4::ClassicRk4(int n) {
  for (Eigen::VectorXd* v : {&k2_, &k3_, &k4_, &tmp_}) v->setZero(n);
}

void ClassicRk4::step(OdeSystem& sys, const Eigen::VectorXd& y0, const Eigen::VectorXd& f0,
                      double h, Eigen::VectorXd& y1, Eigen::VectorXd& f1) {
  tmp_ = y0 + (0.5 * h) * f0;
  sys.derivative(tmp_, k2_);
  tmp_ = y0 + (0.5 * h) * k2_;
  sys.derivative(tmp_, k3_);
  tmp_ = y0 + h * k3_;
  sys.derivative(tmp_, k4_);
  y1 = y0 + (h / 6.0) * (f0 + 2.0 * k2_ + 2.0 * k3_ + k4_);
  sys.derivative(y1, f1);
}

}  // namespace pb
