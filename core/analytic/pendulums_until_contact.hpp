// The closed-form truth of pendulums up to their first contact (the case
// dual_pendulum, SPEC §3: truth = analytic_until_first_contact). Every moving
// body swings as an exact CompoundPendulum about its revolute joint; the first
// contact is the earliest zero of the exact gap of any contact pair, located by
// sampling the gap (1/1024 of the shortest swing), checking every sampled local
// minimum by golden-section search for a dip below zero, and bisection to the
// last bit. After it the states are the free pendulums continued: no longer
// the truth, which the engine states through valid_until_s.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "compound_pendulum.hpp"
#include "exact_gap.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

struct FirstContact {
  double time_s = 0.0;  // s
  int pair = -1;        // index into Case::contacts
  int body_a = -1;      // the pair's bodies, indices into Case::bodies
  int body_b = -1;
  double approach_speed_mps = 0.0;  // m/s, normal relative speed, > 0 approaching
  Vec2 normal = Vec2::Zero();       // unit, from the pair's body_a to body_b
  Vec2 point_m = Vec2::Zero();      // m, world
};

class PendulumsUntilContact {
 public:
  // c must match the pendulum structure (closed_form_match.hpp)
  explicit PendulumsUntilContact(const Case& c);

  // searches for the first contact up to t_s (no further once found)
  void extend_to(double t_s);
  [[nodiscard]] double searched_until_s() const { return searched_until_s_; }
  [[nodiscard]] const std::optional<FirstContact>& first_contact() const { return contact_; }

  // every body at t_s, fixed ones included
  void body_states(double t_s, std::vector<BodyState>& out) const;
  // the gap of contact pair `pair` at t_s
  [[nodiscard]] ExactGap pair_gap(std::size_t pair, double t_s) const;
  [[nodiscard]] const std::vector<CompoundPendulum>& pendulums() const { return pendulums_; }
  [[nodiscard]] nlohmann::json mapping() const;

 private:
  [[nodiscard]] Pose pose_of(int body, double t_s) const;
  [[nodiscard]] BodyState state_of(int body, double t_s) const;
  // the first zero of the gap of `pair` in [lo, hi] given gap(lo) > 0 >= gap(hi)
  [[nodiscard]] double bisect_zero(std::size_t pair, double lo, double hi) const;
  // a zero inside a sampled local minimum of the gap on [lo, hi], or +inf
  [[nodiscard]] double zero_in_dip(std::size_t pair, double lo, double hi) const;
  void record_contact(std::size_t pair, double t_s);

  struct PairRef {
    int body_a = -1;
    int body_b = -1;
  };
  std::vector<std::string> body_names_;
  std::vector<Shape> shapes_;
  std::vector<BodyState> initial_;     // every body at t = 0
  std::vector<int> pendulum_of_body_;  // index into pendulums_, -1 for fixed bodies
  std::vector<CompoundPendulum> pendulums_;
  std::vector<PairRef> pairs_;
  std::vector<std::string> pair_names_;

  double step_s_ = 0.0;           // s, the sampling step (+inf: nothing moves)
  long sample_ = 0;               // index of the last sample taken
  std::vector<double> gap_;       // gap of each pair at the last sample
  std::vector<double> gap_prev_;  // and at the one before
  double searched_until_s_ = 0.0;
  std::optional<FirstContact> contact_;
};

}  // namespace pb::internal
