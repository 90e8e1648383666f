#include "damped_mode.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace pb::internal {

// With y = x e^(sigma tau) the equation becomes y'' = D y, D = sigma^2 - w0^2,
// so x = e^(-sigma tau) (x0 C + (v0 + sigma x0) S) and
// x' = e^(-sigma tau) (v0 C - (sigma v0 + w0^2 x0) S), with C = cos(w_d tau),
// S = sin(w_d tau) / w_d when D < 0 (w_d^2 = -D), C = 1, S = tau when D = 0,
// C = cosh(b tau), S = sinh(b tau) / b when D > 0 (b^2 = D)
// (any text on linear vibration, e.g. Meirovitch, Fundamentals of Vibrations, §2.5).
DampedMode::DampedMode(double sigma_per_s, double omega0_sq_per_s2, double x0, double v0)
    : sigma_(sigma_per_s), omega0_sq_(omega0_sq_per_s2), x0_(x0), v0_(v0) {
  // D as a product of (sigma - w0)(sigma + w0): no cancellation near critical
  const double omega0 = std::sqrt(omega0_sq_);
  const double d = (sigma_ - omega0) * (sigma_ + omega0);
  const double y_rate0 = std::abs(v0_ + sigma_ * x0_);
  if (d < 0.0) {
    regime_ = Regime::under;
    omega_d_ = std::sqrt(-d);
    envelope_amplitude_ = std::hypot(x0_, y_rate0 / omega_d_);
    envelope_rate_per_s_ = sigma_;
  } else {
    regime_ = d > 0.0 ? Regime::over : Regime::critical;
    beta_ = d > 0.0 ? std::sqrt(d) : 0.0;
    // |C| <= e^(b tau), |S| <= tau e^(b tau), and tau e^(-r tau) <= 2/(e r) e^(-r tau / 2)
    // with r = sigma - b = w0^2 / (sigma + b) > 0
    const double r = omega0_sq_ / (sigma_ + beta_);
    envelope_rate_per_s_ = 0.5 * r;
    envelope_amplitude_ = r > 0.0 ? std::abs(x0_) + y_rate0 * 2.0 / (std::numbers::e * r)
                                  : std::numeric_limits<double>::infinity();
  }
}

void DampedMode::basis(double tau_s, double& ec, double& es) const {
  switch (regime_) {
    case Regime::under: {
      const double decay = std::exp(-sigma_ * tau_s);
      ec = decay * std::cos(omega_d_ * tau_s);
      es = decay * std::sin(omega_d_ * tau_s) / omega_d_;
      return;
    }
    case Regime::critical: {
      const double decay = std::exp(-sigma_ * tau_s);
      ec = decay;
      es = decay * tau_s;
      return;
    }
    case Regime::over: {
      const double bt = beta_ * tau_s;
      if (bt < 1.0) {
        // small b tau: sinh(b tau) / b without cancellation
        const double decay = std::exp(-sigma_ * tau_s);
        ec = decay * std::cosh(bt);
        es = decay * std::sinh(bt) / beta_;
      } else {
        // exponentials combined first so that neither overflows:
        // slow rate b - sigma = -w0^2 / (sigma + b), fast rate -(sigma + b)
        const double slow = std::exp(-omega0_sq_ / (sigma_ + beta_) * tau_s);
        const double fast = std::exp(-(sigma_ + beta_) * tau_s);
        ec = 0.5 * (slow + fast);
        es = 0.5 * (slow - fast) / beta_;
      }
      return;
    }
  }
}

double DampedMode::value(double tau_s) const {
  double ec = 0.0;
  double es = 0.0;
  basis(tau_s, ec, es);
  return x0_ * ec + (v0_ + sigma_ * x0_) * es;
}

double DampedMode::rate(double tau_s) const {
  double ec = 0.0;
  double es = 0.0;
  basis(tau_s, ec, es);
  return v0_ * ec - (sigma_ * v0_ + omega0_sq_ * x0_) * es;
}

DampedMode DampedMode::derivative() const {
  // x''(0) from the equation of motion
  const double a0 = -2.0 * sigma_ * v0_ - omega0_sq_ * x0_;
  return DampedMode(sigma_, omega0_sq_, v0_, a0);
}

double DampedMode::stationary_point(int k) const {
  constexpr double none = std::numeric_limits<double>::infinity();
  // x' = 0  <=>  v0 C = p S, p = sigma v0 + w0^2 x0
  const double p = sigma_ * v0_ + omega0_sq_ * x0_;
  if (v0_ == 0.0 && p == 0.0) return none;  // x is identically zero
  switch (regime_) {
    case Regime::under: {
      // w_d v0 cos(th) = p sin(th): th = alpha + n pi, alpha = atan2(w_d v0, p)
      const double alpha = std::atan2(omega_d_ * v0_, p);
      const double first = alpha > 0.0 ? alpha : alpha + std::numbers::pi;
      return (first + std::numbers::pi * static_cast<double>(k)) / omega_d_;
    }
    case Regime::critical: {
      // v0 = p tau
      if (k > 0 || p == 0.0) return none;
      const double tau = v0_ / p;
      return tau > 0.0 ? tau : none;
    }
    case Regime::over: {
      // tanh(b tau) = b v0 / p
      if (k > 0 || p == 0.0) return none;
      const double ratio = beta_ * v0_ / p;
      if (!(ratio > 0.0 && ratio < 1.0)) return none;
      return std::atanh(ratio) / beta_;
    }
  }
  return none;
}

}  // namespace pb::internal
