// The closed-form truth of two free disks colliding head on (the case
// head_on, SPEC §3): nothing but gravity and the contact acts, so the centre
// of mass moves as X(t) = X0 + V t + g t^2 / 2 (gravity accelerates both disks
// alike and drops out of their relative motion), the spins stay constant
// (the force passes through both centres, no friction), and the relative
// coordinate along the fixed line of centres u is the clamped Kelvin-Voigt
// oscillator of the reduced mass mu = m_a m_b / (m_a + m_b): the gap
// s(t) = |x_b - x_a| - R_a - R_b is a NormalContactMotion with mass mu and no
// normal gravity. The bodies follow from x_a = X - (m_b / M) r u and
// x_b = X + (m_a / M) r u with r = s + R_a + R_b (e.g. Goldstein, Classical
// Mechanics, §3.1: the two-body problem reduced to one).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "normal_contact_motion.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

class TwoDisksHeadOn {
 public:
  // a, b: the two moving circles (a the pair's body_a), pair: their plain
  // Kelvin-Voigt contact pair; indices into c (closed_form_match.hpp checks
  // that the relative velocity is along the line of centres)
  TwoDisksHeadOn(const Case& c, int a, int b, int pair);

  void extend_to(double t_s) { normal_.extend_to(t_s); }
  void body_states(double t_s, std::vector<BodyState>& out) const;
  void contacts(double t_s, std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes(double now_s) const;
  [[nodiscard]] long phases_begun(double t_s) const;
  [[nodiscard]] nlohmann::json mapping() const;
  [[nodiscard]] const NormalContactMotion& relative_motion() const { return normal_; }

 private:
  static NormalContactParams relative_params(const Case& c, int a, int b, int pair);

  int a_ = -1;
  int b_ = -1;
  int pair_body_a_ = -1;
  int pair_body_b_ = -1;
  double mass_a_kg_ = 0.0;
  double mass_b_kg_ = 0.0;
  double radius_a_m_ = 0.0;
  double radius_b_m_ = 0.0;
  Vec2 u_ = Vec2::Zero();          // unit, from disk a's centre to disk b's
  Vec2 centre0_m_ = Vec2::Zero();  // m, centre of mass at t = 0
  Vec2 centre_v_mps_ = Vec2::Zero();  // m/s, its velocity
  Vec2 gravity_mps2_ = Vec2::Zero();
  std::vector<BodyState> initial_;  // every body at t = 0
  NormalContactMotion normal_;
};

}  // namespace pb::internal
