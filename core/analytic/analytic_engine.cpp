// The truth: engine "analytic" (SPEC §3). It evaluates, at any time asked,
// the exact solution of the cases that have one: a body translating on a line
// (falling_ball, sliding, square_landing, concave_arch, incline_launch), two
// disks head on (head_on), and pendulums up to their first contact
// (dual_pendulum, pendulum_wall); there it has no time step: advance_to lands
// on t exactly, and steps() counts the phases of the piecewise closed form
// begun so far. Where the closed form ends (after the pendulums' first
// contact) or where there is none (truth = converged), the truth is
// numerical (numerical_truth.hpp): the independent truth (core/independent,
// no code shared with the reference solver or the adapters) where it covers
// the case, with its agreement with the converged reference in the mapping;
// else the reference solver at exact geometry and tight tolerance, with a
// Richardson estimate of its error (converged_reference.hpp). The mapping
// says which part is which.
#include "planarbench/analytic/analytic_engine.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>

#include "body_on_line.hpp"
#include "closed_form_match.hpp"
#include "numerical_truth.hpp"
#include "pendulums_until_contact.hpp"
#include "planarbench/build_info.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/reference/pair_geometry.hpp"
#include "disk_row.hpp"
#include "resting_stack.hpp"
#include "two_disks_head_on.hpp"

namespace pb {

namespace {

// the independent truth in one line (supports())
constexpr const char* kIndependentText =
    "the independent truth (core/independent): exact geometry in closed form, the law written "
    "again from the paper's equations, Boost.Odeint dopri5 at abs and rel 1e-12 with located "
    "contact events; its agreement with the converged reference in the mapping";

// why the reference at exact geometry cannot run the case ("" when it can)
std::string exact_geometry_reason(const Case& c) {
  for (const ContactPair& p : c.contacts) {
    std::string why;
    if (p.body_a < 0 || p.body_b < 0 ||
        static_cast<std::size_t>(p.body_a) >= c.bodies.size() ||
        static_cast<std::size_t>(p.body_b) >= c.bodies.size()) {
      return fmt::format("contact pair '{}' names a body that does not exist", p.name);
    }
    if (!PairGeometry::supported(c.bodies[static_cast<std::size_t>(p.body_a)],
                                 c.bodies[static_cast<std::size_t>(p.body_b)],
                                 GeometryMode::exact, &why)) {
      return fmt::format("contact pair '{}': {}", p.name, why);
    }
  }
  return {};
}

class AnalyticEngine final : public Engine {
 public:
  // nothing to set: a closed form has no tolerance or step
  AnalyticEngine() : binder_("analytic") {}

  [[nodiscard]] std::string name() const override { return "analytic"; }
  [[nodiscard]] std::string version() const override {
    return fmt::format("closed form (planarbench {})", build_info::kVersion);
  }

  [[nodiscard]] Capability supports(const Case& c) const override {
    if (c.truth == TruthKind::converged) {
      if (internal::NumericalTruth::independent_unsupported(c).empty()) {
        return {Support::mapped, std::string("no closed form: the truth is ") + kIndependentText};
      }
      if (auto why = exact_geometry_reason(c); !why.empty()) {
        return {Support::unsupported, "truth = converged: " + why};
      }
      return {Support::mapped,
              "no closed form: the truth is the reference solver at exact geometry, rk45 at "
              "rtol 1e-12, shown converged (Richardson estimate in the mapping)"};
    }
    const internal::ClosedFormMatch m = internal::match_closed_form(c);
    if (m.kind == internal::ClosedFormKind::none) return {Support::unsupported, m.reason};
    if (m.kind == internal::ClosedFormKind::pendulums_until_contact) {
      if (internal::NumericalTruth::independent_unsupported(c).empty()) {
        return {Support::mapped,
                std::string("closed form up to the first contact; after it ") + kIndependentText};
      }
      if (auto why = exact_geometry_reason(c); !why.empty()) {
        return {Support::unsupported, "after the first contact: " + why};
      }
      return {Support::mapped,
              "closed form up to the first contact; after it the reference solver at exact "
              "geometry, rk45 at rtol 1e-12, shown converged (Richardson estimate in the mapping)"};
    }
    return {Support::native, {}};
  }

  [[nodiscard]] const SettingsBinder& settings() const override { return binder_; }

  void build(const Case& c, const SettingsOverrides& overrides) override {
    binder_.apply(overrides);
    body_.reset();
    disks_.reset();
    stack_.reset();
    row_.reset();
    pendulums_.reset();
    numeric_.reset();
    time_s_ = 0.0;
    handover_s_ = std::numeric_limits<double>::infinity();
    if (c.truth == TruthKind::converged) {
      if (auto why = exact_geometry_reason(c);
          !why.empty() && !internal::NumericalTruth::independent_unsupported(c).empty()) {
        throw EngineError("analytic: truth = converged: " + why);
      }
      numeric_ = std::make_unique<internal::NumericalTruth>(c);
      handover_s_ = 0.0;
      return;
    }
    const internal::ClosedFormMatch m = internal::match_closed_form(c);
    switch (m.kind) {
      case internal::ClosedFormKind::none:
        throw EngineError("analytic: " + m.reason);
      case internal::ClosedFormKind::body_on_line:
        body_ = std::make_unique<internal::BodyOnLine>(c, m.disk, m.line, m.pair);
        body_->extend_to(c.duration_s);
        break;
      case internal::ClosedFormKind::two_disks_head_on:
        disks_ = std::make_unique<internal::TwoDisksHeadOn>(c, m.disk, m.line, m.pair);
        disks_->extend_to(c.duration_s);
        break;
      case internal::ClosedFormKind::resting_stack:
        stack_ = std::make_unique<internal::RestingStack>(c);
        break;
      case internal::ClosedFormKind::disk_row:
        row_ = std::make_unique<internal::DiskRow>(c);
        break;
      case internal::ClosedFormKind::pendulums_until_contact:
        pendulums_ = std::make_unique<internal::PendulumsUntilContact>(c);
        pendulums_->extend_to(c.duration_s);
        if (const auto& fc = pendulums_->first_contact()) {
          handover_s_ = fc->time_s;
          // the independent truth runs from t = 0 on its own (not handed the
          // closed form's state); the converged reference likewise
          numeric_ = std::make_unique<internal::NumericalTruth>(c);
        }
        break;
    }
  }

  void advance_to(double t_s) override {
    if (!body_ && !disks_ && !stack_ && !row_ && !pendulums_ && !numeric_) {
      throw EngineError("analytic: advance_to before build");
    }
    if (!(t_s >= time_s_) || !std::isfinite(t_s)) {
      throw EngineError(
          fmt::format("analytic: cannot advance from t = {} s to t = {} s", time_s_, t_s));
    }
    // events beyond the case's duration are located when first asked for
    if (body_) body_->extend_to(t_s);
    if (disks_) disks_->extend_to(t_s);
    if (pendulums_) pendulums_->extend_to(t_s);
    if (numeric_ && t_s > handover_s_) numeric_->advance_to(t_s);
    time_s_ = t_s;
  }

  [[nodiscard]] double time() const override { return time_s_; }

  void body_states(std::vector<BodyState>& out) const override {
    if (numeric_now()) {
      numeric_->body_states(out);
      return;
    }
    if (body_) body_->body_states(time_s_, out);
    if (disks_) disks_->body_states(time_s_, out);
    if (stack_) stack_->body_states(time_s_, out);
    if (row_) row_->body_states(time_s_, out);
    if (pendulums_) pendulums_->body_states(time_s_, out);
  }

  void contacts(std::vector<ContactSample>& out) const override {
    out.clear();
    if (numeric_now()) {
      numeric_->contacts(out);
      return;
    }
    // the pendulums' closed form ends at the first contact: no samples
    if (body_) body_->contacts(time_s_, out);
    if (disks_) disks_->contacts(time_s_, out);
    if (stack_) stack_->contacts(time_s_, out);
    if (row_) row_->contacts(time_s_, out);
  }

  [[nodiscard]] std::vector<ContactEpisode> episodes() const override {
    if (body_) return body_->episodes(time_s_);
    if (disks_) return disks_->episodes(time_s_);
    if (stack_) return stack_->episodes(time_s_);
    if (row_) return row_->episodes(time_s_);
    // the numerical part's episodes; before the handover only the first
    // contact's onset is known, from the closed form
    if (numeric_now()) return numeric_->episodes();
    std::vector<ContactEpisode> out;
    if (!pendulums_) return out;
    const auto& fc = pendulums_->first_contact();
    if (!fc || fc->time_s > time_s_) return out;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    ContactEpisode ep;
    ep.body_a = fc->body_a;
    ep.body_b = fc->body_b;
    ep.onset_time_s = fc->time_s;
    ep.offset_time_s = nan;
    ep.approach_speed_mps = fc->approach_speed_mps;
    ep.separation_speed_mps = nan;
    ep.restitution = nan;
    ep.peak_force_n = nan;
    ep.impulse_ns = nan;
    ep.max_penetration_m = nan;
    out.push_back(ep);
    return out;
  }

  [[nodiscard]] long steps() const override {
    if (body_) return body_->phases_begun(time_s_);
    if (disks_) return disks_->phases_begun(time_s_);
    if (stack_) return 1;  // one phase: at rest
    if (row_) return row_->impacts_begun(time_s_);
    long n = 0;
    if (pendulums_) {
      const auto& fc = pendulums_->first_contact();
      n += fc && fc->time_s <= time_s_ ? 2 : 1;
    }
    if (numeric_now()) n += numeric_->steps();
    return n;
  }

  [[nodiscard]] nlohmann::json mapping() const override {
    nlohmann::json j = nlohmann::json{{"closed_form", "none"}};
    if (body_) j = body_->mapping();
    if (disks_) j = disks_->mapping();
    if (stack_) j = stack_->mapping();
    if (row_) j = row_->mapping();
    if (pendulums_) j = pendulums_->mapping();
    if (numeric_) {
      j["numerical_truth"] = numeric_->description();
      j["numerical_from_s"] = handover_s_;
      const std::string what =
          numeric_->independent()
              ? std::string(
                    "the independent truth (core/independent, no code shared with the reference "
                    "solver, the shared contact law or the adapters; its agreement with the "
                    "converged reference under numerical_truth)")
              : std::string(
                    "the converged reference at exact geometry (the reference judged against "
                    "itself, at settings tighter than the run it judges)");
      j["numerical_why"] =
          handover_s_ > 0.0
              ? "the closed form holds up to the first contact; through and after it the truth "
                "is " + what + " (SPEC §3)"
              : "the case has no closed form (truth = converged): the truth over the whole run "
                "is " + what + " (SPEC §3)";
    }
    return j;
  }

  [[nodiscard]] Physics physics() const override {
    Physics p;
    p.mode = "closed form";
    p.collision_by = "closed form";
    p.collision = "the exact shapes' gap in closed form";
    p.contact_force_by = "closed form";
    p.contact_force = "the case's law solved in closed form (SPEC §3)";
    p.parameters = "the case's law as stated";
    if (numeric_ && numeric_->independent()) {
      p.mode = handover_s_ > 0.0 ? "closed form, then independent integration"
                                 : "independent integration";
      p.collision +=
          "; after the closed form: the independent truth's exact geometry "
          "(support points, point-to-ellipse by bisection)";
      p.contact_force +=
          "; after it: the case's law written again from the paper's equations, "
          "integrated by Boost.Odeint dopri5 at abs and rel 1e-12 with located "
          "contact events";
    } else if (numeric_) {
      p.mode = handover_s_ > 0.0 ? "closed form, then converged reference" : "converged reference";
      p.collision += "; after the closed form: the reference solver's exact geometry";
      p.contact_force += "; after it: the case's law integrated by the reference solver at "
                         "rtol 1e-12 (the reference judged against itself)";
    }
    return p;
  }

  [[nodiscard]] nlohmann::json extra_attributes() const override {
    nlohmann::json j = nlohmann::json::object();
    if (pendulums_ && !numeric_) {
      // no contact found: the states are the truth as far as searched
      j["valid_until_s"] = pendulums_->searched_until_s();
    }
    return j;
  }

 private:
  // the numerical truth holds now: after the closed form's end, or always
  // when there is none
  [[nodiscard]] bool numeric_now() const {
    return numeric_ && (time_s_ > handover_s_ || handover_s_ == 0.0);
  }

  SettingsBinder binder_;
  double time_s_ = 0.0;      // s
  double handover_s_ = 0.0;  // s, from here on the numerical truth (inf: none)
  std::unique_ptr<internal::BodyOnLine> body_;
  std::unique_ptr<internal::TwoDisksHeadOn> disks_;
  std::unique_ptr<internal::RestingStack> stack_;
  std::unique_ptr<internal::DiskRow> row_;
  std::unique_ptr<internal::PendulumsUntilContact> pendulums_;
  std::unique_ptr<internal::NumericalTruth> numeric_;
};

}  // namespace

std::unique_ptr<Engine> make_analytic_engine() {
  return std::make_unique<AnalyticEngine>();
}

}  // namespace pb
