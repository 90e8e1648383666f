#include "jacobi_elliptic.hpp"

#include "root_finding.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace pb::internal {

namespace {

// am(u | m), A&S 16.4.3: with a0 = 1, b0 = sqrt(1 - m), c0 = sqrt(m),
// a_n+1 = (a_n + b_n)/2, b_n+1 = sqrt(a_n b_n), c_n+1 = (a_n - b_n)/2 until
// c_N vanishes; phi_N = 2^N a_N u and phi_n-1 = (phi_n + asin(c_n / a_n
// sin phi_n)) / 2; am = phi_0.
double agm_landen_amplitude(double u, double m) {
  // quadratic convergence: 16 steps are ample even for m within 1e-15 of 1
  constexpr int kMaxSteps = 16;
  std::array<double, kMaxSteps + 1> a{};
  std::array<double, kMaxSteps + 1> c{};
  a[0] = 1.0;
  double b = std::sqrt(1.0 - m);
  c[0] = std::sqrt(m);
  std::size_t n = 0;
  while (n < kMaxSteps && std::abs(c[n]) > std::numeric_limits<double>::epsilon() * a[n]) {
    a[n + 1] = 0.5 * (a[n] + b);
    c[n + 1] = 0.5 * (a[n] - b);
    b = std::sqrt(a[n] * b);
    ++n;
  }
  double phi = std::ldexp(a[n] * u, static_cast<int>(n));
  for (std::size_t i = n; i > 0; --i) phi = 0.5 * (phi + std::asin(c[i] / a[i] * std::sin(phi)));
  return phi;
}

}  // namespace

JacobiValues jacobi_elliptic(double u, double m) {
  JacobiValues v;
  if (m >= 1.0) {
    // the separatrix: am = gd(u) = atan(sinh u) (DLMF 22.5.ii, 4.23.39)
    v.am = std::atan(std::sinh(u));
    v.sn = std::tanh(u);
    v.cn = 1.0 / std::cosh(u);
    v.dn = v.cn;
    return v;
  }
  // reduce u to |u| <= K: am(u + 2 n K) = am(u) + n pi (DLMF 22.16.2), so sn
  // and cn change sign with n and dn is even
  const double quarter = complete_elliptic_k(m);
  const double turns = std::nearbyint(u / (2.0 * quarter));
  const double ur = u - turns * 2.0 * quarter;
  const double am = agm_landen_amplitude(ur, m);
  const double sign = std::fmod(turns, 2.0) == 0.0 ? 1.0 : -1.0;
  v.am = am + turns * std::numbers::pi;
  v.sn = sign * std::sin(am);
  v.cn = sign * std::cos(am);
  // dn^2 = 1 - m sn^2 = cn^2 + (1 - m) sn^2 (DLMF 22.6.1): a sum of two
  // non-negative terms, free of the cancellation of the first form near K
  // and of A&S 16.4.4's 0/0 at u = K
  v.dn = std::sqrt(v.cn * v.cn + (1.0 - m) * v.sn * v.sn);
  return v;
}

double complete_elliptic_k(double m) {
  double a = 1.0;
  double b = std::sqrt(1.0 - m);
  // quadratic convergence: stop when the means agree or stop changing
  for (int i = 0; i < 64 && a != b; ++i) {
    const double next_a = 0.5 * (a + b);
    const double next_b = std::sqrt(a * b);
    if (next_a == a && next_b == b) break;
    a = next_a;
    b = next_b;
  }
  return 0.5 * std::numbers::pi / a;
}

double elliptic_f(double phi, double m) {
  if (m >= 1.0) return std::atanh(std::sin(phi));  // F(phi | 1) = gd^-1(phi), DLMF 19.6.8
  // F(phi + n pi) = F(phi) + 2 n K (DLMF 19.2.10): reduce to |phi| <= pi/2
  const double quarter = complete_elliptic_k(m);
  const double turns = std::nearbyint(phi / std::numbers::pi);
  const double reduced = phi - turns * std::numbers::pi;
  // am is increasing, am(+-K) = +-pi/2: the first u with am(u) >= phi
  const double u = first_true_by_bisection(
      [&](double x) { return jacobi_elliptic(x, m).am >= reduced; }, -quarter, quarter);
  return u + 2.0 * turns * quarter;
}

}  // namespace pb::internal
