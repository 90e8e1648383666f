// Jacobi elliptic functions am, sn, cn, dn of argument u and parameter
// m = k^2 in [0, 1], by the arithmetic-geometric mean and descending Landen
// transformation (Abramowitz & Stegun 16.4.3; DLMF 22.20(ii)). The exact
// large-amplitude pendulum is written with them.
#pragma once

namespace pb::internal {

struct JacobiValues {
  double am = 0.0;  // amplitude, rad (continuous in u, grows by pi every 2K)
  double sn = 0.0;
  double cn = 0.0;
  double dn = 0.0;
};

// 0 <= m <= 1 (m = 1: am = gd(u), sn = tanh u, cn = dn = sech u, DLMF 22.5.ii)
[[nodiscard]] JacobiValues jacobi_elliptic(double u, double m);

// K(m) = pi / (2 AGM(1, sqrt(1 - m))), 0 <= m < 1 (A&S 17.6.1). Written out
// rather than std::comp_ellint_1: libstdc++ 12 loses 7e-12 of it at m = 1 - 1e-6.
[[nodiscard]] double complete_elliptic_k(double m);

// F(phi | m), the incomplete integral of the first kind, as the inverse of
// am above (bisection to the last bit), so that am(F(phi | m) | m) = phi
// to rounding; any phi, 0 <= m <= 1 (m = 1: |phi| < pi/2).
[[nodiscard]] double elliptic_f(double phi, double m);

}  // namespace pb::internal
