#include "pendulums_until_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "root_finding.hpp"

namespace pb::internal {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// samples per shortest swing: far finer than any change of sign of the gap
// of two smooth swinging shapes, so no crossing falls between two samples
constexpr double kSamplesPerSwing = 1024.0;

}  // namespace

PendulumsUntilContact::PendulumsUntilContact(const Case& c) {
  pendulum_of_body_.assign(c.bodies.size(), -1);
  for (const Body& b : c.bodies) {
    body_names_.push_back(b.name);
    shapes_.push_back(b.shape);
    BodyState s;
    s.position_m = b.position_m;
    s.angle_rad = b.angle_rad;
    if (!b.fixed) {
      s.velocity_mps = b.velocity_mps;
      s.angular_velocity_radps = b.angular_velocity_radps;
    }
    initial_.push_back(s);
  }
  double swing_s = kInf;
  for (const RevoluteJoint& j : c.joints) {
    const auto body = static_cast<std::size_t>(j.body);
    pendulum_of_body_[body] = static_cast<int>(pendulums_.size());
    pendulums_.emplace_back(j.anchor_world_m, c.bodies[body], c.gravity_mps2);
    swing_s = std::min(swing_s, pendulums_.back().time_scale_s());
  }
  for (const ContactPair& p : c.contacts) {
    pairs_.push_back(PairRef{p.body_a, p.body_b});
    pair_names_.push_back(p.name);
  }
  step_s_ = swing_s / kSamplesPerSwing;

  // t = 0: already touching counts as the first contact
  for (std::size_t p = 0; p < pairs_.size(); ++p) gap_.push_back(pair_gap(p, 0.0).gap_m);
  gap_prev_ = gap_;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    if (gap_[p] <= 0.0 && !contact_) record_contact(p, 0.0);
  }
}

Pose PendulumsUntilContact::pose_of(int body, double t_s) const {
  const BodyState s = state_of(body, t_s);
  return Pose{s.position_m, s.angle_rad};
}

BodyState PendulumsUntilContact::state_of(int body, double t_s) const {
  const int pend = pendulum_of_body_[static_cast<std::size_t>(body)];
  if (pend < 0) return initial_[static_cast<std::size_t>(body)];
  return pendulums_[static_cast<std::size_t>(pend)].state_at(t_s);
}

ExactGap PendulumsUntilContact::pair_gap(std::size_t pair, double t_s) const {
  const PairRef& p = pairs_[pair];
  return exact_gap(shapes_[static_cast<std::size_t>(p.body_a)], pose_of(p.body_a, t_s),
                   shapes_[static_cast<std::size_t>(p.body_b)], pose_of(p.body_b, t_s));
}

double PendulumsUntilContact::bisect_zero(std::size_t pair, double lo, double hi) const {
  return first_true_by_bisection([&](double t) { return pair_gap(pair, t).gap_m <= 0.0; }, lo, hi);
}

double PendulumsUntilContact::zero_in_dip(std::size_t pair, double lo, double hi) const {
  // golden-section search for the minimum (Press et al., Numerical Recipes
  // 3rd ed., §10.2), to the resolution the gap's rounding allows
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo;
  double b = hi;
  double x1 = b - r * (b - a);
  double x2 = a + r * (b - a);
  double f1 = pair_gap(pair, x1).gap_m;
  double f2 = pair_gap(pair, x2).gap_m;
  for (int it = 0; it < 200 && b - a > 4.0 * std::numeric_limits<double>::epsilon() * b; ++it) {
    if (f1 <= 0.0) return bisect_zero(pair, lo, x1);
    if (f2 <= 0.0) return bisect_zero(pair, lo, x2);
    if (f1 < f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - r * (b - a);
      f1 = pair_gap(pair, x1).gap_m;
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + r * (b - a);
      f2 = pair_gap(pair, x2).gap_m;
    }
  }
  return kInf;
}

void PendulumsUntilContact::record_contact(std::size_t pair, double t_s) {
  const ExactGap g = pair_gap(pair, t_s);
  const PairRef& p = pairs_[pair];
  const BodyState sa = state_of(p.body_a, t_s);
  const BodyState sb = state_of(p.body_b, t_s);
  FirstContact fc;
  fc.time_s = t_s;
  fc.pair = static_cast<int>(pair);
  fc.body_a = p.body_a;
  fc.body_b = p.body_b;
  fc.normal = g.normal;
  fc.point_m = 0.5 * (g.point_a_m + g.point_b_m);
  // the gap closes at n . (v_a(p) - v_b(p)) (envelope theorem on the distance)
  fc.approach_speed_mps =
      g.normal.dot(point_velocity(sa, g.point_a_m) - point_velocity(sb, g.point_b_m));
  contact_ = fc;
}

void PendulumsUntilContact::extend_to(double t_s) {
  if (contact_ || !(step_s_ < kInf)) {
    // found, or nothing moves: the gaps are those of t = 0
    searched_until_s_ = std::max(searched_until_s_, t_s);
    return;
  }
  const std::size_t n = pairs_.size();
  while (static_cast<double>(sample_) * step_s_ < t_s) {
    const double t_prev = static_cast<double>(sample_ - 1) * step_s_;
    const double t_now = static_cast<double>(sample_) * step_s_;
    const double t_next = static_cast<double>(sample_ + 1) * step_s_;
    double first = kInf;
    std::size_t first_pair = 0;
    for (std::size_t p = 0; p < n; ++p) {
      const double g_next = pair_gap(p, t_next).gap_m;
      double t_zero = kInf;
      const bool dip = (sample_ == 0 || gap_prev_[p] > gap_[p]) && gap_[p] <= g_next;
      if (dip && gap_[p] > 0.0) {
        t_zero = zero_in_dip(p, sample_ == 0 ? 0.0 : t_prev, t_next);
      }
      if (t_zero == kInf && gap_[p] > 0.0 && g_next <= 0.0) t_zero = bisect_zero(p, t_now, t_next);
      if (t_zero < first) {
        first = t_zero;
        first_pair = p;
      }
      gap_prev_[p] = gap_[p];
      gap_[p] = g_next;
    }
    ++sample_;
    if (first < kInf) {
      record_contact(first_pair, first);
      searched_until_s_ = std::max(first, t_s);
      return;
    }
  }
  searched_until_s_ = std::max(searched_until_s_, static_cast<double>(sample_) * step_s_);
}

void PendulumsUntilContact::body_states(double t_s, std::vector<BodyState>& out) const {
  out.resize(initial_.size());
  for (std::size_t i = 0; i < initial_.size(); ++i) out[i] = state_of(static_cast<int>(i), t_s);
}

nlohmann::json PendulumsUntilContact::mapping() const {
  nlohmann::json j;
  j["closed_form"] = "compound_pendulums_until_first_contact";
  j["description"] =
      "each moving body an exact large-amplitude compound pendulum about its revolute joint "
      "(Jacobi elliptic functions by AGM / descending Landen, A&S 16.4); first contact = "
      "first zero of the exact gap of any contact pair (gap sampled at 1/1024 of the "
      "shortest swing, local minima checked by golden section, bisection to the last bit)";
  nlohmann::json pend = nlohmann::json::array();
  for (std::size_t b = 0; b < pendulum_of_body_.size(); ++b) {
    const int i = pendulum_of_body_[b];
    if (i < 0) continue;
    nlohmann::json d = pendulums_[static_cast<std::size_t>(i)].describe();
    d["body"] = body_names_[b];
    pend.push_back(d);
  }
  j["pendulums"] = pend;
  if (contact_) {
    j["first_contact"] = {{"time_s", contact_->time_s},
                          {"pair", pair_names_[static_cast<std::size_t>(contact_->pair)]},
                          {"approach_speed_mps", contact_->approach_speed_mps}};
  }
  j["not_expressed"] = nlohmann::json::array(
      {"the contact itself: states after the first contact are the free pendulums continued "
       "and are not the truth (valid_until_s); no contact samples; the one episode has its "
       "onset time and approach speed only, every other field NaN"});
  return j;
}

}  // namespace pb::internal
