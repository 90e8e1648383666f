// Engine "reference": the paper's algorithm (Jun, Sohn, Yoo), wrapped in the
// planarbench engine interface. The work is in reference_solver.hpp.
#include "planarbench/reference/reference_engine.hpp"

#include <algorithm>

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "planarbench/errors.hpp"
#include "planarbench/reference/coulomb_friction.hpp"
#include "planarbench/reference/pair_geometry.hpp"
#include "planarbench/reference/planar_model.hpp"
#include "planarbench/reference/reference_settings.hpp"
#include "planarbench/reference/reference_solver.hpp"

namespace pb {

namespace {

class ReferenceEngine final : public Engine {
 public:
  ReferenceEngine() : binder_("reference") { bind_reference_settings(binder_, settings_); }

  [[nodiscard]] std::string name() const override { return "reference"; }

  [[nodiscard]] std::string version() const override {
    return "planarbench reference 0.1 (outline contact of Jun, Sohn & Yoo; Dormand-Prince 5(4) "
           "and classic RK4 with located events)";
  }

  [[nodiscard]] Capability supports(const Case& c) const override {
    try {
      const PlanarModel model(c);
    } catch (const std::invalid_argument& e) {
      return Capability{Support::unsupported, e.what()};
    }
    const GeometryMode mode =
        settings_.geometry == "exact" ? GeometryMode::exact : GeometryMode::outline;
    const int nb = static_cast<int>(c.bodies.size());
    for (const auto& p : c.contacts) {
      if (p.body_a < 0 || p.body_a >= nb || p.body_b < 0 || p.body_b >= nb) {
        return Capability{Support::unsupported, "contact pair '" + p.name + "' names no body"};
      }
      std::string reason;
      if (!PairGeometry::supported(c.bodies[static_cast<std::size_t>(p.body_a)],
                                   c.bodies[static_cast<std::size_t>(p.body_b)], mode, &reason)) {
        return Capability{Support::unsupported, "pair '" + p.name + "': " + reason};
      }
    }
    // a group's pairs: one body of each kind of shape stands for the others
    for (const ContactGroup& g : c.contact_groups) {
      std::vector<int> kinds;
      for (const int i : g.bodies) {
        const Body& b = c.bodies[static_cast<std::size_t>(i)];
        const bool seen = std::any_of(kinds.begin(), kinds.end(), [&](int j) {
          const Body& o = c.bodies[static_cast<std::size_t>(j)];
          return o.shape.index() == b.shape.index() && o.fixed == b.fixed;
        });
        if (!seen) kinds.push_back(i);
      }
      for (std::size_t x = 0; x < kinds.size(); ++x) {
        for (std::size_t y = x + 1; y < kinds.size(); ++y) {
          const Body& a = c.bodies[static_cast<std::size_t>(kinds[x])];
          const Body& b = c.bodies[static_cast<std::size_t>(kinds[y])];
          if (a.fixed && b.fixed) continue;
          std::string reason;
          if (!PairGeometry::supported(a, b, mode, &reason)) {
            return Capability{Support::unsupported, "contact group '" + g.name + "': " + reason};
          }
        }
      }
    }
    return Capability{Support::native, ""};
  }

  [[nodiscard]] const SettingsBinder& settings() const override { return binder_; }

  void build(const Case& c, const SettingsOverrides& overrides) override {
    binder_.apply(overrides);
    solver_.reset();
    bodies_ = static_cast<int>(c.bodies.size());
    pair_laws_ = nlohmann::json::object();
    friction_ = nlohmann::json::object();
    pair_names_.clear();
    for (const auto& p : c.contacts) {
      pair_laws_[p.name] = contact_law_name(p.law);
      pair_names_.push_back(p.name);
      if (p.has_friction()) friction_[p.name] = p.friction;
    }
    for (const auto& g : c.contact_groups) {
      pair_laws_[g.name] = contact_law_name(g.law);
      if (g.has_friction()) friction_[g.name] = g.friction;
    }
    has_groups_ = c.has_contact_groups();
    outline_points_ = nlohmann::json::object();
    for (const auto& b : c.bodies) outline_points_[b.name] = b.outline_points;
    try {
      solver_ = std::make_unique<ReferenceSolver>(c, settings_);
    } catch (const std::invalid_argument& e) {
      throw EngineError(fmt::format("reference cannot build case '{}': {}", c.name, e.what()));
    }
  }

  void advance_to(double t_s) override { solver().advance_to(t_s); }
  [[nodiscard]] double time() const override { return solver_ ? solver_->time() : 0.0; }

  void body_states(std::vector<BodyState>& out) const override {
    out.resize(static_cast<std::size_t>(bodies_));
    for (int i = 0; i < bodies_; ++i) out[static_cast<std::size_t>(i)] = solver().body_state(i);
  }

  void contacts(std::vector<ContactSample>& out) const override { solver().contacts(out); }

  [[nodiscard]] std::vector<ContactEpisode> episodes() const override {
    return solver_ ? solver_->episodes() : std::vector<ContactEpisode>{};
  }

  [[nodiscard]] long steps() const override { return solver_ ? solver_->stats().steps : 0; }
  [[nodiscard]] long library_steps_on_this_thread() const override {
    return reference_steps_on_this_thread();
  }

  [[nodiscard]] nlohmann::json mapping() const override {
    nlohmann::json m;
    m["contact_law"] = pair_laws_;
    m["expressed_as"] =
        "natively: each pair's law through the shared contact_force_n (paper eqs. 1-7; never "
        "pulls; Lankarani-Nikravesh delta_dot^- latched when the contact is declared; K of eq. 3 "
        "with the published square root)";
    m["geometry"] =
        settings_.geometry == "exact"
            ? "exact: true circle / ellipse / infinite line / polygon (exact_contact.hpp)"
            : "outline: the paper's outline points (§2.1.1), every point against the other "
              "outline's edges (detection=brute: exhaustively; detection=fast: bounding-volume "
              "trees, the same result); half-plane = its surface segment of outline_points points";
    m["outline_points"] = outline_points_;
    m["contact_model"] =
        "one contact per pair: the penetration and normal of the deepest point, the line of "
        "action through the depth-weighted centroid of the inside points of every overlap region "
        "(of both bodies for two polygons, whose faces are sampled at 180 points); the force acts "
        "at the contact points (torques included)";
    if (has_groups_) {
      m["contact_groups"] =
          "every pair of a group may touch: a Verlet list over bounding boxes fattened by a "
          "quarter of each body's reach (sort and sweep), rebuilt when a body has moved half its "
          "margin, a trial step moving one past its margin taken shorter (near_pairs.hpp); only "
          "the near pairs run the narrow phase; sticking pairs solved together sparsely";
    }
    m["joints"] = "joint coordinates: revolute joints to ground hold by construction";
    if (!friction_.empty()) {
      m["friction"] = {
          {"coefficient", friction_},
          {"model",
           "Coulomb, one coefficient (SPEC §7), at the pair's contact points while the normal "
           "force presses: slip f = -mu F along the slip; stick rigid (the limit of a tangential "
           "spring capped by Coulomb): the force that keeps the points' relative tangential "
           "acceleration at -100/s x their slip speed, solved for all stuck pairs together; "
           "stick / slip changes located as events (coulomb_friction.hpp)"},
          {"stick_speed_mps", kStickSpeed_mps},
          {"stick_rate_per_s", kStickRate_per_s}};
    }
    m["not_expressed"] = nlohmann::json::array();
    return m;
  }

  [[nodiscard]] Physics physics() const override {
    Physics p;
    p.mode = settings_.geometry;
    p.collision_by = "reference";
    p.collision = settings_.geometry == "exact"
                      ? "the exact shapes (circle, ellipse, polygon, line) in closed form"
                      : "the paper's outline search (§2.1.1): the closest outline points refined "
                        "on their neighbours, penetration from the points inside the other body";
    p.contact_force_by = "reference (case law)";
    p.contact_force =
        "the case's law (paper eqs. 1-7), one force per pair at the depth-weighted contact point, "
        "integrated with located contact events";
    p.parameters = "the case's law as stated";
    return p;
  }

  [[nodiscard]] nlohmann::json extra_attributes() const override {
    nlohmann::json x = nlohmann::json::object();
    if (!solver_) return x;
    const SolverStats s = solver_->stats();
    x["constraint_drift_m"] = s.constraint_drift_m;
    x["constraint_drift_note"] =
        "joint coordinates: the joints hold by construction; this is the largest distance, over "
        "the accepted steps, between each pendulum's anchor point reconstructed from its state "
        "and its world pivot (rounding only)";
    x["geometry"] = settings_.geometry;
    x["detection"] = settings_.detection;
    x["integrator"] = settings_.integrator;
    x["rhs_evaluations"] = s.rhs_evaluations;
    x["rejected_steps"] = s.rejected;
    x["events_located"] = s.events;
    if (has_groups_) x["broad_phase_rebuilds"] = solver_->near_rebuilds();
    if (!friction_.empty()) {
      x["friction_dissipation_j"] = solver_->friction_dissipation_j();
      nlohmann::json jt = nlohmann::json::object();
      for (std::size_t k = 0; k < pair_names_.size(); ++k) {
        jt[pair_names_[k]] = solver_->tangential_impulse_ns(static_cast<int>(k));
      }
      x["tangential_impulse_ns"] = jt;
      x["friction_note"] =
          "integrated with the motion over the whole run: the energy friction dissipated (J) "
          "and each pair's tangential impulse on its body_b (N s, along t = (n.y, -n.x))";
    }
    return x;
  }

 private:
  [[nodiscard]] ReferenceSolver& solver() const {
    if (!solver_) throw EngineError("reference: build() was not called");
    return *solver_;
  }

  ReferenceSettings settings_;
  SettingsBinder binder_;
  std::unique_ptr<ReferenceSolver> solver_;
  int bodies_ = 0;
  nlohmann::json pair_laws_ = nlohmann::json::object();
  nlohmann::json friction_ = nlohmann::json::object();  // pair name -> coefficient
  std::vector<std::string> pair_names_;  // declared pairs
  bool has_groups_ = false;
  nlohmann::json outline_points_ = nlohmann::json::object();
};

}  // namespace

std::unique_ptr<Engine> make_reference_engine() { return std::make_unique<ReferenceEngine>(); }

}  // namespace pb
