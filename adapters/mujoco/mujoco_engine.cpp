// The mujoco adapter: engine "mujoco" (MuJoCo 2.2.2, Debian's libmujoco-dev).
// A case becomes MJCF text (mujoco_mjcf), loaded from memory; each step is
// MuJoCo's own mj_step in two halves so that the state a step starts from is
// sampled (mujoco_stepping). Modes:
//   native (default) MuJoCo's collision and soft contact, each pair's solref
//          set at every step from the case's law and the effective mass of
//          the current configuration (mujoco_solref_rule): no look-ahead;
//   oracle the law mapped once onto solref, calibrated at each pair's first
//          touch found by a contact-free probe run (mujoco_probe,
//          mujoco_contact_mapping): foreknowledge, opt-in;
//   inject the case's own law applied at MuJoCo's contact geometry
//          (mujoco_injector).
#include "planarbench/adapters/mujoco_engine.hpp"

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "mujoco_capacity.hpp"
#include "mujoco_contact_mapping.hpp"
#include "mujoco_description.hpp"
#include "mujoco_exact_depth.hpp"
#include "mujoco_fault.hpp"
#include "mujoco_frame.hpp"
#include "mujoco_geometry.hpp"
#include "mujoco_injector.hpp"
#include "mujoco_mjcf.hpp"
#include "mujoco_model.hpp"
#include "mujoco_plan.hpp"
#include "mujoco_friction.hpp"
#include "mujoco_pair_state.hpp"
#include "mujoco_probe.hpp"
#include "mujoco_sampler.hpp"
#include "mujoco_settings.hpp"
#include "mujoco_solref_rule.hpp"
#include "mujoco_stepping.hpp"
#include "mujoco_support.hpp"
#include "planarbench/contact_law_response.hpp"
#include "planarbench/episode_tracker.hpp"
#include "planarbench/errors.hpp"

namespace pb {

namespace {

using namespace internal::mujoco;

// m: inactive contacts get gap = margin + this, i.e. they would need a
// penetration of 1 km to become active
constexpr double kInactiveGapM = 1e3;

// an impact resolved by fewer steps than this is flagged in the mapping
constexpr double kMinStepsPerImpact = 10.0;


// the reduced mass of two bodies (a fixed body has infinite mass), kg
double reduced_mass_kg(const Body& a, const Body& b) {
  const double wa = a.fixed ? 0.0 : 1.0 / a.mass_kg;
  const double wb = b.fixed ? 0.0 : 1.0 / b.mass_kg;
  return 1.0 / (wa + wb);
}

class MujocoEngine final : public Engine {
 public:
  MujocoEngine() : binder_(bind_mujoco_settings(settings_)) { install_warning_handler(); }

  std::string name() const override { return "mujoco"; }
  std::string version() const override {
    return fmt::format("{} (mj_version {}, header {})", mj_versionString(), mj_version(),
                       mjVERSION_HEADER);
  }
  Capability supports(const Case& c) const override {
    return mujoco_capability(c, settings_.mode);
  }
  const SettingsBinder& settings() const override { return binder_; }

  void build(const Case& c, const SettingsOverrides& overrides) override;
  void advance_to(double t_s) override;
  double time() const override { return static_cast<double>(steps_) * dt_s_; }
  void body_states(std::vector<BodyState>& out) const override;
  void contacts(std::vector<ContactSample>& out) const override;
  std::vector<ContactEpisode> episodes() const override {
    return sampler_ ? sampler_->episodes() : std::vector<ContactEpisode>{};
  }
  long steps() const override { return steps_; }
  nlohmann::json mapping() const override;
  nlohmann::json extra_attributes() const override;
  Physics physics() const override;
  long steps_before_start() const override { return probe_steps_; }
  [[nodiscard]] long library_steps_on_this_thread() const override {
    return integrations_on_this_thread();
  }

 private:
  MjcfOptions base_options() const;
  // the model of options (and the layout_ of its names), written from plan_
  ModelPtr load(const MjcfOptions& options);
  PairParams pair_params(std::size_t k, bool inactive) const;
  Calibration calibration(std::size_t k, const FirstTouch& t) const;
  void build_oracle(nlohmann::json& pairs, nlohmann::json& lost);
  void ensure_current();
  void check_warnings();
  void sample();

  MujocoSettings settings_;
  SettingsBinder binder_;

  Case case_;
  MujocoPlan plan_;  // the case's MuJoCo form, decided once per build
  ContactCapacity capacity_;  // <size nconmax njmax>
  bool multiccd_ = false;     // <flag multiccd> (mujoco.multiccd)
  double dt_s_ = 1e-4;
  bool inject_ = false;
  bool oracle_ = false;
  long probe_steps_ = 0;  // MuJoCo steps taken during build (the oracle's probe run)
  ModelPtr model_;
  DataPtr data_;
  ModelLayout layout_;
  std::optional<Scratch> scratch_;
  std::unique_ptr<ForceInjector> injector_;
  std::unique_ptr<SolrefRule> rule_;  // native mode
  WarningWatch watch_;
  std::optional<PairSampler> sampler_;  // observations, episodes, depth checks
  long steps_ = 0;
  int most_solver_iterations_ = 0;  // mjData::solver_iter, the most of one step
  bool forward_current_ = false;  // mj_forward ran at the current state
  bool sampled_ = false;          // the current state was sampled
  // the reason of the warning that ended the run ("" while none did): MuJoCo
  // has reset the state by then, so the run must not go on from it
  std::string fault_;
  // warnings that are noted only (WarningInfo::fault false): count, first time s
  std::array<long, mjNWARNING> noted_count_{};
  std::array<double, mjNWARNING> noted_first_s_{};
  nlohmann::json mapping_ = nlohmann::json::object();
};

MjcfOptions MujocoEngine::base_options() const {
  MjcfOptions o;
  o.dt_s = settings_.dt_s;
  o.integrator = settings_.integrator;
  o.solver = settings_.solver;
  o.iterations = settings_.iterations;
  o.tolerance = settings_.tolerance;
  o.cone = settings_.cone;
  o.impratio = settings_.impratio;
  o.noslip_iterations = settings_.noslip_iterations;
  o.nconmax = capacity_.nconmax;
  o.njmax = capacity_.njmax;
  o.multiccd = multiccd_;
  // a group's geoms: the direct form without a spring, set per contact by
  // the rule once pressed (native mode; the other modes refuse groups)
  for (std::size_t g = 0; g < case_.contact_groups.size(); ++g) {
    PairParams p;
    p.solref = {0.0, 0.0};
    for (std::size_t i = 0; i < 5; ++i) p.solimp[i] = settings_.solimp[i];
    o.groups.push_back(p);
  }
  return o;
}

ModelPtr MujocoEngine::load(const MjcfOptions& options) {
  ModelPtr m = load_mjcf(write_mjcf(case_, plan_, options));
  layout_ = model_layout(m.get(), case_, plan_);
  return m;
}

PairParams MujocoEngine::pair_params(std::size_t k, bool inactive) const {
  PairParams p;
  // gap = margin: active below distance 0; inactive: never active
  const double margin = plan_.pairs[k].margin_m;
  p.gap_m = inactive ? margin + kInactiveGapM : margin;
  for (std::size_t i = 0; i < 5; ++i) p.solimp[i] = settings_.solimp[i];
  return p;
}

Calibration MujocoEngine::calibration(std::size_t k, const FirstTouch& t) const {
  const ContactPair& cp = case_.contacts[k];
  Calibration cal;
  if (t.found) {
    cal.effective_mass_kg = t.effective_mass_kg;
    cal.approach_speed_mps = t.approach_speed_mps;
    cal.source = fmt::format(
        "1/(J M^-1 J^T) from MuJoCo (mj_jac, mj_solveM) at the pair's first touch in a "
        "contact-free probe run: t = {:.6f} s, point ({:.6f}, {:.6f}) m, normal ({:.6f}, {:.6f})",
        t.time_s, t.point_m.x(), t.point_m.y(), t.normal_ab.x(), t.normal_ab.y());
  } else {
    cal.effective_mass_kg = reduced_mass_kg(case_.bodies[static_cast<std::size_t>(cp.body_a)],
                                            case_.bodies[static_cast<std::size_t>(cp.body_b)]);
    cal.approach_speed_mps = 0.0;
    cal.source =
        "the pair did not touch in the contact-free probe run: reduced mass of the two bodies "
        "(a normal through both centres of mass assumed)";
  }
  return cal;
}

// oracle: the law mapped once onto each pair's solref, calibrated at the
// pair's first touch in a contact-free probe run (foreknowledge)
void MujocoEngine::build_oracle(nlohmann::json& pairs, nlohmann::json& lost) {
  const std::size_t np = case_.contacts.size();
  MjcfOptions options = base_options();
  for (std::size_t k = 0; k < np; ++k) options.pairs.push_back(pair_params(k, true));
  const ModelPtr inactive = load(options);
  // where and how each pair first meets: calibrates the solref and tells how
  // many steps an impact spans
  long probe_steps = 0;
  const auto touch =
      probe_first_touch(inactive.get(), case_, layout_, case_.duration_s, probe_steps);
  options.pairs.clear();
  for (std::size_t k = 0; k < np; ++k) {
    if (!layout_.pairs[k].present) {
      options.pairs.push_back(pair_params(k, false));
      pairs.push_back({{"law", contact_law_name(case_.contacts[k].law)},
                       {"expressed_as", "nothing: both bodies are fixed"}});
      continue;
    }
    const LawMapping lm = map_contact_law(case_.contacts[k].law, calibration(k, touch[k]));
    PairParams p = pair_params(k, false);
    p.solref = lm.solref;
    options.pairs.push_back(p);
    pairs.push_back(lm.json);
    const double steps = lm.force_duration_s / dt_s_;
    pairs.back()["steps_per_impact"] = steps;
    if (steps < kMinStepsPerImpact) {
      lost.push_back(fmt::format(
          "pair '{}': one impact's force phase ({:.3g} s) spans only {:.3g} steps of {} s; "
          "the impact is not resolved (use mujoco.dt <= {:.2g})",
          case_.contacts[k].name, lm.force_duration_s, steps, dt_s_,
          lm.force_duration_s / (2.0 * kMinStepsPerImpact)));
    }
  }
  model_ = load(options);
  add_soft_contact_notes(settings_.solimp[1], lost);
  lost.push_back(
      "solref is per unit effective mass at one configuration (the first touch); where the "
      "effective mass changes with pose or contact point the physical stiffness changes "
      "with it");
}

void MujocoEngine::build(const Case& c, const SettingsOverrides& overrides) {
  binder_.apply(overrides);
  validate_mujoco_settings(settings_, overrides);
  inject_ = settings_.mode == "inject";
  oracle_ = settings_.mode == "oracle";
  const Capability cap = mujoco_capability(c, settings_.mode);
  if (cap.support == Support::unsupported) {
    throw EngineError("mujoco: cannot run case '" + c.name + "': " + cap.reason);
  }
  if (c.has_contact_groups() && settings_.integrator == "RK4") {
    throw EngineError(
        "mujoco: cannot run case '" + c.name +
        "' with mujoco.integrator=RK4: RK4's stages collide again and a contact group's "
        "contacts then take their geoms' solref, not the rule's per-pair one (a declared "
        "<pair> keeps it in m->pair_solref); use Euler");
  }
  case_ = c;
  plan_ = plan_mujoco(case_, settings_.detection_margin_m);
  multiccd_ = settings_.multiccd == "on" ||
              (settings_.multiccd == "auto" && group_meshes_meet(case_, plan_));
  capacity_ = contact_capacity(case_, plan_, settings_, model_dofs(case_, plan_), multiccd_);
  dt_s_ = settings_.dt_s;
  steps_ = 0;
  most_solver_iterations_ = 0;
  probe_steps_ = 0;
  injector_.reset();
  rule_.reset();
  const std::size_t np = case_.contacts.size();
  // every MuJoCo step this build takes (a trace, not the probe's own count)
  const long steps_at_start = integrations_on_this_thread();

  nlohmann::json pairs = nlohmann::json::array();
  nlohmann::json lost = nlohmann::json::array();
  auto not_simulated = [&](std::size_t k) {
    return nlohmann::json{{"law", contact_law_name(case_.contacts[k].law)},
                          {"expressed_as", "nothing: both bodies are fixed"}};
  };
  if (inject_) {
    // every pair inactive: MuJoCo finds the contacts, the adapter applies the law
    MjcfOptions options = base_options();
    for (std::size_t k = 0; k < np; ++k) options.pairs.push_back(pair_params(k, true));
    model_ = load(options);
    for (std::size_t k = 0; k < np; ++k) {
      if (!layout_.pairs[k].present) {
        pairs.push_back(not_simulated(k));
        continue;
      }
      pairs.push_back({{"law", contact_law_name(case_.contacts[k].law)},
                       {"expressed_as",
                        "the case's own law (contact_force_n) applied by the adapter at the "
                        "deepest MuJoCo contact of the pair"}});
    }
    lost.push_back(
        "the force acts at MuJoCo's contact geometry (deepest contact of the pair, its "
        "midpoint position, its normal); with Euler it is evaluated once per step at the "
        "step's start state, with RK4 at every stage");
    lost.push_back(
        "Lankarani-Nikravesh's approach speed is the normal rate at the first step with "
        "penetration > 0 (not at the interpolated onset)");
  } else if (oracle_) {
    build_oracle(pairs, lost);
  } else {
    // native: every pair active from the start; the rule sets its solref at
    // every step from the state the step starts from
    MjcfOptions options = base_options();
    for (std::size_t k = 0; k < np; ++k) {
      PairParams p = pair_params(k, false);
      p.solref = {0.0, 0.0};  // direct form, no spring: set by the rule once pressed
      options.pairs.push_back(p);
    }
    model_ = load(options);
    for (std::size_t k = 0; k < np; ++k) {
      if (!layout_.pairs[k].present) {
        pairs.push_back(not_simulated(k));
        continue;
      }
      pairs.push_back(native_pair_json(case_.contacts[k].law));
    }
    add_soft_contact_notes(settings_.solimp[1], lost);
    lost.push_back(
        "solref is one per pair and acceleration-based: MuJoCo solves the pair's rows together, "
        "so with several contacts the force is split as MuJoCo's solver splits it (a uniform "
        "penetration accelerates every contact point alike: for a face whose middle is not below "
        "the centre of mass the resultant lies under the centre of mass, not at the face's "
        "middle); with RK4 the solref of the step's start holds for its stages, and a contact "
        "appearing in a later stage keeps the pair's previous solref");
  }
  for (std::size_t k = 0; k < np; ++k) {
    const ContactPair& cp = case_.contacts[k];
    describe_pair(case_, plan_, k, pair_params(k, inject_), inject_, pairs[k], lost);
    if (cp.has_friction()) pairs[k]["friction"] = friction_mapping(cp.friction, settings_);
  }

  data_.reset(mj_makeData(model_.get()));
  set_initial_state(model_.get(), data_.get(), case_, layout_);
  watch_.reset(data_.get());
  fault_.clear();
  noted_count_.fill(0);
  noted_first_s_.fill(0.0);
  scratch_.emplace(model_.get());
  if (inject_) injector_ = std::make_unique<ForceInjector>(case_, model_.get(), layout_);
  if (!inject_ && !oracle_) rule_ = std::make_unique<SolrefRule>(case_, model_.get(), layout_);
  sampler_.emplace(case_, plan_, layout_);
  forward_current_ = false;
  sampled_ = false;
  probe_steps_ = integrations_on_this_thread() - steps_at_start;

  mapping_ = {
      {"engine", "mujoco"},
      {"version", version()},
      {"mode", settings_.mode},
      {"frame",
       "case (x, y) -> MuJoCo (x, z); gravity along -z; the case angle theta (ccw) is the "
       "hinge coordinate -theta about +y (a positive turn about +y is clockwise in the x-z "
       "view)"},
      {"stepping",
       fmt::format("{} at dt = {} s; mj_step split into mj_forward and "
                   "mj_Euler/mj_RungeKutta (bit-identical) to sample each step's start state{}",
                   settings_.integrator, settings_.dt_s,
                   rule_ ? "; native mode runs mj_forward's stages one by one with the solref "
                           "rule between mj_collision and mj_makeConstraint"
                         : "")},
      {"bodies", describe_bodies(case_, plan_)},
      {"pairs", pairs},
      {"not_expressed", lost},
  };
  if (capacity_.nconmax > 0 || capacity_.njmax > 0) mapping_["capacity"] = capacity_.json();
  if (case_.has_contact_groups()) {
    mapping_["groups"] = describe_groups(case_, plan_, settings_.solimp, mapping_["not_expressed"]);
  }

  std::optional<ForceInjector::Scope> scope;
  if (injector_) scope.emplace(*injector_);
  ensure_current();
}

void MujocoEngine::ensure_current() {
  mjModel* m = model_.get();
  mjData* d = data_.get();
  if (!forward_current_) {
    const ConstraintHook stiff =
        settings_.friction_damping == "stiff" ? &stiffen_friction_rows : nullptr;
    if (rule_) {
      forward_checked(m, d, &SolrefRule::hook, rule_.get(), stiff);
    } else {
      forward_checked(m, d, nullptr, nullptr, stiff);
    }
    check_warnings();
    most_solver_iterations_ = std::max(most_solver_iterations_, d->solver_iter);
    forward_current_ = true;
  }
  if (!sampled_) {
    sample();
    sampled_ = true;
  }
}

// MuJoCo's warning counters after every half step: a fault ends the run at
// the step it first occurs in, a noted warning is counted
void MujocoEngine::check_warnings() {
  for (const RaisedWarning& w : watch_.raised(data_.get())) {
    const auto k = static_cast<std::size_t>(w.warning);
    if (!warning_info(w.warning).fault) {
      if (noted_count_[k] == 0) noted_first_s_[k] = time();
      noted_count_[k] += w.count;
      continue;
    }
    fault_ = fault_reason(case_, layout_, w, time(), last_warning_text());
    if (w.warning == mjWARN_CONTACTFULL || w.warning == mjWARN_CNSTRFULL) {
      // the capacity is the adapter's (mujoco_capacity.hpp): say how to raise it
      fault_ += fmt::format(
          "; this run's capacity: nconmax {}, njmax {} ({}); mujoco.nconmax and mujoco.njmax "
          "set them, at {:.3g} bytes of mjData per row (njmax x nv and njmax^2 arrays)",
          model_->nconmax, model_->njmax, capacity_.rule,
          capacity_bytes(model_->nconmax, model_->njmax + 1, model_->nv) -
              capacity_bytes(model_->nconmax, model_->njmax, model_->nv));
    }
    throw EngineError(fault_);
  }
}

void MujocoEngine::sample() {
  sampler_->sample(model_.get(), data_.get(), time(), !inject_, {}, injector_.get());
}

void MujocoEngine::advance_to(double t_s) {
  if (!model_) throw EngineError("mujoco: advance_to before build");
  if (!fault_.empty()) throw EngineError(fault_);
  std::optional<ForceInjector::Scope> scope;
  if (injector_) scope.emplace(*injector_);
  while (static_cast<double>(steps_ + 1) * dt_s_ <= t_s + 1e-9 * dt_s_) {
    ensure_current();
    integrate(model_.get(), data_.get());
    ++steps_;
    forward_current_ = false;
    sampled_ = false;
    // RK4's stages run MuJoCo's pipeline too: their warnings belong to this step
    check_warnings();
  }
  ensure_current();
}

void MujocoEngine::body_states(std::vector<BodyState>& out) const {
  out.resize(case_.bodies.size());
  for (std::size_t i = 0; i < case_.bodies.size(); ++i) {
    out[i] = mujoco_body_state(model_.get(), data_.get(), case_, layout_, i);
  }
}

nlohmann::json MujocoEngine::mapping() const {
  nlohmann::json m = mapping_;
  if (rule_ && m.is_object()) {
    m["solref_rule_seen"] = rule_->seen_json();
  }
  if (sampler_ && m.is_object()) sampler_->add_depth_checks(m);
  return m;
}

Physics MujocoEngine::physics() const {
  Physics p;
  p.mode = settings_.mode;
  p.collision_by = "engine";
  p.collision =
      "MuJoCo's own colliders (mj_collision: plane, sphere, ellipsoid and convex mesh geoms, "
      "libccd MPR where no exact collider exists)";
  if (settings_.mode == "inject") {
    p.contact_force_by = "adapter (case law)";
    p.contact_force =
        "the case's law evaluated by the adapter at MuJoCo's contact geometry and applied "
        "through mjcb_passive; MuJoCo's contacts kept inactive";
    p.parameters = "the case's law as stated";
  } else if (settings_.mode == "oracle") {
    p.contact_force_by = "engine";
    p.contact_force = "MuJoCo's soft contact constraints (its constraint solver)";
    p.parameters =
        "one direct solref per pair calibrated at the pair's first touch in a contact-free "
        "probe run of the case (its effective mass and approach speed)";
    p.foreknowledge = true;
  } else {
    p.contact_force_by = "engine";
    p.contact_force = "MuJoCo's soft contact constraints (its constraint solver)";
    p.parameters =
        "each pair's direct solref set at every step from the case's law at the current "
        "penetration and the effective mass of the current configuration (MuJoCo's J M^-1 J^T "
        "over the pair's contacts)";
  }
  return p;
}

nlohmann::json MujocoEngine::extra_attributes() const {
  nlohmann::json j = nlohmann::json::object();
  nlohmann::json noted = nlohmann::json::array();
  for (int i = 0; i < mjNWARNING; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (noted_count_[k] == 0) continue;
    noted.push_back({{"warning", warning_info(i).name},
                     {"meaning", warning_info(i).meaning},
                     {"count", noted_count_[k]},
                     {"first_time_s", noted_first_s_[k]}});
  }
  if (!noted.empty()) j["mujoco_warnings_noted"] = noted;
  if (data_ && case_.has_contact_groups()) {
    // the capacity the run had and the most of it MuJoCo used in one step
    j["mujoco_capacity"] = {{"nconmax", model_->nconmax},
                            {"njmax", model_->njmax},
                            {"most_contacts", data_->maxuse_con},
                            {"most_rows", data_->maxuse_efc},
                            {"most_solver_iterations", most_solver_iterations_},
                            {"group_pairs_found", layout_.pairs.size() -
                                                      static_cast<std::size_t>(layout_.declared())}};
  }
  return j;
}

void MujocoEngine::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  if (sampler_) sampler_->contacts(out);
}

}  // namespace

std::unique_ptr<Engine> make_mujoco_engine() {
  return std::make_unique<MujocoEngine>();
}

}  // namespace pb
