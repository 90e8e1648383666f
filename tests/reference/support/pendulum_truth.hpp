// Test support for dual_pendulum, written independently of the reference
// solver: the exact swing time of a physical pendulum and the restitution a
// Lankarani-Nikravesh contact produces in a one-dimensional collision.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace pb::test {

// complete elliptic integral of the first kind K(k), modulus k, by the
// arithmetic-geometric mean: K = pi / (2 AGM(1, sqrt(1 - k^2)))
// (Abramowitz & Stegun 17.6)
inline double elliptic_k(double k) {
  double a = 1.0;
  double b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 60 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return std::numbers::pi / (2.0 * a);
}

// time for a physical pendulum released from rest at amplitude theta0 (rad)
// to reach the vertical: a quarter period, K(sin(theta0/2)) / omega0 with
// omega0^2 = m g l / I_pivot (e.g. Landau & Lifshitz, Mechanics, §11)
inline double quarter_period_s(double theta0_rad, double mass_kg, double g_mps2, double arm_m,
                               double pivot_inertia_kgm2) {
  const double omega0 = std::sqrt(mass_kg * g_mps2 * arm_m / pivot_inertia_kgm2);
  return elliptic_k(std::sin(0.5 * theta0_rad)) / omega0;
}

// Restitution of the Lankarani-Nikravesh law (paper eq. 7) in a 1D
// collision m x'' = -K x^n (1 + 3 (1 - e^2)/4 x'/v0), x(0) = 0, x'(0) = v0,
// until x returns to 0. With x = x* X, t = t* T, x* = (m v0^2 / K)^(1/(n+1)),
// t* = x*/v0 it becomes X'' = -X^n (1 + alpha X'), X(0) = 0, X'(0) = 1,
// alpha = 3 (1 - e^2)/4: the result depends on e and n only. Integrated here
// with classic RK4 at a fixed step dT (nondimensional), the return to X = 0
// found by bisection on the length of the last step.
inline double lankarani_nikravesh_restitution(double e, double n, double dT) {
  const double alpha = 0.75 * (1.0 - e * e);
  using S = std::array<double, 2>;
  auto f = [&](const S& s) {
    const double x = s[0] > 0.0 ? s[0] : 0.0;
    return S{s[1], -std::pow(x, n) * (1.0 + alpha * s[1])};
  };
  auto rk4 = [&](const S& s, double h) {
    const S k1 = f(s);
    const S k2 = f({s[0] + 0.5 * h * k1[0], s[1] + 0.5 * h * k1[1]});
    const S k3 = f({s[0] + 0.5 * h * k2[0], s[1] + 0.5 * h * k2[1]});
    const S k4 = f({s[0] + h * k3[0], s[1] + h * k3[1]});
    return S{s[0] + h / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
             s[1] + h / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])};
  };
  S s{0.0, 1.0};
  for (long i = 0; i < 100'000'000; ++i) {
    const S next = rk4(s, dT);
    if (next[0] <= 0.0 && i > 0) {
      double lo = 0.0;
      double hi = dT;
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (rk4(s, mid)[0] > 0.0 ? lo : hi) = mid;
      }
      return -rk4(s, hi)[1];
    }
    s = next;
  }
  return std::nan("");
}

}  // namespace pb::test
