// The free motion of a damped linear oscillator, x'' + 2 sigma x' + w0^2 x = 0,
// in closed form for every damping (under-, critically and over-damped), with
// its stationary points and an exponential envelope. The contact phase of the
// disk on a line is this motion about the static penetration; the contact
// force and the velocity obey the same equation, so each is a DampedMode too.
#pragma once

namespace pb::internal {

class DampedMode {
 public:
  // sigma = c / (2 m), 1/s; omega0_sq = k / m, 1/s^2; x0, v0 = x(0), x'(0)
  DampedMode(double sigma_per_s, double omega0_sq_per_s2, double x0, double v0);

  // x(tau) and x'(tau), tau >= 0 the time since the start, s
  [[nodiscard]] double value(double tau_s) const;
  [[nodiscard]] double rate(double tau_s) const;
  // x' as a DampedMode of its own (the same equation, initial x'(0), x''(0))
  [[nodiscard]] DampedMode derivative() const;

  // The k-th (k = 0, 1, ...) root of x' in tau > 0, ascending; +inf when
  // there is none (an over- or critically damped motion has at most one).
  // Between two consecutive ones x is monotone: they bracket every root of
  // x - constant exactly, without sampling.
  [[nodiscard]] double stationary_point(int k) const;

  // |x(tau)| <= envelope_amplitude() * exp(-envelope_rate() * tau) for all tau >= 0
  [[nodiscard]] double envelope_amplitude() const { return envelope_amplitude_; }
  [[nodiscard]] double envelope_rate() const { return envelope_rate_per_s_; }

  // the damped angular frequency, rad/s (0 unless under-damped)
  [[nodiscard]] double damped_frequency() const { return omega_d_; }

 private:
  enum class Regime { under, critical, over };
  // e^(-sigma tau) C(tau) and e^(-sigma tau) S(tau), with C'' = D C, S'' = D S,
  // C(0) = 1, C'(0) = 0, S(0) = 0, S'(0) = 1, D = sigma^2 - w0^2
  void basis(double tau_s, double& ec, double& es) const;

  double sigma_ = 0.0;      // 1/s
  double omega0_sq_ = 0.0;  // 1/s^2
  double x0_ = 0.0;
  double v0_ = 0.0;
  Regime regime_ = Regime::under;
  double omega_d_ = 0.0;  // rad/s, sqrt(w0^2 - sigma^2) when under-damped
  double beta_ = 0.0;     // 1/s, sqrt(sigma^2 - w0^2) when over-damped
  double envelope_amplitude_ = 0.0;
  double envelope_rate_per_s_ = 0.0;
};

}  // namespace pb::internal
