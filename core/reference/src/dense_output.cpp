#include "planarbench/reference/dense_output.hpp"

namespace pb {

void DenseSegment::evaluate(double t_s, Eigen::VectorXd& y) const {
  const double th = h_s > 0.0 ? (t_s - t0_s) / h_s : 1.0;
  if (kind == Kind::dopri5) {
    const double th1 = 1.0 - th;
    y = c0 + th * (c1 + th1 * (c2 + th * (c3 + th1 * c4)));
    return;
  }
  // cubic Hermite basis
  const double th2 = th * th;
  const double th3 = th2 * th;
  const double h00 = 2.0 * th3 - 3.0 * th2 + 1.0;
  const double h10 = th3 - 2.0 * th2 + th;
  const double h01 = -2.0 * th3 + 3.0 * th2;
  const double h11 = th3 - th2;
  y = h00 * c0 + h01 * c1 + (h10 * h_s) * c2 + (h11 * h_s) * c3;
}

void DenseSegment::set_hermite(double t0, double h, const Eigen::VectorXd& y0,
                               const Eigen::VectorXd& y1, const Eigen::VectorXd& f0,
                               const Eigen::VectorXd& f1) {
  kind = Kind::hermite;
  t0_s = t0;
  h_s = h;
  c0 = y0;
  c1 = y1;
  c2 = f0;
  c3 = f1;
}

}  // namespace pb
