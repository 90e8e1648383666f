// Which angle convention a file of impacts obeys, decided by physics (SPEC §8):
// the ground's impulse acts at the contact point, so an impact conserves the
// angular momentum about that point (gravity's impulse over a contact of a few
// ms is negligible). For each sign pair (angle, angular velocity) the
// post-impact momentum is fitted against the pre-impact one over the file
// (least squares with intercept, and Pearson's r); the pair with the highest r
// is the convention, and a file whose best pair is not consistent
// (r < kMinCorrelation or slope outside 1 +- kSlopeBand) is refused.
#pragma once

#include <array>
#include <string>

#include "planarbench/impacts/impact_data.hpp"
#include "planarbench/impacts/impact_object.hpp"

namespace pb {

// The MCube file gives r = 0.984, slope 0.976 in its convention and slopes of
// -0.26 to -1.6 in the others (its README): 0.9 and 0.2 separate those with a
// wide margin while allowing the measurement noise of a 250 Hz capture.
inline constexpr double kMinCorrelation = 0.9;
inline constexpr double kSlopeBand = 0.2;

// The fewest impacts the check decides on: for unrelated momenta Pearson's r
// reaches kMinCorrelation with probability 2e-4 at 10 impacts (t = 5.8 with 8
// degrees of freedom), 0.14 at 3, and is always +-1 at 2.
inline constexpr std::size_t kMinImpacts = 10;

struct ConventionFit {
  AngleConvention convention;
  double slope = 0.0;        // post-impact L against pre-impact L
  double intercept = 0.0;    // kg m^2/s
  double correlation = 0.0;  // Pearson r
  [[nodiscard]] std::string label() const;  // e.g. "angle negated, rate negated"
};

struct ConventionCheck {
  std::array<ConventionFit, 4> fits;  // as stored, angle negated, rate negated, both
  int chosen = -1;                    // index into fits
  [[nodiscard]] const ConventionFit& best() const { return fits[static_cast<std::size_t>(chosen)]; }
};

// The fits of every sign pair; throws InputError naming the file and the
// states when no pair conserves the momentum (the figures in the message).
[[nodiscard]] ConventionCheck check_convention(const ImpactSet& set, const ImpactObject& o);

}  // namespace pb
