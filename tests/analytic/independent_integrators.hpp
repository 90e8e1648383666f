// Independent numerical integrations for the tests of core/analytic/: the
// truths the closed forms are checked against. Written apart from the code
// under test and sharing nothing with it but the physics: classic RK4
// (Hairer, Norsett & Wanner, Solving ODEs I, §II.1) in world x-y coordinates,
// with each switch of the clamped contact force located by bisection on the
// length of the step that crosses it.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <vector>

namespace pb::testing {

using V2 = Eigen::Vector2d;

// A disk of mass m and radius R above a fixed line (a point of it and its
// outward unit normal), gravity g, Kelvin-Voigt contact F = K delta + c
// delta_dot along the normal, clamped at F >= 0.
struct DiskLineProblem {
  double mass_kg = 1.0;
  double radius_m = 0.5;
  double stiffness_n_per_m = 1e4;
  double damping_ns_per_m = 10.0;
  V2 gravity_mps2 = V2(0.0, -9.8066);
  V2 line_point_m = V2::Zero();
  V2 line_normal = V2(0.0, 1.0);
  V2 position0_m = V2::Zero();
  V2 velocity0_mps = V2::Zero();
};

class DiskLineIntegrator {
 public:
  DiskLineIntegrator(const DiskLineProblem& p, double max_step_s) : p_(p), h_max_(max_step_s) {
    y_ = {p.position0_m.x(), p.position0_m.y(), p.velocity0_mps.x(), p.velocity0_mps.y()};
    pressed_ = is_pressed(y_);
  }

  // integrates to t_s exactly (the last step is shortened). Time is counted
  // as t_base + n h and the state summed with Kahan compensation: over 1e6
  // steps plain summation drifts by ~1e-11 s and ~1e-11 m, more than the
  // errors these tests look for.
  void advance_to(double t_s) {
    while (t_ < t_s) {
      const bool last = t_s - t_ <= h_max_;
      const double h = last ? t_s - t_ : h_max_;
      const State d = increment(y_, h, pressed_);
      const State next{y_[0] + d[0], y_[1] + d[1], y_[2] + d[2], y_[3] + d[3]};
      if (is_pressed(next) != pressed_) {
        // the force switches inside this step: the first sub-step at which it
        // has switched, by bisection to the last bit of its length
        double lo = 0.0;
        double hi = h;
        for (;;) {
          const double mid = lo + 0.5 * (hi - lo);
          if (!(mid > lo && mid < hi)) break;
          (is_pressed(step(y_, mid, pressed_)) != pressed_ ? hi : lo) = mid;
        }
        const bool onset = !pressed_ && penetration(y_) <= 0.0;
        accept(increment(y_, hi, pressed_));
        t_ += hi;
        restart_clock();
        if (!pressed_) {
          if (onset)
            onsets.push_back(t_);
          else
            recontacts.push_back(t_);
        } else {
          clamps.push_back(t_);
          // without damping the force and the penetration vanish together
          if (penetration(y_) <= 0.0) offsets.push_back(t_);
        }
        pressed_ = !pressed_;
        continue;
      }
      if (!pressed_ && penetration(y_) > 0.0 && penetration(next) <= 0.0) {
        // the disk leaves the line during a free step: locate the offset
        double lo = 0.0;
        double hi = h;
        for (;;) {
          const double mid = lo + 0.5 * (hi - lo);
          if (!(mid > lo && mid < hi)) break;
          (penetration(step(y_, mid, false)) <= 0.0 ? hi : lo) = mid;
        }
        offsets.push_back(t_ + hi);
      }
      accept(d);
      if (last) {
        t_ = t_s;
        restart_clock();
      } else {
        ++steps_;
        t_ = t_base_ + static_cast<double>(steps_) * h_max_;
      }
    }
  }

  [[nodiscard]] double time() const { return t_; }
  [[nodiscard]] V2 position() const { return {y_[0], y_[1]}; }
  [[nodiscard]] V2 velocity() const { return {y_[2], y_[3]}; }
  [[nodiscard]] double penetration() const { return penetration(y_); }
  [[nodiscard]] double force() const { return pressed_ ? std::max(0.0, spring(y_)) : 0.0; }

  std::vector<double> onsets;      // s, penetration becomes positive
  std::vector<double> clamps;      // s, the force returns to zero
  std::vector<double> recontacts;  // s, the force turns positive again while penetrating
  std::vector<double> offsets;     // s, penetration back to zero

 private:
  using State = std::array<double, 4>;  // x, y, vx, vy

  [[nodiscard]] double penetration(const State& y) const {
    return p_.radius_m - (V2(y[0], y[1]) - p_.line_point_m).dot(p_.line_normal);
  }
  // K delta + c delta_dot, unclamped
  [[nodiscard]] double spring(const State& y) const {
    const double rate = -V2(y[2], y[3]).dot(p_.line_normal);
    return p_.stiffness_n_per_m * penetration(y) + p_.damping_ns_per_m * rate;
  }
  [[nodiscard]] bool is_pressed(const State& y) const {
    return penetration(y) > 0.0 && spring(y) > 0.0;
  }
  // the smooth right-hand side of one mode (pressed: the unclamped law)
  [[nodiscard]] State rhs(const State& y, bool pressed) const {
    V2 acc = p_.gravity_mps2;
    if (pressed) acc += spring(y) / p_.mass_kg * p_.line_normal;
    return {y[2], y[3], acc.x(), acc.y()};
  }
  [[nodiscard]] State step(const State& y, double h, bool pressed) const {
    const State d = increment(y, h, pressed);
    return {y[0] + d[0], y[1] + d[1], y[2] + d[2], y[3] + d[3]};
  }
  // the RK4 increment of one step
  [[nodiscard]] State increment(const State& y, double h, bool pressed) const {
    auto axpy = [](const State& a, double s, const State& b) {
      return State{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2], a[3] + s * b[3]};
    };
    const State k1 = rhs(y, pressed);
    const State k2 = rhs(axpy(y, 0.5 * h, k1), pressed);
    const State k3 = rhs(axpy(y, 0.5 * h, k2), pressed);
    const State k4 = rhs(axpy(y, h, k3), pressed);
    State out;
    for (std::size_t i = 0; i < 4; ++i) {
      out[i] = h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    return out;
  }

  // y += d with Kahan compensation (Higham, Accuracy and Stability of
  // Numerical Algorithms, §4.3)
  void accept(const State& d) {
    for (std::size_t i = 0; i < 4; ++i) {
      const double inc = d[i] - comp_[i];
      const double sum = y_[i] + inc;
      comp_[i] = (sum - y_[i]) - inc;
      y_[i] = sum;
    }
  }
  void restart_clock() {
    t_base_ = t_;
    steps_ = 0;
  }

  DiskLineProblem p_;
  double h_max_;
  State y_{};
  State comp_{};
  double t_ = 0.0;
  double t_base_ = 0.0;
  long steps_ = 0;
  bool pressed_ = false;
};

// phi'' = -w0^2 sin(phi) by RK4 with step h from (phi0, rate0) over t_s;
// returns {phi, phi'}
inline std::array<double, 2> pendulum_rk4(double phi0, double rate0, double omega0_sq, double t_s,
                                          double h) {
  std::array<double, 2> y{phi0, rate0};
  auto f = [&](const std::array<double, 2>& s) {
    return std::array<double, 2>{s[1], -omega0_sq * std::sin(s[0])};
  };
  const long n = static_cast<long>(std::ceil(t_s / h));
  const double dt = t_s / static_cast<double>(n);
  for (long i = 0; i < n; ++i) {
    const auto k1 = f(y);
    const auto k2 = f({y[0] + 0.5 * dt * k1[0], y[1] + 0.5 * dt * k1[1]});
    const auto k3 = f({y[0] + 0.5 * dt * k2[0], y[1] + 0.5 * dt * k2[1]});
    const auto k4 = f({y[0] + dt * k3[0], y[1] + dt * k3[1]});
    y[0] += dt / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]);
    y[1] += dt / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]);
  }
  return y;
}

// K(m) = pi / (2 AGM(1, sqrt(1 - m))) (Abramowitz & Stegun 17.6.1), m = k^2
// the parameter (not the modulus: 1 - k^2 would lose the digits of 1 - m
// near m = 1), independent of std::comp_ellint_1
inline double complete_elliptic_k_by_agm(double m) {
  double a = 1.0;
  double b = std::sqrt(1.0 - m);
  for (int i = 0; i < 40 && a != b; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return 3.14159265358979323846 / (2.0 * a);
}

// The nearest point of the ellipse (a cos t, b sin t) to p by brute force:
// the best of 4096 samples of t, then Newton on d/dt |p - q(t)|^2 / 2 =
// -(p - q) . q'(t) = 0 (independent of Eberly's method in the code).
inline V2 nearest_on_ellipse_brute(double a, double b, const V2& p) {
  auto q = [&](double t) { return V2(a * std::cos(t), b * std::sin(t)); };
  double best_t = 0.0;
  double best = 1e300;
  for (int i = 0; i < 4096; ++i) {
    const double t = 2.0 * 3.14159265358979323846 * i / 4096.0;
    const double d = (p - q(t)).squaredNorm();
    if (d < best) {
      best = d;
      best_t = t;
    }
  }
  double t = best_t;
  for (int it = 0; it < 50; ++it) {
    const V2 dq(-a * std::sin(t), b * std::cos(t));
    const V2 ddq(-a * std::cos(t), -b * std::sin(t));
    const V2 r = p - q(t);
    const double step = -r.dot(dq) / (dq.dot(dq) - r.dot(ddq));
    t -= step;
    if (std::abs(step) < 1e-16) break;
  }
  return q(t);
}

}  // namespace pb::testing
