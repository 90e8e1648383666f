// The numerical part of the truth (SPEC §3), where no closed form holds
// (truth = converged) or after the pendulums' first contact: the independent
// truth (core/independent, sharing no code with the reference solver, the
// shared contact law or the adapters) where it covers the case, else the
// converged reference (converged_reference.hpp), which then judges the
// reference against itself.
//
// With the independent truth, the converged reference is run beside it once,
// at build, and their agreement over the case's duration goes into the
// description (the mapping): the largest position and angle differences on
// the output grid, and each episode's onset, restitution and impulse.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::independent {
class IndependentTruth;
}

namespace pb::internal {

class ConvergedReference;

class NumericalTruth {
 public:
  // "" when the independent truth covers the case, else why not
  [[nodiscard]] static std::string independent_unsupported(const Case& c);

  // throws EngineError when neither can run the case
  explicit NumericalTruth(const Case& c);
  ~NumericalTruth();
  NumericalTruth(const NumericalTruth&) = delete;
  NumericalTruth& operator=(const NumericalTruth&) = delete;

  [[nodiscard]] bool independent() const { return independent_ != nullptr; }
  void advance_to(double t_s);
  void body_states(std::vector<BodyState>& out) const;
  void contacts(std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const;
  [[nodiscard]] long steps() const;
  [[nodiscard]] nlohmann::json description() const;

 private:
  std::unique_ptr<independent::IndependentTruth> independent_;
  std::unique_ptr<ConvergedReference> reference_;
  nlohmann::json agreement_ = nlohmann::json::object();
  std::string independent_not_used_;  // why the converged reference instead
};

}  // namespace pb::internal
