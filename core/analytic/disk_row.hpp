// The closed-form truth of a row of disks struck along its line, without
// gravity (SPEC §11, a Newton's cradle with gaps): the disks fly freely
// between impacts, and each impact is binary, the clamped Kelvin-Voigt
// oscillator of the two disks' reduced mass (normal_contact_motion.hpp, as
// two_disks_head_on.hpp for one pair), the pair's centre of mass moving
// uniformly through it. Momentum is exact; each impact's restitution is the
// law's. The impacts follow one another in time order; the truth refuses a
// case where two would overlap (a disk touching both neighbours at once has
// no binary closed form) or where the disks do not move along the row.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "normal_contact_motion.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

class DiskRow {
 public:
  // throws std::invalid_argument with the reason when the case is not one
  explicit DiskRow(const Case& c);
  [[nodiscard]] static std::string why_not(const Case& c);

  void body_states(double t_s, std::vector<BodyState>& out) const;
  void contacts(double t_s, std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes(double now_s) const;
  [[nodiscard]] long impacts_begun(double t_s) const;
  [[nodiscard]] nlohmann::json mapping() const;

 private:
  // one stretch of time: free flight of every disk, or one binary impact
  struct Stretch {
    double t0_s = 0.0;
    double t1_s = 0.0;
    std::vector<double> s0_m;     // m, each disk's centre along the row at t0
    std::vector<double> v0_mps;   // m/s, its speed along the row at t0
    int pair = -1;                // impact: disks pair and pair + 1; -1 free flight
    std::shared_ptr<NormalContactMotion> motion;  // impact: the gap, from t0
  };
  // centre positions and speeds along the row at t_s within stretch st
  void along_row(const Stretch& st, double t_s, std::vector<double>& s_m,
                 std::vector<double>& v_mps) const;
  [[nodiscard]] const Stretch& stretch_at(double t_s) const;

  std::vector<int> disks_;       // body indices along the row
  std::vector<double> mass_kg_, radius_m_;
  Vec2 origin_m_ = Vec2::Zero();
  Vec2 direction_ = Vec2(1.0, 0.0);
  double stiffness_n_per_m_ = 0.0, damping_ns_per_m_ = 0.0;
  std::vector<BodyState> initial_;
  std::vector<Stretch> stretches_;
};

}  // namespace pb::internal
