// Test support: the closed-form truth of a frictionless disk on a fixed line
// with a clamped Kelvin-Voigt contact (SPEC §3), written independently of the
// reference solver. Used by the tests of falling_ball and sliding.
//
// The problem. Let n be the line's outward unit normal, d its unit direction,
// p0 a point on it. The disk's centre is c = p0 + s d + (z + R) n, with z the
// gap (z < 0: penetration delta = -z). Gravity g has the components
// g_t = g . d along the line and -a = g . n across it. Without friction the
// tangential motion is s'' = g_t, always. Across the line:
//   free flight   z'' = -a                     (parabola),
//   in contact    m z'' = -m a - K z - c z'    while F = -K z - c z' > 0,
// a damped linear oscillator about z_eq = -m a / K, in closed form:
//   z = z_eq + exp(-zeta w tau) (A cos(w_d tau) + B sin(w_d tau)),
//   w = sqrt(K/m), zeta = c / (2 sqrt(K m)), w_d = w sqrt(1 - zeta^2).
// A contact starts at z = 0 falling; the force clamps when F reaches 0 (the
// law would pull), after which the disk flies free until z = 0 (episode end,
// SPEC §4). Event times come from bisection on the closed forms to machine
// precision.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <variant>
#include <vector>

#include "planarbench/case.hpp"

namespace pb::test {

class DiskOnLineTruth {
 public:
  struct Episode {
    double onset_s = 0.0, offset_s = 0.0;          // s, z = 0 crossings
    double approach_mps = 0.0, separation_mps = 0.0;  // m/s, |z'| there
    double peak_force_n = 0.0, impulse_ns = 0.0, max_penetration_m = 0.0;
    [[nodiscard]] double restitution() const { return separation_mps / approach_mps; }
  };

  // ground = bodies[0] (a fixed half-plane), disk = bodies[1], contacts[0] Kelvin-Voigt
  DiskOnLineTruth(const Case& c, double t_end) {
    const Body& ground = c.bodies.at(0);
    const Body& disk = c.bodies.at(1);
    const auto& kv = std::get<KelvinVoigt>(c.contacts.at(0).law);
    radius_ = std::get<Circle>(disk.shape).radius_m;
    mass_ = disk.mass_kg;
    k_ = kv.stiffness_n_per_m;
    c_ = kv.damping_ns_per_m;
    const double th = ground.angle_rad;
    d_ = Vec2(std::cos(th), std::sin(th));
    n_ = Vec2(-std::sin(th), std::cos(th));
    p0_ = ground.position_m;
    a_ = -c.gravity_mps2.dot(n_);
    g_t_ = c.gravity_mps2.dot(d_);
    s0_ = d_.dot(disk.position_m - p0_);
    vs0_ = d_.dot(disk.velocity_mps);
    const double z0 = n_.dot(disk.position_m - p0_) - radius_;
    const double v0 = n_.dot(disk.velocity_mps);
    w_ = std::sqrt(k_ / mass_);
    zeta_ = c_ / (2.0 * std::sqrt(k_ * mass_));
    wd_ = w_ * std::sqrt(1.0 - zeta_ * zeta_);
    build(z0, v0, t_end);
  }

  // centre position and velocity at t
  [[nodiscard]] Vec2 position(double t) const {
    const double s = s0_ + vs0_ * t + 0.5 * g_t_ * t * t;
    return p0_ + s * d_ + (normal_state(t)[0] + radius_) * n_;
  }
  [[nodiscard]] Vec2 velocity(double t) const {
    return (vs0_ + g_t_ * t) * d_ + normal_state(t)[1] * n_;
  }
  [[nodiscard]] double penetration(double t) const { return std::max(0.0, -normal_state(t)[0]); }
  [[nodiscard]] const std::vector<Episode>& episodes() const { return episodes_; }

 private:
  enum class Kind { free, contact };
  struct Phase {
    Kind kind;
    double t0, z0, v0;
  };

  // z, z' at tau into a phase
  [[nodiscard]] std::array<double, 2> eval(const Phase& p, double tau) const {
    if (p.kind == Kind::free) return {p.z0 + p.v0 * tau - 0.5 * a_ * tau * tau, p.v0 - a_ * tau};
    const double zeq = -mass_ * a_ / k_;
    const double A = p.z0 - zeq;
    const double B = (p.v0 + zeta_ * w_ * A) / wd_;
    const double e = std::exp(-zeta_ * w_ * tau);
    const double cs = std::cos(wd_ * tau);
    const double sn = std::sin(wd_ * tau);
    const double z = zeq + e * (A * cs + B * sn);
    const double v = e * ((-zeta_ * w_ * A + wd_ * B) * cs + (-zeta_ * w_ * B - wd_ * A) * sn);
    return {z, v};
  }
  [[nodiscard]] double force(const Phase& p, double tau) const {
    const auto s = eval(p, tau);
    return -k_ * s[0] - c_ * s[1];
  }
  [[nodiscard]] std::array<double, 2> normal_state(double t) const {
    std::size_t i = 0;
    while (i + 1 < phases_.size() && phases_[i + 1].t0 <= t) ++i;
    return eval(phases_[i], t - phases_[i].t0);
  }

  // first tau in (0, tau_max] with f(tau) crossing to the other sign, scanned
  // at dtau then bisected to machine precision; NaN if none
  static double first_crossing(const std::function<double(double)>& f, double tau_max, double dtau) {
    double lo = 0.0;
    const double f0 = f(dtau * 1e-9);
    for (double hi = dtau; lo < tau_max; lo = hi, hi += dtau) {
      if ((f(hi) > 0.0) != (f0 > 0.0)) {
        for (int i = 0; i < 200; ++i) {
          const double mid = 0.5 * (lo + hi);
          if (mid == lo || mid == hi) break;
          ((f(mid) > 0.0) != (f0 > 0.0) ? hi : lo) = mid;
        }
        return hi;
      }
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

  // maximum of f on (0, T) at a root of its derivative df (one sign change)
  static double max_at_root(const std::function<double(double)>& f,
                            const std::function<double(double)>& df, double T) {
    const double tau = first_crossing(df, T, T / 2000.0);
    return std::isfinite(tau) ? f(tau) : std::max(f(0.0), f(T));
  }

  void build(double z0, double v0, double t_end) {
    double t = 0.0;
    Kind kind = z0 <= 0.0 ? Kind::contact : Kind::free;
    Episode ep;
    if (kind == Kind::contact) ep.onset_s = 0.0, ep.approach_mps = std::max(-v0, 0.0);
    bool released = false;  // clamped free flight inside the penetration
    while (t < t_end) {
      const Phase p{kind, t, z0, v0};
      phases_.push_back(p);
      if (kind == Kind::free && !released) {
        // next onset: z = 0 falling
        const double disc = v0 * v0 + 2.0 * a_ * z0;
        const double tau = (v0 + std::sqrt(disc)) / a_;
        if (t + tau >= t_end) break;
        t += tau;
        const auto s = eval(p, tau);
        z0 = 0.0, v0 = s[1];
        kind = Kind::contact;
        ep = Episode{};
        ep.onset_s = t;
        ep.approach_mps = -v0;
      } else if (kind == Kind::contact) {
        // until the clamp (F = 0) within one damped period
        const double T = 2.0 * std::numbers::pi / wd_;
        const double tau = first_crossing([&](double x) { return force(p, x); }, T, T / 4000.0);
        const double tau_end = std::isfinite(tau) ? tau : t_end - t;
        ep.peak_force_n = std::max(
            ep.peak_force_n,
            max_at_root([&](double x) { return force(p, x); },
                        [&](double x) {
                          const auto s = eval(p, x);
                          const double acc = (-mass_ * a_ - k_ * s[0] - c_ * s[1]) / mass_;
                          return -k_ * s[1] - c_ * acc;
                        },
                        std::min(tau_end, t_end - t)));
        ep.max_penetration_m =
            std::max(ep.max_penetration_m,
                     max_at_root([&](double x) { return -eval(p, x)[0]; },
                                 [&](double x) { return -eval(p, x)[1]; },
                                 std::min(tau_end, t_end - t)));
        if (!std::isfinite(tau) || t + tau >= t_end) break;
        const auto s = eval(p, tau);
        // impulse by momentum balance: m dz' = int(F) - m a T
        ep.impulse_ns += mass_ * (s[1] - v0) + mass_ * a_ * tau;
        t += tau;
        z0 = s[0], v0 = s[1];
        kind = Kind::free;
        released = true;
      } else {
        // clamped flight until z = 0 rising: z0 < 0, v0 > 0
        const double disc = v0 * v0 + 2.0 * a_ * z0;
        const double tau = (v0 - std::sqrt(disc)) / a_;
        if (t + tau >= t_end) break;
        t += tau;
        const auto s = eval(p, tau);
        ep.offset_s = t;
        ep.separation_mps = s[1];
        episodes_.push_back(ep);
        z0 = 0.0, v0 = s[1];
        released = false;
        // the next free phase starts at z = 0 rising
        phases_.push_back(Phase{Kind::free, t, z0, v0});
        const double tau2 = 2.0 * v0 / a_;  // back to z = 0
        if (t + tau2 >= t_end) break;
        t += tau2;
        const auto s2 = eval(phases_.back(), tau2);
        z0 = 0.0, v0 = s2[1];
        kind = Kind::contact;
        ep = Episode{};
        ep.onset_s = t;
        ep.approach_mps = -v0;
      }
    }
    if (ep.onset_s > 0.0 || kind == Kind::contact) open_episode_ = ep;
  }

  double radius_ = 0.0, mass_ = 0.0, k_ = 0.0, c_ = 0.0;
  Vec2 d_, n_, p0_;
  double a_ = 0.0, g_t_ = 0.0, s0_ = 0.0, vs0_ = 0.0;
  double w_ = 0.0, zeta_ = 0.0, wd_ = 0.0;
  std::vector<Phase> phases_;
  std::vector<Episode> episodes_;
  Episode open_episode_;

 public:
  // the episode still open at t_end (sliding: the one contact), with its peak
  // force and penetration so far
  [[nodiscard]] const Episode& open_episode() const { return open_episode_; }
};

}  // namespace pb::test
