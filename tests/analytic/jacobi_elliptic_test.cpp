// Tests for core/analytic/jacobi_elliptic.cpp
#include "jacobi_elliptic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "independent_integrators.hpp"

namespace pb::internal {
namespace {

// The limits m = 0 (circular functions) and m = 1 (hyperbolic), DLMF 22.5.ii.
TEST(JacobiElliptic, Limits) {
  for (double u : {-3.0, -0.4, 0.0, 0.7, 2.5, 10.0}) {
    const JacobiValues c = jacobi_elliptic(u, 0.0);
    // the reduction u - 2 n K with K = pi/2 rounds by a few ulp of u
    EXPECT_NEAR(c.sn, std::sin(u), 4e-16 * std::max(1.0, std::abs(u)));
    EXPECT_NEAR(c.cn, std::cos(u), 4e-16 * std::max(1.0, std::abs(u)));
    EXPECT_NEAR(c.dn, 1.0, 2e-16);
    EXPECT_NEAR(c.am, u, 1e-14);
    const JacobiValues h = jacobi_elliptic(u, 1.0);
    EXPECT_NEAR(h.sn, std::tanh(u), 1e-15);
    EXPECT_NEAR(h.cn, 1.0 / std::cosh(u), 1e-15);
    EXPECT_NEAR(h.dn, 1.0 / std::cosh(u), 1e-15);
  }
}

class JacobiParameter : public ::testing::TestWithParam<double> {};

// am inverts the incomplete elliptic integral of the first kind:
// F(am(u | m) | k) = u, with std::ellint_1 (libstdc++'s Carlson R_F, code
// independent of the AGM/Landen evaluation under test). Not at m = 1 - 1e-6,
// where libstdc++ 12 itself is off by 7e-12 relative (its K(k) against the AGM).
TEST_P(JacobiParameter, AmplitudeInvertsEllint1) {
  const double m = GetParam();
  if (m > 0.9999) GTEST_SKIP() << "std::ellint_1 is not accurate this close to m = 1";
  const double k = std::sqrt(m);
  for (double u : {0.01, 0.3, 1.0, 1.7, 2.9, 5.3, -0.8, -4.0}) {
    const JacobiValues v = jacobi_elliptic(u, m);
    // a few ulp of u (libstdc++'s own K is 6e-16 relative off at m = 0.146,
    // against a 50-digit AGM), times dF/d(am) = 1/dn, which magnifies the
    // rounding of am near am = pi/2
    EXPECT_NEAR(std::ellint_1(k, v.am), u, 2e-15 * std::max(1.0, std::abs(u)) / v.dn)
        << "m=" << m << " u=" << u;
  }
}

// sn^2 + cn^2 = 1, dn^2 + m sn^2 = 1 (DLMF 22.6.1); sn(K) = 1, cn(K) = 0,
// dn(K) = sqrt(1 - m) (DLMF 22.5.i); 4K-periodic sn, 2K-antiperiodic.
TEST_P(JacobiParameter, IdentitiesAndSpecialValues) {
  const double m = GetParam();
  const double quarter = testing::complete_elliptic_k_by_agm(m);
  for (double u : {0.2, 1.1, 2.4, 7.7}) {
    const JacobiValues v = jacobi_elliptic(u, m);
    // rounding of squares and sums: a few ulp of 1
    EXPECT_NEAR(v.sn * v.sn + v.cn * v.cn, 1.0, 4e-16);
    EXPECT_NEAR(v.dn * v.dn + m * v.sn * v.sn, 1.0, 4e-16);
    // a shift by 2K rounds u + 2K and the reduction: a few ulp of 8 + 2K,
    // times the slope of sn, cn, dn (<= 1)
    const JacobiValues w = jacobi_elliptic(u + 2.0 * quarter, m);
    const double tol = 8e-16 * (u + 2.0 * quarter);
    EXPECT_NEAR(w.sn, -v.sn, tol);
    EXPECT_NEAR(w.cn, -v.cn, tol);
    EXPECT_NEAR(w.dn, v.dn, tol);
    EXPECT_NEAR(w.am, v.am + std::numbers::pi, tol);
  }
  // at K: cn's slope there is -dn(K) = -sqrt(1 - m), so the rounding of K
  // and of am (a few ulp of pi/2) shows in cn and am only
  const JacobiValues at_k = jacobi_elliptic(quarter, m);
  EXPECT_NEAR(at_k.sn, 1.0, 2e-16);
  EXPECT_NEAR(at_k.cn, 0.0, 1e-15);
  EXPECT_NEAR(at_k.dn, std::sqrt(1.0 - m), 1e-15);
  EXPECT_NEAR(at_k.am, 0.5 * std::numbers::pi, 1e-15 / std::sqrt(1.0 - m));
}

// d sn / du = cn dn and d am / du = dn (DLMF 22.13.1, 22.16.1), by a central
// difference with h = 1e-5 (truncation ~h^2 = 1e-10, rounding ~1e-11).
TEST_P(JacobiParameter, Derivatives) {
  const double m = GetParam();
  const double h = 1e-5;
  for (double u : {0.3, 1.4, 3.3}) {
    const JacobiValues v = jacobi_elliptic(u, m);
    const JacobiValues p = jacobi_elliptic(u + h, m);
    const JacobiValues q = jacobi_elliptic(u - h, m);
    EXPECT_NEAR((p.sn - q.sn) / (2.0 * h), v.cn * v.dn, 1e-9);
    EXPECT_NEAR((p.am - q.am) / (2.0 * h), v.dn, 1e-9);
  }
}

// K(m) and F(phi | m): against the test's own AGM and std::ellint_1 (where
// that is accurate), and F inverts am.
TEST_P(JacobiParameter, CompleteAndIncompleteIntegrals) {
  const double m = GetParam();
  const double quarter = testing::complete_elliptic_k_by_agm(m);
  EXPECT_NEAR(complete_elliptic_k(m), quarter, 4e-16 * quarter);
  for (double phi : {0.1, 0.9, 1.5, 2.8, -1.2, 7.0}) {
    const double u = elliptic_f(phi, m);
    // am(F(phi)) = phi: bisection to the last bit of u, times the slope dn
    EXPECT_NEAR(jacobi_elliptic(u, m).am, phi, 8e-16 * std::max(1.0, std::abs(phi)));
    if (m <= 0.9999) {
      // against libstdc++: a few ulp of F, magnified near pi/2 by 1/dn
      EXPECT_NEAR(u, std::ellint_1(std::sqrt(m), phi),
                  1e-15 * std::max(1.0, std::abs(u)) / std::sqrt(1.0 - m));
    }
  }
}

// m = 0.1464 is the dual pendulum's k^2 = sin^2(22.5 deg); 0.999999 a swing
// near the top
INSTANTIATE_TEST_SUITE_P(Parameters, JacobiParameter,
                         ::testing::Values(1e-12, 0.05, 0.14644660940672624, 0.5, 0.9, 0.999999));

}  // namespace
}  // namespace pb::internal
