// The mujoco3 adapter: engine "mujoco3" (MuJoCo 3.3.8, the npm package
// mujoco-js 0.0.7: MuJoCo's official WebAssembly build, run by Node).
// case -> plan -> MJCF -> steps, as the 2.2.2 adapter (mujoco_engine.cpp)
// with the same plan, the same MJCF writer (for MuJoCo 3: mujoco_major = 3),
// the same per-step solref rule and the same observations; only the steps run
// elsewhere. Each step, the WebAssembly side (wasm/server.mjs) runs MuJoCo
// 3.3.8's mj_step up to mj_collision and sends the contacts; this side
// answers each contact's solref by the rule (on the 2.2.2 mirror of the
// state, mujoco3_mirror.hpp); MuJoCo 3.3.8 re-adds the contacts with them,
// solves, sends each contact's force, and integrates on the next command.
// Native mode only (the WebAssembly build has no mjcb_passive for inject, and
// oracle's probe run is not ported).
#include "planarbench/adapters/mujoco3_engine.hpp"

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <deque>
#include <cmath>
#include <optional>

#include "mujoco3_batch.hpp"
#include "mujoco3_mirror.hpp"
#include "mujoco3_process.hpp"
#include "mujoco_capacity.hpp"
#include "mujoco_description.hpp"
#include "mujoco_fault.hpp"
#include "mujoco_friction.hpp"
#include "mujoco_mjcf.hpp"
#include "mujoco_model.hpp"
#include "mujoco_plan.hpp"
#include "mujoco_sampler.hpp"
#include "mujoco_settings.hpp"
#include "mujoco_solref_rule.hpp"
#include "mujoco_stepping.hpp"
#include "mujoco_support.hpp"
#include "planarbench/errors.hpp"

namespace pb {

namespace {

using namespace internal::mujoco;
using namespace internal::mujoco3;

// s: how long `list` waits for the library's version
constexpr double kVersionTimeoutS = 60.0;

// steps computed ahead of the runner's sampling in one command, at most
constexpr long kStepsAhead = 1000;

thread_local long t_steps = 0;

// the last line of a text (MuJoCo's last warning)
std::string last_line(const std::string& text) {
  const auto nl = text.rfind('\n');
  return nl == std::string::npos ? text : text.substr(nl + 1);
}  // every STEP sent on this thread (the no-look-ahead trace)

// the library's own version (mj_versionString), the package's and Node's,
// asked once per process
const std::string& wasm_version() {
  static const std::string v = [] {
    const Mujoco3Install& in = mujoco3_install();
    if (!in.available) return "unavailable: " + in.reason;
    try {
      // PB_MUJOCO3_TIMEOUT_S when set (a hung server.mjs made `list` wait
      // 60 s at a 3 s limit: issue 49)
      Mujoco3Process p(in, mujoco3_answer_timeout_s(kVersionTimeoutS));
      p.send(Kind::version, nullptr, 0);
      const auto j = p.receive_info("VERSION", {{"version", JsonField::string},
                                                {"package", JsonField::string},
                                                {"node", JsonField::string}});
      return fmt::format("{} (mujoco-js {}, MuJoCo's WebAssembly build, Node {})",
                         j.at("version").get<std::string>(), j.at("package").get<std::string>(),
                         j.at("node").get<std::string>());
    } catch (const std::exception& e) {
      return fmt::format("unavailable: {}", e.what());
    }
  }();
  return v;
}

class Mujoco3Engine final : public Engine {
 public:
  Mujoco3Engine() : binder_(bind_mujoco_settings(settings_, MujocoLine::v3)) {}

  std::string name() const override { return "mujoco3"; }
  std::string version() const override { return wasm_version(); }
  Capability supports(const Case& c) const override {
    const Mujoco3Install& in = mujoco3_install();
    if (!in.available) return {Support::unsupported, "mujoco3 unavailable: " + in.reason};
    return mujoco_capability(c, "native", MujocoLine::v3);
  }
  const SettingsBinder& settings() const override { return binder_; }

  void build(const Case& c, const SettingsOverrides& overrides) override;
  void advance_to(double t_s) override;
  double time() const override { return static_cast<double>(steps_) * settings_.dt_s; }
  void body_states(std::vector<BodyState>& out) const override;
  void contacts(std::vector<ContactSample>& out) const override;
  std::vector<ContactEpisode> episodes() const override {
    return sampler_ ? sampler_->episodes() : std::vector<ContactEpisode>{};
  }
  long steps() const override { return steps_; }
  nlohmann::json mapping() const override;
  nlohmann::json extra_attributes() const override;
  Physics physics() const override;
  [[nodiscard]] long library_steps_on_this_thread() const override { return t_steps; }

 private:
  MjcfOptions options(int major) const;
  // one step's outcome as MuJoCo 3.3.8 computed it
  struct Record {
    long step = 0;
    std::vector<double> warnings;  // numbers[8], lastinfo[8]
    std::size_t ncon = 0;
    std::vector<double> numbers;   // qpos, qvel, then kRecordContactNumbers per contact
  };
  // one command (START with the state, or RUN n): the records of its steps
  // into pending_, answering each question with the rule's solrefs
  void fetch(Kind command, const std::vector<double>& payload);
  // a fault among a step's warnings ends the run when that step is reached
  void note_warnings(long step, std::span<const double> warnings);
  // a step's record as the current state: the mirror, the observations
  void consume(const Record& rec);

  MujocoSettings settings_;
  SettingsBinder binder_;
  Case case_;
  MujocoPlan plan_;
  ContactCapacity capacity_;  // the mirror's nconmax (2.2.2's rule)
  bool multiccd_ = false;     // <flag multiccd> (mujoco3.multiccd)
  ModelPtr mirror_model_;
  DataPtr mirror_data_;
  ModelLayout layout_;
  std::unique_ptr<SolrefRule> rule_;
  std::optional<PairSampler> sampler_;
  std::unique_ptr<Mujoco3Process> process_;
  WarningWatch watch_;
  std::string fault_;
  std::string pending_fault_;    // the fault of step fault_step_, not reached yet
  long fault_step_ = -1;
  std::deque<Record> pending_;   // computed, not yet reached
  long computed_ = 0;            // the step of the next record
  std::vector<double> in_;
  std::vector<double> out_;
  std::vector<double> forces_;
  long steps_ = 0;
  nlohmann::json mapping_ = nlohmann::json::object();
};

MjcfOptions Mujoco3Engine::options(int major) const {
  MjcfOptions o;
  o.dt_s = settings_.dt_s;
  o.integrator = major >= 3 ? settings_.integrator : "Euler";
  o.solver = settings_.solver;
  o.iterations = settings_.iterations;
  o.tolerance = settings_.tolerance;
  o.cone = settings_.cone;
  o.impratio = settings_.impratio;
  o.noslip_iterations = settings_.noslip_iterations;
  o.mujoco_major = major;
  if (major >= 3) o.solreffriction = {settings_.solreffriction[0], settings_.solreffriction[1]};
  // MuJoCo 3 keeps contacts and rows in its arena (its default size unless
  // mujoco3.memory_mb); the 2.2.2 mirror holds the contacts only, so it is
  // given the rule's nconmax and MuJoCo's default njmax (it makes no rows)
  o.multiccd = multiccd_;
  if (major >= 3) {
    o.memory_mb = settings_.memory_mb;
  } else {
    o.nconmax = capacity_.nconmax;
  }
  for (std::size_t g = 0; g < case_.contact_groups.size(); ++g) {
    PairParams p;
    p.solref = {0.0, 0.0};  // set per contact by the rule once pressed
    for (std::size_t i = 0; i < 5; ++i) p.solimp[i] = settings_.solimp[i];
    o.groups.push_back(p);
  }
  for (std::size_t k = 0; k < case_.contacts.size(); ++k) {
    PairParams p;
    p.gap_m = plan_.pairs[k].margin_m;  // active below distance 0
    for (std::size_t i = 0; i < 5; ++i) p.solimp[i] = settings_.solimp[i];
    p.solref = {0.0, 0.0};  // direct form, no spring: set by the rule once pressed
    o.pairs.push_back(p);
  }
  return o;
}

void Mujoco3Engine::build(const Case& c, const SettingsOverrides& overrides) {
  binder_.apply(overrides);
  validate_mujoco_settings(settings_, overrides, MujocoLine::v3);
  const Capability cap = supports(c);
  if (cap.support == Support::unsupported) {
    throw EngineError("mujoco3: cannot run case '" + c.name + "': " + cap.reason);
  }
  if (c.has_contact_groups() && settings_.integrator == "RK4") {
    throw EngineError(
        "mujoco3: cannot run case '" + c.name +
        "' with mujoco3.integrator=RK4: RK4's stages collide again and a contact group's "
        "contacts then take their geoms' solref, not the rule's per-pair one; use Euler, "
        "implicit or implicitfast");
  }
  case_ = c;
  plan_ = plan_mujoco(case_, settings_.detection_margin_m);
  // the mirror's contact capacity: 2.2.2's rule, or mujoco3.nconmax
  MujocoSettings mirror = settings_;
  mirror.njmax = 0;
  multiccd_ = settings_.multiccd == "on" ||
              (settings_.multiccd == "auto" && group_meshes_meet(case_, plan_));
  capacity_ = contact_capacity(case_, plan_, mirror, model_dofs(case_, plan_), multiccd_);
  steps_ = 0;
  computed_ = 0;
  fault_step_ = -1;
  pending_fault_.clear();
  pending_.clear();
  fault_.clear();
  sampler_.reset();
  rule_.reset();
  process_.reset();

  // the mirror: the same MJCF for MuJoCo 2.2.2, without what only 3 reads
  mirror_model_ = load_mjcf(write_mjcf(case_, plan_, options(2)));
  layout_ = model_layout(mirror_model_.get(), case_, plan_);
  mirror_data_.reset(mj_makeData(mirror_model_.get()));
  set_initial_state(mirror_model_.get(), mirror_data_.get(), case_, layout_);
  rule_ = std::make_unique<SolrefRule>(case_, mirror_model_.get(), layout_);
  sampler_.emplace(case_, plan_, layout_);

  const std::string xml = write_mjcf(case_, plan_, options(3));
  process_ = std::make_unique<Mujoco3Process>(mujoco3_install(), mujoco3_answer_timeout_s());
  process_->send(Kind::load, xml.data(), xml.size());
  const auto info = process_->receive_info(
      "LOAD", {{"version", JsonField::string}, {"nq", JsonField::integer}, {"nv", JsonField::integer},
               {"ngeom", JsonField::integer}, {"nbody", JsonField::integer},
               {"npair", JsonField::integer}, {"integrator", JsonField::string}});
  const mjModel* m = mirror_model_.get();
  // the same MJCF must give the same layout in both versions
  const std::array<std::pair<const char*, int>, 5> sizes = {
      {{"nq", m->nq}, {"nv", m->nv}, {"ngeom", m->ngeom}, {"nbody", m->nbody}, {"npair", m->npair}}};
  for (const auto& [key, n] : sizes) {
    if (info.at(key).get<int>() != n) {
      throw EngineError(fmt::format("mujoco3: MuJoCo 3 compiled the case with {} = {}, MuJoCo "
                                    "2.2.2 (the rule's mirror) with {}",
                                    key, info.at(key).get<int>(), n));
    }
  }
  watch_.reset(mirror_data_.get());

  nlohmann::json pairs = nlohmann::json::array();
  nlohmann::json lost = nlohmann::json::array();
  const std::size_t np = case_.contacts.size();
  const MjcfOptions o3 = options(3);
  for (std::size_t k = 0; k < np; ++k) {
    const ContactPair& cp = case_.contacts[k];
    if (!layout_.pairs[k].present) {
      pairs.push_back({{"law", contact_law_name(cp.law)},
                       {"expressed_as", "nothing: both bodies are fixed"}});
    } else {
      pairs.push_back(native_pair_json(cp.law));
    }
    describe_pair(case_, plan_, k, o3.pairs[k], false, pairs[k], lost, MujocoLine::v3);
    if (cp.has_friction()) {
      pairs[k]["friction"] = friction_mapping(cp.friction, settings_, MujocoLine::v3);
    }
  }
  add_soft_contact_notes(settings_.solimp[1], lost);
  lost.push_back(
      "solref is one per pair and acceleration-based: MuJoCo solves the pair's rows together, "
      "so with several contacts the force is split as MuJoCo's solver splits it; with RK4 the "
      "solref of the step's start holds for its stages");
  mapping_ = {
      {"engine", "mujoco3"},
      {"version", version()},
      {"mode", "native"},
      {"frame",
       "case (x, y) -> MuJoCo (x, z); gravity along -z; the case angle theta (ccw) is the "
       "hinge coordinate -theta about +y"},
      {"stepping",
       fmt::format(
           "{} at dt = {} s in MuJoCo {}: mj_step's own sequence (mj_checkPos, mj_checkVel, "
           "mj_forward's stages one by one, mj_checkAcc, then the integrator) in the "
           "WebAssembly side; between mj_collision and mj_makeConstraint each contact is "
           "copied out, given the rule's solref and re-added (mj_addContact: this build has no "
           "mjcb_ callbacks)",
           settings_.integrator, settings_.dt_s, info.at("version").get<std::string>())},
      {"rule_mirror",
       "the solref rule and the observations read a MuJoCo 2.2.2 model of the same MJCF (the "
       "same qpos layout, mass matrix and Jacobians; checked: nq, nv, ngeom, nbody, npair "
       "agree) set to MuJoCo 3.3.8's qpos, qvel and contacts at every step, so the rule is "
       "the 2.2.2 adapter's, written once; the forces are 3.3.8's mj_contactForce"},
      {"bodies", describe_bodies(case_, plan_)},
      {"pairs", pairs},
      {"not_expressed", lost},
  };
  if (case_.has_contact_groups()) {
    mapping_["groups"] = describe_groups(case_, plan_, settings_.solimp, mapping_["not_expressed"],
                                         MujocoLine::v3);
    mapping_["capacity"] = {
        {"mujoco3",
         settings_.memory_mb > 0
             ? fmt::format("<size memory=\"{}M\"> (mujoco3.memory_mb): contacts, rows and the "
                           "solver's stack share it",
                           settings_.memory_mb)
             : std::string("MuJoCo 3's default arena (its heuristic from nv; no <size>): "
                           "contacts, rows and the solver's stack share it")},
        {"mirror_nconmax", capacity_.nconmax},
        {"mirror_rule", capacity_.rule}};
  }

  // the initial state, as 2.2.2's adapter sets it (set_initial_state)
  out_.assign(mirror_data_->qpos, mirror_data_->qpos + m->nq);
  out_.insert(out_.end(), mirror_data_->qvel, mirror_data_->qvel + m->nv);
  fetch(Kind::start, out_);
  consume(pending_.front());
  pending_.pop_front();
}

void Mujoco3Engine::fetch(Kind command, const std::vector<double>& payload) {
  mjModel* m = mirror_model_.get();
  mjData* d = mirror_data_.get();
  const BatchLayout layout{static_cast<std::size_t>(m->nq), static_cast<std::size_t>(m->nv),
                           static_cast<std::size_t>(m->ngeom)};
  process_->send_numbers(command, payload);
  for (;;) {
    process_->receive_numbers(Kind::batch, in_);
    // the whole message checked before any of it is used (mujoco3_batch.hpp)
    const Batch batch = read_batch(in_, layout);
    for (const BatchStep& s : batch.records) {
      Record rec;
      rec.step = computed_++;
      rec.ncon = s.ncon;
      rec.numbers.assign(s.qpos.begin(), s.qpos.end());
      rec.numbers.insert(rec.numbers.end(), s.qvel.begin(), s.qvel.end());
      rec.numbers.insert(rec.numbers.end(), s.contacts.begin(), s.contacts.end());
      // a step nobody asked about has no contact in the constraint: the rule
      // sets nothing there, but it sees the step (a contact's end). With no
      // pressed contact it reads the contacts only, never the state's
      // Jacobians: the mirror's kinematics wait for consume()
      if (!s.asked && fault_step_ < 0) {
        mirror_contacts(m, d, s.contacts, rec.ncon, kRecordContactNumbers);
        SolrefRule::hook(rule_.get(), m, d);
      }
      note_warnings(rec.step, s.warnings);
      pending_.push_back(std::move(rec));
    }
    if (!batch.question) return;
    // the question: the contacts of step computed_ after mj_collision
    const BatchStep& q = *batch.question;
    note_warnings(computed_, q.warnings);
    mirror_state(m, d, q.qpos, q.qvel);
    mirror_contacts(m, d, q.contacts, q.ncon, kContactNumbers);
    // the rule, once: each contact's solref (and m->pair_solref, which RK4's
    // stages reuse), and the contacts fused at a shared vertex
    SolrefRule::hook(rule_.get(), m, d);
    out_.clear();
    out_.insert(out_.end(), m->pair_solref, m->pair_solref + mjNREF * m->npair);
    for (std::size_t i = 0; i < q.ncon; ++i) {
      const mjContact& con = d->contact[i];
      out_.push_back(con.solref[0]);
      out_.push_back(con.solref[1]);
      out_.push_back(static_cast<double>(con.exclude));
    }
    process_->send_numbers(Kind::solrefs, out_);
  }
}

void Mujoco3Engine::note_warnings(long step, std::span<const double> warnings) {
  if (fault_step_ >= 0) return;
  mirror_warnings(mirror_data_.get(), warnings);
  for (const RaisedWarning& w : watch_.raised(mirror_data_.get())) {
    if (!warning_info(w.warning).fault) continue;
    // fault_reason names the engine "mujoco"; this run is MuJoCo 3's
    const std::string reason =
        fault_reason(case_, layout_, w, static_cast<double>(step) * settings_.dt_s,
                     last_line(process_->stderr_tail()));
    pending_fault_ = "mujoco3" + reason.substr(reason.find(':'));
    fault_step_ = step;
    return;
  }
}

void Mujoco3Engine::consume(const Record& rec) {
  mjModel* m = mirror_model_.get();
  mjData* d = mirror_data_.get();
  const auto nq = static_cast<std::size_t>(m->nq);
  const auto nv = static_cast<std::size_t>(m->nv);
  steps_ = rec.step;
  if (rec.step == fault_step_) {
    fault_ = pending_fault_;
    throw EngineError(fault_);
  }
  const std::span<const double> v(rec.numbers);
  mirror_state(m, d, v.subspan(0, nq), v.subspan(nq, nv));
  const auto contacts = v.subspan(nq + nv);
  mirror_contacts(m, d, contacts, rec.ncon, kRecordContactNumbers);
  forces_.resize(6 * rec.ncon);
  for (std::size_t i = 0; i < rec.ncon; ++i) {
    const auto f = contacts.subspan(i * kRecordContactNumbers + kContactNumbers + 1, 6);
    std::copy(f.begin(), f.end(), forces_.begin() + static_cast<std::ptrdiff_t>(6 * i));
  }
  sampler_->sample(m, d, time(), true, forces_, nullptr);
}

void Mujoco3Engine::advance_to(double t_s) {
  if (!process_) throw EngineError("mujoco3: advance_to before build");
  if (!fault_.empty()) throw EngineError(fault_);
  const double dt = settings_.dt_s;
  long target = steps_;
  while (static_cast<double>(target + 1) * dt <= t_s + 1e-9 * dt) ++target;
  // the steps up to the case's end are computed ahead in chunks (each from
  // its own past only: the same bits as one at a time), never beyond it
  const auto last_step = static_cast<long>(std::floor(case_.duration_s / dt + 1e-9));
  while (computed_ <= target) {
    const long n = std::max(target - computed_ + 1,
                            std::min(kStepsAhead, last_step - computed_ + 1));
    t_steps += n;
    fetch(Kind::run, {static_cast<double>(n)});
  }
  while (!pending_.empty() && pending_.front().step <= target) {
    consume(pending_.front());
    pending_.pop_front();
  }
}

void Mujoco3Engine::body_states(std::vector<BodyState>& out) const {
  out.resize(case_.bodies.size());
  for (std::size_t i = 0; i < case_.bodies.size(); ++i) {
    out[i] = mujoco_body_state(mirror_model_.get(), mirror_data_.get(), case_, layout_, i);
  }
}

void Mujoco3Engine::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  if (sampler_) sampler_->contacts(out);
}

nlohmann::json Mujoco3Engine::mapping() const {
  nlohmann::json m = mapping_;
  if (rule_ && m.is_object()) {
    m["solref_rule_seen"] = rule_->seen_json();
  }
  if (sampler_ && m.is_object()) sampler_->add_depth_checks(m);
  return m;
}

nlohmann::json Mujoco3Engine::extra_attributes() const {
  nlohmann::json j = nlohmann::json::object();
  if (!case_.has_contact_groups() || !process_ || !fault_.empty()) return j;
  // MuJoCo 3's arena and the most of it used (mjData::maxuse_*)
  try {
    process_->send(Kind::stats, nullptr, 0);
    j["mujoco3_capacity"] = process_->receive_info(
        "STATS", {{"narena_bytes", JsonField::number}, {"maxuse_arena_bytes", JsonField::number},
                  {"most_contacts", JsonField::integer}, {"most_rows", JsonField::integer}});
    j["mujoco3_capacity"]["group_pairs_found"] =
        layout_.pairs.size() - static_cast<std::size_t>(layout_.declared());
  } catch (const std::exception& e) {
    j["mujoco3_capacity"] = {{"unavailable", e.what()}};
  }
  return j;
}

Physics Mujoco3Engine::physics() const {
  Physics p;
  p.mode = "native";
  p.collision_by = "engine";
  p.collision = "MuJoCo 3.3.8's own colliders (mj_collision in its WebAssembly build)";
  p.contact_force_by = "engine";
  p.contact_force = "MuJoCo 3.3.8's soft contact constraints (its constraint solver)";
  p.parameters =
      "each pair's direct solref set at every step from the case's law at the current "
      "penetration and the effective mass of the current configuration (the rule of engine "
      "mujoco, on a 2.2.2 mirror of 3.3.8's state and contacts)";
  return p;
}

}  // namespace

std::unique_ptr<Engine> make_mujoco3_engine() {
  return std::make_unique<Mujoco3Engine>();
}

}  // namespace pb
