// Locating an event inside a step: the first step length tau in (lo, hi] at
// which a predicate ("the contact phase must change") becomes true, by a
// bracketing root finder on a scalar event function g(tau).
//   illinois  regula falsi with the Illinois modification (Dowell & Jarratt
//             1971), superlinear; each new point kept tol/2 inside the
//             bracket, so that once one end has converged the next point
//             closes the bracket (without it, rounding noise near the root
//             made it crawl: 39 calls instead of 9 on x^3 + 2x - 1 to 1e-15);
//             bisection after 60 iterations as a safeguard;
//   bisection halving only (the paper's onset location, §3.1).
// The caller evaluates g by re-taking the step from its start with length
// tau, so the located point lies on the integrator's own solution.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

namespace pb {

enum class RootMethod { illinois, bisection };

struct Bracket {
  double lo = 0.0;   // predicate false here
  double hi = 0.0;   // predicate true here (the located point)
  int iterations = 0;
};

// `probe(tau)` returns {g(tau), predicate(tau)}; predicate(lo) is false and
// predicate(hi) true, with g_lo, g_hi the values there. Stops when
// hi - lo <= tol or after max_iterations.
template <class Probe>
Bracket locate_event(Probe&& probe, double lo, double g_lo, double hi, double g_hi, double tol,
                     RootMethod method, int max_iterations = 200) {
  Bracket b{lo, hi, 0};
  int side = 0;  // which end moved last: -1 lo, +1 hi
  while (b.hi - b.lo > tol && b.iterations < max_iterations) {
    ++b.iterations;
    const double mid = 0.5 * (b.lo + b.hi);
    double x = mid;
    if (method == RootMethod::illinois && b.iterations <= 60 && g_lo != g_hi) {
      // secant through the bracket ends, kept tol/2 inside
      x = b.lo - g_lo * (b.hi - b.lo) / (g_hi - g_lo);
      x = std::min(std::max(x, b.lo + 0.5 * tol), b.hi - 0.5 * tol);
      if (!(x > b.lo && x < b.hi)) x = mid;
    }
    if (!(x > b.lo && x < b.hi)) break;  // the bracket cannot shrink further
    const std::pair<double, bool> r = probe(x);
    if (r.second) {
      b.hi = x;
      g_hi = r.first;
      if (side == +1) g_lo *= 0.5;  // Illinois: the other end stalls, halve its value
      side = +1;
    } else {
      b.lo = x;
      g_lo = r.first;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    }
  }
  return b;
}

}  // namespace pb
