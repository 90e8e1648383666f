// The independent truth (issue 25): a second implementation of the cases'
// physics that shares no code with the reference solver (core/reference), the
// shared contact law (core/src/contact_force.cpp), the shared ellipse distance
// (core/src/ellipse_distance.cpp), the other closed forms of core/analytic or
// the adapters; only pb_core's plain data types (Case, Body, ContactPair,
// BodyState, ContactSample, ContactEpisode) and its errors. The analytic
// engine uses it where a case has no closed form (truth = converged) and for
// the pendulums after their first contact, in place of the converged
// reference, so that an error in the reference or in the shared law shows up
// against the truth instead of cancelling out.
//
// What it covers (anything else: unsupported() says why):
//   - bodies free or pinned to the world by one revolute joint each;
//   - pairs: a fixed half-plane against a circle, an ellipse or a polygon (one
//     vertex in contact at a time: a second vertex reaching the line during a
//     contact ends the run with an error), a circle against an ellipse;
//   - frictionless pairs with Kelvin-Voigt, Hertz or Lankarani-Nikravesh laws;
//   - no pair overlapping at t = 0.
// How: independent/hybrid_integration.hpp (Boost.Odeint dopri5 at abs and
// rel 1e-12, located contact events, episodes kept on its own).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::independent {

class HybridIntegration;

class IndependentTruth {
 public:
  // "" when the case is covered, else why not (one line)
  [[nodiscard]] static std::string unsupported(const Case& c);

  // throws EngineError when the case is not covered
  explicit IndependentTruth(const Case& c);
  ~IndependentTruth();
  IndependentTruth(const IndependentTruth&) = delete;
  IndependentTruth& operator=(const IndependentTruth&) = delete;

  void advance_to(double t_s);
  [[nodiscard]] double time() const;
  void body_states(std::vector<BodyState>& out) const;
  void contacts(std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const;
  [[nodiscard]] long steps() const;
  // kinetic plus gravity's potential energy now, J
  [[nodiscard]] double energy() const;
  // what it is, its tolerances and its laws, for the mapping
  [[nodiscard]] nlohmann::json description() const;

 private:
  std::unique_ptr<HybridIntegration> run_;
};

}  // namespace pb::independent
