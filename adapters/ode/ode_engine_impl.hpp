// The ODE adapter's engine class (internal): ode_engine.cpp builds and steps
// it, ode_engine_mapping.cpp writes what its mapping() records.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "ode_contact_mapping.hpp"
#include "ode_library.hpp"
#include "ode_pair_contact.hpp"
#include "ode_probe.hpp"
#include "ode_space_collider.hpp"
#include "ode_settings.hpp"
#include "ode_world.hpp"
#include "planarbench/contact_pairs.hpp"
#include "planarbench/engine.hpp"
#include "planarbench/episode_tracker.hpp"

namespace pb::internal::ode {

// plain Kelvin-Voigt (no damping ramp): a linear spring-damper already
inline bool is_plain_kelvin_voigt(const ContactLaw& law) {
  const auto* kv = std::get_if<KelvinVoigt>(&law);
  return kv != nullptr && kv->damping_depth_m <= 0.0;
}

// one contact pair's state between samples
struct PairTrack {
  double force_n = 0.0;               // N, normal force of the current sample
  // N, the joints' force on body_b along t = n rotated by +90 deg over the
  // step that ended now (native, oracle; 0 in inject mode, which has no
  // friction); issue 32
  double tangential_force_n = 0.0;
  double latched_approach_mps = 0.0;  // m/s, delta_dot at onset (eq. 7's delta_dot^-)
  bool in_contact = false;            // penetration > 0 at the current sample
  double depth_m = 0.0;               // m, at the current sample
  double speed_mps = 0.0;             // m/s, approach speed at the current sample
  Vec2 normal_ab = Vec2::Zero();
  Vec2 point_m = Vec2::Zero();
};

class OdeEngine final : public Engine {
 public:
  OdeEngine() : binder_(internal::ode::bind_ode_settings(settings_)) {}

  [[nodiscard]] std::string name() const override { return "ode"; }

  [[nodiscard]] std::string version() const override {
    return fmt::format(
        "ODE {} (pkg-config at build time; headers dODE_VERSION {}; "
        "dGetConfiguration: {})",
        internal::ode::ode_pkgconfig_version(), internal::ode::ode_header_version(),
        internal::ode::ode_configuration());
  }

  [[nodiscard]] Capability supports(const Case& c) const override;
  [[nodiscard]] const SettingsBinder& settings() const override { return binder_; }
  void build(const Case& c, const SettingsOverrides& overrides) override;
  void advance_to(double t_s) override;
  [[nodiscard]] double time() const override { return static_cast<double>(steps_) * step_s_; }
  void body_states(std::vector<BodyState>& out) const override;
  void contacts(std::vector<ContactSample>& out) const override;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const override {
    return tracker_.episodes();
  }
  [[nodiscard]] long steps() const override { return steps_; }
  [[nodiscard]] nlohmann::json mapping() const override;
  [[nodiscard]] nlohmann::json extra_attributes() const override;
  [[nodiscard]] Physics physics() const override;
  [[nodiscard]] long steps_before_start() const override { return probe_steps_; }
  [[nodiscard]] long library_steps_on_this_thread() const override {
    return internal::ode::world_steps_on_this_thread();
  }

 private:
  void map_contacts_oracle(const std::vector<FirstTouch>& touches);
  void map_contacts_native();
  // a fresh mapping with the fields every mode records, then the mode writes its own
  void start_mapping();
  void add_common_mapping();
  [[nodiscard]] nlohmann::json native_rule_json(const ContactLaw& law, double friction) const;
  [[nodiscard]] nlohmann::json bodies_json() const;
  [[nodiscard]] std::string collision_text() const;
  [[nodiscard]] const ContactPair& pair(int p) const { return (*pairs_)[p]; }
  void add_native_joints(std::size_t e);
  [[nodiscard]] double separation_speed_mps(const dContactGeom& g) const;
  void add_normal_force(const dContactGeom& g, double f_n) const;
  void add_oracle_joint(std::size_t e);
  void step_once();
  [[nodiscard]] bool injected_forces_run_away();
  void sample_contacts();

  OdeSettings settings_;
  SettingsBinder binder_;

  Case case_;
  std::unique_ptr<OdeWorld> world_;
  // the run's pairs: the declared ones, then a scene's as ODE's broad phase
  // reports them (every vector below indexed by pair grows with it)
  std::unique_ptr<ContactPairs> pairs_;
  std::unique_ptr<Collider> collider_;
  StepContacts now_;               // ODE's contacts at the current state
  std::vector<PairTrack> track_;   // per pair
  std::vector<int> in_contact_;    // pairs in contact at the current sample, ascending
  std::vector<int> forced_;        // pairs whose force the last step set
  std::vector<std::pair<int, int>> visit_;  // scratch: (pair, entry of now_.pairs or -1)
  std::vector<SoftContact> soft_;  // oracle mode, per (declared) pair
  // this step's contact joints: entry e of now_.pairs owns rows [first, first + count) of
  // feedback_ and explicit_n_, a pool as large as the state's contacts
  struct JointRange {
    int first = 0;
    int count = 0;
  };
  std::vector<JointRange> joints_;
  std::vector<dJointFeedback> feedback_;  // per contact joint of the step
  std::vector<double> explicit_n_;  // per contact joint, like feedback_: its explicit damping force, N
  std::vector<double> angle_rad_;  // continuous angles, per body
  std::vector<Vec2> force_n_;      // inject mode: total force per body this step, N
  std::vector<double> torque_nm_;  // inject mode: about the centre of mass, N m
  EpisodeTracker tracker_;
  bool inject_ = false;
  bool oracle_ = false;
  bool quick_ = false;
  bool corrected_ = true;
  long probe_steps_ = 0;  // ODE steps taken during build (the oracle's probe run)
  // native mode: contact rows whose corrected damping did not hold (c < h k),
  // and the largest h k / c seen
  long rows_correction_invalid_ = 0;
  long rows_made_ = 0;
  double worst_hk_over_c_ = 0.0;
  double step_s_ = 1e-4;
  int substeps_ = 1;
  long steps_ = 0;
  std::string diverged_;  // non-empty once a body blew up
  nlohmann::json mapping_ = nlohmann::json::object();
  nlohmann::json extra_ = nlohmann::json::object();
  // ODE's non-fatal messages during this run's steps (ode_library.hpp)
  long messages_seen_ = 0;
  long messages_mark_ = 0;  // the thread's count when last looked at
  std::string first_message_;
};

}  // namespace pb::internal::ode
