#include "planarbench/impacts/impact_convention.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "planarbench/errors.hpp"

namespace pb {

std::string ConventionFit::label() const {
  auto word = [](double sign) { return sign > 0 ? "as stored" : "negated"; };
  return fmt::format("angle {}, angular velocity {}", word(convention.angle_sign),
                     word(convention.rate_sign));
}

namespace {

ConventionFit fit(const ImpactSet& set, const ImpactObject& o, AngleConvention c) {
  const std::size_t n = set.size();
  std::vector<double> before(n), after(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ImpactState pre = to_model(set.pre[i], c);
    ImpactState post = to_model(set.post[i], c);
    // the contact point of the impact: at the pre-impact angle
    const Vec2 offset = lowest_point_offset(o, pre.angle_rad);
    before[i] = angular_momentum_about(o, pre, offset);
    after[i] = angular_momentum_about(o, post, offset);
  }
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += before[i];
    my += after[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (before[i] - mx) * (before[i] - mx);
    syy += (after[i] - my) * (after[i] - my);
    sxy += (before[i] - mx) * (after[i] - my);
  }
  ConventionFit f;
  f.convention = c;
  f.slope = sxx > 0.0 ? sxy / sxx : 0.0;
  f.intercept = my - f.slope * mx;
  f.correlation = sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0;
  return f;
}

}  // namespace

ConventionCheck check_convention(const ImpactSet& set, const ImpactObject& o) {
  if (set.size() < kMinImpacts) {
    throw InputError(set.path, 0, "data.states_i",
                     fmt::format("has {} impact{}: too few to decide the angle convention (a "
                                 "correlation over the impacts); at least {} needed",
                                 set.size(), set.size() == 1 ? "" : "s", kMinImpacts));
  }
  ConventionCheck check;
  const std::array<AngleConvention, 4> pairs = {
      AngleConvention{1.0, 1.0}, AngleConvention{-1.0, 1.0}, AngleConvention{1.0, -1.0},
      AngleConvention{-1.0, -1.0}};
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    check.fits[k] = fit(set, o, pairs[k]);
    if (check.chosen < 0 || check.fits[k].correlation > check.best().correlation) {
      check.chosen = static_cast<int>(k);
    }
  }
  const ConventionFit& b = check.best();
  if (!(b.correlation >= kMinCorrelation) || !(std::abs(b.slope - 1.0) <= kSlopeBand)) {
    throw InputError(set.path, 0, "data.states_i, data.states_f",
                     fmt::format("no angle convention conserves the angular momentum about the "
                                 "contact point through the impacts: the best ({}) fits slope {:.3f}, "
                                 "r {:.3f}; consistent data need r >= {} and slope within 1 +- {}",
                                 b.label(), b.slope, b.correlation, kMinCorrelation, kSlopeBand));
  }
  return check;
}

}  // namespace pb
