#include "planarbench/independent/independent_truth.hpp"

#include <fmt/format.h>

#include "hybrid_integration.hpp"
#include "pair_contact.hpp"
#include "planarbench/errors.hpp"
#include "rigid_bodies.hpp"

namespace pb::independent {

std::string IndependentTruth::unsupported(const Case& c) {
  if (const ContactPair* f = c.first_pair_with_friction()) {
    return fmt::format(
        "contact pair '{}' has friction {}: the independent truth is frictionless (the paper's "
        "law has no tangential force)",
        f->name, f->friction);
  }
  if (auto why = RigidBodies::unsupported(c); !why.empty()) return why;
  for (const ContactPair& p : c.contacts) {
    if (p.body_a < 0 || p.body_b < 0 || static_cast<std::size_t>(p.body_a) >= c.bodies.size() ||
        static_cast<std::size_t>(p.body_b) >= c.bodies.size() || p.body_a == p.body_b) {
      return fmt::format("contact pair '{}' names a body that does not exist", p.name);
    }
    const Body& a = c.bodies[static_cast<std::size_t>(p.body_a)];
    const Body& b = c.bodies[static_cast<std::size_t>(p.body_b)];
    if (auto why = pair_contact_unsupported(a, b); !why.empty()) {
      return fmt::format("contact pair '{}': {}", p.name, why);
    }
  }
  // every pair apart at the start (an episode begins at a located onset)
  const RigidBodies model(c, 0);
  std::vector<BodyMotion> m;
  model.motions(model.initial_state(), m);
  for (const ContactPair& p : c.contacts) {
    const auto a = static_cast<std::size_t>(p.body_a);
    const auto b = static_cast<std::size_t>(p.body_b);
    try {
      const PairContact pc = pair_contact(c.bodies[a].shape, m[a], c.bodies[b].shape, m[b]);
      if (pc.depth_m > 0.0) {
        return fmt::format("contact pair '{}' overlaps at t = 0 (by {:g} m)", p.name, pc.depth_m);
      }
    } catch (const EngineError& e) {
      return fmt::format("contact pair '{}' at t = 0: {}", p.name, e.what());
    }
  }
  return {};
}

IndependentTruth::IndependentTruth(const Case& c) {
  if (auto why = unsupported(c); !why.empty()) {
    throw EngineError(fmt::format("independent truth of case '{}': {}", c.name, why));
  }
  run_ = std::make_unique<HybridIntegration>(c, IntegrationSettings{});
}

IndependentTruth::~IndependentTruth() = default;

void IndependentTruth::advance_to(double t_s) {
  run_->advance_to(t_s);
}
double IndependentTruth::time() const {
  return run_->time();
}
void IndependentTruth::body_states(std::vector<BodyState>& out) const {
  run_->body_states(out);
}
void IndependentTruth::contacts(std::vector<ContactSample>& out) const {
  run_->contacts(out);
}
std::vector<ContactEpisode> IndependentTruth::episodes() const {
  return run_->episodes();
}
long IndependentTruth::steps() const {
  return run_->steps();
}
double IndependentTruth::energy() const {
  return run_->energy();
}

nlohmann::json IndependentTruth::description() const {
  const IntegrationSettings& s = run_->settings();
  return {
      {"solver",
       fmt::format("independent truth (core/independent): shares no code with the reference "
                   "solver, the shared contact law or the adapters; Boost.Odeint Dormand-Prince "
                   "5(4) with dense output at abs {:g}, rel {:g}, steps <= {:g} s; contact "
                   "onset, offset and the force's clamp located by bisection on the dense output "
                   "(no force discontinuity inside a step)",
                   s.abs_tol, s.rel_tol, s.max_step_s)},
      {"geometry",
       "exact, in closed form: support points of circle, ellipse and polygon against a line; a "
       "disk against an ellipse by Eberly's bisection for the nearest point"},
      {"laws", run_->laws()},
      {"motion", "free bodies in (x, y, theta); bodies pinned to the world in their angle alone"},
      {"agreement_with_converged_reference",
       "measured by tests/independent/independent_agreement_test.cpp (positions, each "
       "episode's restitution and impulse)"}};
}

}  // namespace pb::independent
