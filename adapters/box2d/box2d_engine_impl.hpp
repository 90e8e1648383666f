// The Box2D adapter's engine class (box2d_engine.cpp: stepping, sampling and
// what a run reports; box2d_engine_build.cpp: what it supports and the world
// it builds from a case), shared by the two.
#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_world.h>

#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "box2d_settings.hpp"
#include "box2d_world_callbacks.hpp"
#include "planarbench/engine.hpp"
#include "planarbench/episode_tracker.hpp"

namespace pb::internal::box2d {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// onsets whose restitution is logged in the mapping (a bound: no allocation
// while stepping)
constexpr std::size_t kOnsetLogCapacity = 256;
// m, the penetration given to the episode tracker for a pair Box2D counts as
// touching (a manifold with points) whose float separation came out >= 0
constexpr double kTouching_m = 1e-12;

// every b2World::Step of this thread: a trace the engine reads before and
// after build (SPEC §5b: the default mode steps nothing ahead of t = 0)
extern thread_local long t_world_steps;

// the contact state of one pair after the latest step
struct PairSample {
  bool valid = false;
  double penetration_m = kNaN;  // m, > 0 overlap (as measured)
  double tracked_m = kNaN;      // m, the penetration the episode tracker was given
  double speed_mps = kNaN;      // m/s, normal approach speed (> 0 approaching)
  double force_n = 0.0;         // N, reported at this time (engine: the last step's)
  double step_force_n = 0.0;    // N, mean force over the step that ended here
  double tangential_force_n = 0.0;  // N, on body_b along t, mean over that step (issue 32)
  Vec2 normal = Vec2::Zero();   // from body_a to body_b
  Vec2 point_m = Vec2::Zero();
};

inline bool finite(const BodyState& s) {
  return std::isfinite(s.position_m.x()) && std::isfinite(s.position_m.y()) &&
         std::isfinite(s.angle_rad) && std::isfinite(s.velocity_mps.x()) &&
         std::isfinite(s.velocity_mps.y()) && std::isfinite(s.angular_velocity_radps);
}

class Box2dEngine final : public Engine {
 public:
  Box2dEngine() { bind_settings(binder_, &settings_); }

  [[nodiscard]] std::string name() const override { return "box2d"; }
  [[nodiscard]] std::string version() const override;
  [[nodiscard]] Capability supports(const Case& c) const override;
  [[nodiscard]] const SettingsBinder& settings() const override { return binder_; }
  void build(const Case& c, const SettingsOverrides& overrides) override;
  void advance_to(double t_s) override;
  [[nodiscard]] double time() const override { return time_s_; }
  void body_states(std::vector<BodyState>& out) const override;
  void contacts(std::vector<ContactSample>& out) const override;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const override;
  [[nodiscard]] long steps() const override { return steps_; }
  [[nodiscard]] nlohmann::json mapping() const override { return mapping_with_onsets(); }
  [[nodiscard]] nlohmann::json extra_attributes() const override;
  [[nodiscard]] Physics physics() const override;
  [[nodiscard]] long steps_before_start() const override { return steps_before_start_; }
  [[nodiscard]] long library_steps_on_this_thread() const override { return t_world_steps; }

 private:
  [[nodiscard]] bool inject() const { return settings_.mode == "inject"; }
  static void validate_bodies(const Case& c, double dt_s);
  void create_bodies(double threshold_mps);
  void create_joints();
  void map_pairs();
  void step();
  void apply_injected_forces();
  void check_state();
  [[noreturn]] void fail(std::string reason);
  void sample_pairs();
  void sample_engine_pair(std::size_t k);
  // m, a lower bound of pair k's gap from the bodies' centres and bounding
  // radii, and the most that gap can change in one step: the probe's exact
  // gap is needed only where the pair can touch within a step
  [[nodiscard]] bool far_apart(std::size_t k, double& lower_bound_m) const;
  void sample_injected_pair(std::size_t k);
  void track(std::size_t k, const PairSample& before, PairSample& now);
  [[nodiscard]] nlohmann::json mapping_with_onsets() const;

  Box2dSettings settings_;
  SettingsBinder binder_{"box2d"};

  Case case_;
  long steps_ = 0;
  double time_s_ = 0.0;
  bool collide_ = true;  // the contact filter lets the case pairs collide (engine mode)

  PairTable pairs_;
  std::vector<PairState> pair_states_;
  std::vector<BodyInertia> inertia_;
  std::vector<PairSample> samples_;
  // per pair, for far_apart: a fixed half-plane body_a's line (point, unit
  // normal towards body_b) or the bodies' bounding radii
  struct FarBound {
    bool plane = false;    // body_a is a fixed half-plane
    bool usable = false;   // a bound exists (a plane, or two finite radii)
    Vec2 point_m = Vec2::Zero();
    Vec2 normal = Vec2::Zero();
    double radius_a_m = 0.0;
    double radius_b_m = 0.0;
  };
  std::vector<FarBound> far_;
  std::vector<double> latched_approach_mps_;  // inject mode: delta_dot at onset, per pair
  std::vector<Vec2> injected_force_n_;        // inject mode: total force per body this step, N
  std::vector<double> injected_torque_nm_;    // inject mode: about the centre of mass, N m
  EpisodeTracker tracker_;
  double orphan_impulse_ns_ = 0.0;  // N s, solver impulse outside any episode (should stay 0)

  nlohmann::json mapping_ = nlohmann::json::object();
  // the callbacks must outlive the world (members are destroyed in reverse order)
  PairContactFilter filter_{pairs_, collide_};
  PairContactListener listener_{pairs_, pair_states_, inertia_, time_s_};
  std::unique_ptr<b2World> world_;
  std::vector<b2Body*> bodies_;  // index = Case::bodies index
  std::string fault_;  // why the run stopped ("" while it did not): it does not go on
  long steps_before_start_ = 0;  // b2World steps taken during build
};

}  // namespace pb::internal::box2d
