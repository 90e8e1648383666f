// The closed-form truth of a frictionless disk on a fixed line (the cases
// falling_ball and sliding, SPEC §2-§3): in the frame of the line (tangent t,
// outward normal n of the half-plane) the tangential motion is uniform
// acceleration g . t for all time, the rotation keeps its initial rate (the
// normal force passes through the centre and there is no friction), and the
// normal motion is a NormalContactMotion.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "normal_contact_motion.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

class DiskOnLine {
 public:
  // disk: the moving Circle body, line: the fixed HalfPlane body, pair: the
  // contact pair between them (Kelvin-Voigt without ramp); indices into c.
  DiskOnLine(const Case& c, int disk, int line, int pair);

  // locates every event up to t_s
  void extend_to(double t_s) { normal_.extend_to(t_s); }

  // states of every body of the case at t_s (fixed bodies stay put)
  void body_states(double t_s, std::vector<BodyState>& out) const;
  // one sample while the disk penetrates the line (delta > 0), else none
  void contacts(double t_s, std::vector<ContactSample>& out) const;
  // the episode table up to now_s
  [[nodiscard]] std::vector<ContactEpisode> episodes(double now_s) const;
  // phases of the normal motion begun by t_s
  [[nodiscard]] long phases_begun(double t_s) const;
  // what closed form is used, with its parameters
  [[nodiscard]] nlohmann::json mapping() const;

  [[nodiscard]] const NormalContactMotion& normal_motion() const { return normal_; }

 private:
  static NormalContactParams normal_params(const Case& c, int disk, int line, int pair,
                                           bool& snapped);

  int disk_ = -1;
  int pair_body_a_ = -1;
  int pair_body_b_ = -1;
  bool disk_is_a_ = false;
  double radius_m_ = 0.0;           // m
  Vec2 line_origin_m_;              // m, a point of the line
  Vec2 tangent_;                    // unit, line direction
  Vec2 normal_dir_;                 // unit, outward normal of the half-plane
  double along0_m_ = 0.0;           // m, tangential coordinate of the centre at t = 0
  double along_rate0_mps_ = 0.0;    // m/s
  double along_accel_mps2_ = 0.0;   // m/s^2, g . t
  double angle0_rad_ = 0.0;         // rad
  double spin_radps_ = 0.0;         // rad/s, constant
  bool gap_snapped_ = false;        // the initial gap was rounding of zero
  std::vector<BodyState> initial_;  // every body at t = 0
  NormalContactMotion normal_;
};

}  // namespace pb::internal
