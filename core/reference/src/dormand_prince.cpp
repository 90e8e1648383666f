#include "planarbench/reference/dormand_prince.hpp"

#include <algorithm>
#include <cmath>

namespace pb {

namespace {

// Butcher tableau, HNW I Table 5.2 (Dormand & Prince 1980)
constexpr double a21 = 1.0 / 5.0;
constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                 a54 = -212.0 / 729.0;
constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                 a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
// 5th-order weights (= row 7 of the tableau, FSAL)
constexpr double b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0,
                 b5 = -2187.0 / 6784.0, b6 = 11.0 / 84.0;
// b - b_hat, the error estimate
constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                 e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
// dense output (Shampine 1986), as in dopri5.f
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

double rms(const Eigen::VectorXd& v) {
  return v.size() > 0 ? std::sqrt(v.squaredNorm() / static_cast<double>(v.size())) : 0.0;
}

}  // namespace

DormandPrince5::DormandPrince5(int n) {
  for (Eigen::VectorXd* v : {&k2_, &k3_, &k4_, &k5_, &k6_, &tmp_}) v->setZero(n);
}

double DormandPrince5::step(OdeSystem& sys, const Eigen::VectorXd& y0, const Eigen::VectorXd& f0,
                            double h, double rtol, double atol, Eigen::VectorXd& y1,
                            Eigen::VectorXd& f1) {
  const Eigen::VectorXd& k1 = f0;
  tmp_ = y0 + h * a21 * k1;
  sys.derivative(tmp_, k2_);
  tmp_ = y0 + h * (a31 * k1 + a32 * k2_);
  sys.derivative(tmp_, k3_);
  tmp_ = y0 + h * (a41 * k1 + a42 * k2_ + a43 * k3_);
  sys.derivative(tmp_, k4_);
  tmp_ = y0 + h * (a51 * k1 + a52 * k2_ + a53 * k3_ + a54 * k4_);
  sys.derivative(tmp_, k5_);
  tmp_ = y0 + h * (a61 * k1 + a62 * k2_ + a63 * k3_ + a64 * k4_ + a65 * k5_);
  sys.derivative(tmp_, k6_);
  y1 = y0 + h * (b1 * k1 + b3 * k3_ + b4 * k4_ + b5 * k5_ + b6 * k6_);
  sys.derivative(y1, f1);
  // embedded error, scaled component-wise
  tmp_ = h * (e1 * k1 + e3 * k3_ + e4 * k4_ + e5 * k5_ + e6 * k6_ + e7 * f1);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < y0.size(); ++i) {
    const double sc = atol + rtol * std::max(std::abs(y0[i]), std::abs(y1[i]));
    const double r = tmp_[i] / sc;
    sum += r * r;
  }
  return y0.size() > 0 ? std::sqrt(sum / static_cast<double>(y0.size())) : 0.0;
}

void DormandPrince5::dense(double t0_s, double h, const Eigen::VectorXd& y0,
                           const Eigen::VectorXd& y1, const Eigen::VectorXd& f0,
                           const Eigen::VectorXd& f1, DenseSegment& out) const {
  out.kind = DenseSegment::Kind::dopri5;
  out.t0_s = t0_s;
  out.h_s = h;
  out.c0 = y0;
  out.c1 = y1 - y0;
  out.c2 = h * f0 - out.c1;
  out.c3 = out.c1 - h * f1 - out.c2;
  out.c4 = h * (d1 * f0 + d3 * k3_ + d4 * k4_ + d5 * k5_ + d6 * k6_ + d7 * f1);
}

double DormandPrince5::initial_step(OdeSystem& sys, const Eigen::VectorXd& y0,
                                    const Eigen::VectorXd& f0, double rtol, double atol,
                                    double h_max) {
  const Eigen::VectorXd sc = (atol + rtol * y0.array().abs()).matrix();
  const double d0 = rms(y0.cwiseQuotient(sc));
  const double d1n = rms(f0.cwiseQuotient(sc));
  double h0 = (d0 < 1e-5 || d1n < 1e-5) ? 1e-6 : 0.01 * d0 / d1n;
  h0 = std::min(h0, h_max);
  tmp_ = y0 + h0 * f0;
  sys.derivative(tmp_, k2_);
  const double d2 = rms((k2_ - f0).cwiseQuotient(sc)) / h0;
  const double dm = std::max(d1n, d2);
  const double h1 = dm <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / dm, 1.0 / 5.0);
  return std::min({100.0 * h0, h1, h_max});
}

}  // namespace pb
