// Root finding for the closed forms: bisection to the last bit of a bracket,
// and the first sign change of a quadratic, solved without cancellation.
#pragma once

#include <cmath>

namespace pb::internal {

// Bisection on a predicate that is false at lo and true at hi (a sign change
// of the function it tests): returns the first double at which it is true, to
// the last bit (the bracket shrinks until no double lies between its ends).
// At most about 2100 halvings for any bracket of doubles; no allocation.
template <class Predicate>
[[nodiscard]] double first_true_by_bisection(Predicate&& is_true, double lo, double hi) {
  while (true) {
    const double mid = lo + 0.5 * (hi - lo);
    if (!(mid > lo && mid < hi)) return hi;
    if (is_true(mid)) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
}

// Direction of a crossing through zero.
enum class Crossing { downward = -1, upward = +1 };

// The smallest tau > 0 at which q(tau) = c0 + c1 tau + c2 tau^2 crosses zero in
// the given direction (its slope there has that sign; a tangency is not a
// crossing); +inf when there is none. Roots by the cancellation-free form
// q = -(c1 + sign(c1) sqrt(c1^2 - 4 c2 c0)) / 2, roots q / c2 and c0 / q
// (Press et al., Numerical Recipes, 3rd ed., §5.6).
[[nodiscard]] double first_quadratic_crossing(double c0, double c1, double c2, Crossing dir);

}  // namespace pb::internal
