// The closed-form truth: engine "analytic" (SPEC §3). It evaluates, at any
// time asked, the exact solution of the cases that have one: the disk on a
// line (falling_ball, sliding) and pendulums up to their first contact
// (dual_pendulum). There is no time step: advance_to lands on t exactly, and
// steps() counts the phases of the piecewise closed form begun so far.
#include "planarbench/analytic/analytic_engine.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>

#include "closed_form_match.hpp"
#include "disk_on_line.hpp"
#include "pendulums_until_contact.hpp"
#include "planarbench/build_info.hpp"
#include "planarbench/errors.hpp"

namespace pb {

namespace {

class AnalyticEngine final : public Engine {
 public:
  // nothing to set: a closed form has no tolerance or step
  AnalyticEngine() : binder_("analytic") {}

  [[nodiscard]] std::string name() const override { return "analytic"; }
  [[nodiscard]] std::string version() const override {
    return fmt::format("closed form (planarbench {})", build_info::kVersion);
  }

  [[nodiscard]] Capability supports(const Case& c) const override {
    const internal::ClosedFormMatch m = internal::match_closed_form(c);
    if (m.kind == internal::ClosedFormKind::none) return {Support::unsupported, m.reason};
    return {Support::native, {}};
  }

  [[nodiscard]] const SettingsBinder& settings() const override { return binder_; }

  void build(const Case& c, const SettingsOverrides& overrides) override {
    binder_.apply(overrides);
    disk_.reset();
    pendulums_.reset();
    time_s_ = 0.0;
    const internal::ClosedFormMatch m = internal::match_closed_form(c);
    switch (m.kind) {
      case internal::ClosedFormKind::none:
        throw EngineError("analytic: " + m.reason);
      case internal::ClosedFormKind::disk_on_line:
        disk_ = std::make_unique<internal::DiskOnLine>(c, m.disk, m.line, m.pair);
        disk_->extend_to(c.duration_s);
        break;
      case internal::ClosedFormKind::pendulums_until_contact:
        pendulums_ = std::make_unique<internal::PendulumsUntilContact>(c);
        pendulums_->extend_to(c.duration_s);
        break;
    }
  }

  void advance_to(double t_s) override {
    if (!disk_ && !pendulums_) throw EngineError("analytic: advance_to before build");
    if (!(t_s >= time_s_) || !std::isfinite(t_s)) {
      throw EngineError(
          fmt::format("analytic: cannot advance from t = {} s to t = {} s", time_s_, t_s));
    }
    // events beyond the case's duration are located when first asked for
    if (disk_) disk_->extend_to(t_s);
    if (pendulums_) pendulums_->extend_to(t_s);
    time_s_ = t_s;
  }

  [[nodiscard]] double time() const override { return time_s_; }

  void body_states(std::vector<BodyState>& out) const override {
    if (disk_) disk_->body_states(time_s_, out);
    if (pendulums_) pendulums_->body_states(time_s_, out);
  }

  void contacts(std::vector<ContactSample>& out) const override {
    out.clear();
    // the pendulums' closed form ends at the first contact: no samples
    if (disk_) disk_->contacts(time_s_, out);
  }

  [[nodiscard]] std::vector<ContactEpisode> episodes() const override {
    if (disk_) return disk_->episodes(time_s_);
    std::vector<ContactEpisode> out;
    if (!pendulums_) return out;
    const auto& fc = pendulums_->first_contact();
    if (!fc || fc->time_s > time_s_) return out;
    // only the onset of the first contact is known in closed form
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
    if (disk_) return disk_->phases_begun(time_s_);
    if (pendulums_) {
      const auto& fc = pendulums_->first_contact();
      return fc && fc->time_s <= time_s_ ? 2 : 1;
    }
    return 0;
  }

  [[nodiscard]] nlohmann::json mapping() const override {
    if (disk_) return disk_->mapping();
    if (pendulums_) return pendulums_->mapping();
    return nlohmann::json{{"closed_form", "none"}};
  }

  [[nodiscard]] nlohmann::json extra_attributes() const override {
    nlohmann::json j = nlohmann::json::object();
    if (pendulums_) {
      // the states are the truth up to the first contact only
      const auto& fc = pendulums_->first_contact();
      j["valid_until_s"] = fc ? fc->time_s : pendulums_->searched_until_s();
    }
    return j;
  }

 private:
  SettingsBinder binder_;
  double time_s_ = 0.0;  // s
  std::unique_ptr<internal::DiskOnLine> disk_;
  std::unique_ptr<internal::PendulumsUntilContact> pendulums_;
};

}  // namespace

std::unique_ptr<Engine> make_analytic_engine() {
  return std::make_unique<AnalyticEngine>();
}

}  // namespace pb
