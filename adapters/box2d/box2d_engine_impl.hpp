// The Box2D adapter's engine class (box2d_engine.cpp: stepping, sampling and
// what a run reports; box2d_engine_build.cpp: what it supports and the world
// it builds from a case), shared by the two.
#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_world.h>

#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "box2d_pair_book.hpp"
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
  bool listed = false;          // measured: Box2D held a contact of the pair (or t = 0)
  bool open = false;            // its episode is open (its tracker's in_contact, kept here)
  double penetration_m = kNaN;  // m, > 0 overlap (as measured)
  double tracked_m = kNaN;      // m, the penetration the episode tracker was given
  double speed_mps = kNaN;      // m/s, normal approach speed (> 0 approaching)
  // N, reported at this time: engine mode, the mean force over the output
  // interval that ended here (box2d_mapping_notes.cpp, "forces"); inject
  // mode, the law's force for the next step
  double force_n = 0.0;
  double step_force_n = 0.0;        // N, mean force over the step that ended here
  double tangential_force_n = 0.0;  // N, on body_b along t, mean as force_n (issue 32)
  Vec2 normal = Vec2::Zero();       // from body_a to body_b
  Vec2 point_m = Vec2::Zero();
  // N s, the pair's normal and tangent impulses over the output interval
  // `interval` (Box2dEngine::interval_), so far
  long interval = -1;
  double interval_impulse_ns = 0.0;
  double interval_tangent_impulse_ns = 0.0;
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
  // the pairs' states and their mapping: the declared pairs', and the one
  // every pair of each contact group starts from
  void map_pairs(double threshold_mps, std::vector<PairState>& declared,
                 std::vector<PairState>& groups);
  // restitution and friction of a law, into `st` and the mapping entry `j`
  void map_law(const ContactLaw& law, double friction, PairState& st, nlohmann::json& j) const;
  // grows every per-pair vector to the pairs PairBook holds now
  void grow_pairs();
  // the group pairs that can touch at t = 0, before Box2D's broad phase has
  // run (it pairs fixtures in the first b2World::Step): the case's boxes,
  // fattened as Box2D's (b2_aabbExtension), swept once (broad_phase.hpp)
  void add_initial_group_pairs();
  void step();
  void apply_injected_forces();
  void check_state();
  [[noreturn]] void fail(std::string reason);
  void sample_pairs();
  // after a step: the pairs to sample (active_), each with Box2D's contacts
  // of it (head_, listed_), from one walk over b2World::GetContactList; and
  // once more, as apart, each pair that had a contact at its last sample
  void list_contacts();
  void sample_engine_pair(std::size_t k);
  // m, a lower bound of the gap of bodies a and b from their centres and
  // bounding radii (or a fixed half-plane's line), and whether it exceeds
  // what that gap can change in two steps: the probe's exact gap is needed
  // only where the pair can touch within a step
  [[nodiscard]] bool far_apart(int body_a, int body_b, double& lower_bound_m) const;
  void sample_injected_pair(std::size_t k);
  void track(std::size_t k, const PairSample& before, PairSample& now);
  [[nodiscard]] nlohmann::json mapping_with_onsets() const;

  Box2dSettings settings_;
  SettingsBinder binder_{"box2d"};

  Case case_;
  long steps_ = 0;
  double time_s_ = 0.0;
  bool collide_ = true;  // the contact filter lets the case pairs collide (engine mode)

  PairBook pairs_;  // the run's pairs and their listener state (box2d_pair_book.hpp)
  std::vector<BodyInertia> inertia_;
  // per pair (indexed like pairs_, grown by grow_pairs)
  std::vector<PairSample> samples_;
  // per body, for far_apart: a fixed half-plane's line (point, unit outward
  // normal), or the body's bounding radius (infinite for a moving half-plane)
  struct FarBound {
    bool plane = false;  // a fixed half-plane
    Vec2 point_m = Vec2::Zero();
    Vec2 normal = Vec2::Zero();
    double radius_m = 0.0;
  };
  std::vector<FarBound> far_;  // per body
  // per body, its motion after the latest step (far_apart reads these for
  // each of Box2D's contacts: one pass over the bodies, not two b2Body
  // reads per contact)
  struct Motion {
    Vec2 centre_m = Vec2::Zero();
    Vec2 velocity_mps = Vec2::Zero();
    double spin_radps = 0.0;
  };
  std::vector<Motion> motion_;
  // per pair (indexed like pairs_, grown by grow_pairs)
  std::vector<long> seen_;  // the step whose contact walk last listed the pair
  std::vector<int> head_;   // its last contact in listed_ then (-1: none)
  // the pairs sampled at the latest step, ascending (the declared pairs'
  // order of the pass over every pair this replaces), and the step before's
  std::vector<int> active_;
  std::vector<int> previous_active_;
  // Box2D's contacts of the latest walk, chained per pair from head_
  struct Listed {
    const b2Contact* contact = nullptr;
    int next = -1;  // the pair's previous contact in listed_, -1 none
  };
  std::vector<Listed> listed_;
  std::vector<const b2Contact*> bucket_;  // scratch: one pair's contacts
  // the output interval: advance_to calls that step; the force reported is
  // each pair's impulse over the interval's steps / their time
  long interval_ = 0;
  long interval_steps_ = 0;
  bool interval_force_ = false;  // the reported force is the interval's mean (reported_force)
  std::vector<double> latched_approach_mps_;  // inject mode: delta_dot at onset, per pair
  std::vector<Vec2> injected_force_n_;        // inject mode: total force per body this step, N
  std::vector<double> injected_torque_nm_;    // inject mode: about the centre of mass, N m
  // per pair: a tracker of its own keeps each lookup in a map of one pair
  // (a shared one's maps held a scene's thousands)
  std::vector<EpisodeTracker> trackers_;
  double orphan_impulse_ns_ = 0.0;  // N s, solver impulse outside any episode (should stay 0)

  nlohmann::json mapping_ = nlohmann::json::object();
  // the callbacks must outlive the world (members are destroyed in reverse order)
  PairContactFilter filter_{pairs_, collide_};
  PairContactListener listener_{pairs_, inertia_, time_s_};
  std::unique_ptr<b2World> world_;
  std::vector<b2Body*> bodies_;  // index = Case::bodies index
  std::string fault_;  // why the run stopped ("" while it did not): it does not go on
  long steps_before_start_ = 0;  // b2World steps taken during build
};

}  // namespace pb::internal::box2d
