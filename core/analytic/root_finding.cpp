#include "root_finding.hpp"

#include <algorithm>
#include <limits>

namespace pb::internal {

double first_quadratic_crossing(double c0, double c1, double c2, Crossing dir) {
  constexpr double none = std::numeric_limits<double>::infinity();
  const double want = static_cast<double>(dir);
  // linear: one root, slope c1
  if (c2 == 0.0) {
    if (c1 == 0.0 || c1 * want < 0.0) return none;
    const double r = -c0 / c1;
    return r > 0.0 ? r : none;
  }
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  // no real root, or a double root (a tangency, not a crossing)
  if (!(disc > 0.0)) return none;
  const double s = std::copysign(std::sqrt(disc), c1 == 0.0 ? 1.0 : c1);
  const double q = -0.5 * (c1 + s);
  // slopes at the two roots, q'(r) = c1 + 2 c2 r: -s at q / c2 and +s at c0 / q
  double best = none;
  const double r1 = q / c2;
  if (-s * want > 0.0 && r1 > 0.0) best = std::min(best, r1);
  if (q != 0.0) {
    const double r2 = c0 / q;
    if (s * want > 0.0 && r2 > 0.0) best = std::min(best, r2);
  }
  return best;
}

}  // namespace pb::internal
