#include "numerical_truth.hpp"

#include <algorithm>
#include <cmath>

#include "converged_reference.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/independent/independent_truth.hpp"

namespace pb::internal {

namespace {

// the independent truth and the converged reference over the whole case, on
// the output grid: how far they agree
nlohmann::json agreement(const Case& c) {
  independent::IndependentTruth ind(c);
  ConvergedReference ref(c);
  std::vector<BodyState> si;
  std::vector<BodyState> sr;
  double position = 0.0;  // m
  double angle = 0.0;     // rad
  for (int k = 0; k < c.output_samples(); ++k) {
    const double t = c.output_time(k);
    ind.advance_to(t);
    ref.advance_to(t);
    ind.body_states(si);
    ref.body_states(sr);
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
      if (c.bodies[i].fixed) continue;
      position = std::max(position, (si[i].position_m - sr[i].position_m).norm());
      angle = std::max(angle, std::abs(si[i].angle_rad - sr[i].angle_rad));
    }
  }
  const auto ei = ind.episodes();
  const auto er = ref.episodes();
  nlohmann::json episodes = nlohmann::json::array();
  for (std::size_t k = 0; k < std::min(ei.size(), er.size()); ++k) {
    episodes.push_back({{"onset_s", std::abs(ei[k].onset_time_s - er[k].onset_time_s)},
                        {"restitution", std::abs(ei[k].restitution - er[k].restitution)},
                        {"impulse_relative", std::abs(er[k].impulse_ns / ei[k].impulse_ns - 1.0)}});
  }
  return {{"what",
           "independent truth minus the converged reference over the case's duration: largest "
           "position and angle difference of any moving body on the output grid; per episode "
           "(paired by index) the onset's, the restitution's absolute and the impulse's "
           "relative difference"},
          {"position_max_m", position},
          {"angle_max_rad", angle},
          {"episodes_independent", ei.size()},
          {"episodes_reference", er.size()},
          {"episodes", episodes},
          {"reference", ref.description()}};
}

// the independent truth through the whole case: "" when it runs, else why
// not (a state it does not cover, e.g. a polygon's second vertex reaching
// the line, shows only on the way)
std::string independent_fails(const Case& c) {
  try {
    independent::IndependentTruth t(c);
    t.advance_to(c.duration_s);
    return {};
  } catch (const EngineError& e) {
    return e.what();
  }
}

}  // namespace

std::string NumericalTruth::independent_unsupported(const Case& c) {
  return independent::IndependentTruth::unsupported(c);
}

NumericalTruth::NumericalTruth(const Case& c) {
  std::string why_not = independent_unsupported(c);
  if (why_not.empty()) why_not = independent_fails(c);
  if (why_not.empty()) {
    independent_ = std::make_unique<independent::IndependentTruth>(c);
    try {
      agreement_ = agreement(c);
    } catch (const EngineError& e) {
      // the truth stands on its own; only the comparison is missing
      agreement_ = {{"what", "not measured: the converged reference cannot run the case"},
                    {"why", e.what()}};
    }
  } else {
    reference_ = std::make_unique<ConvergedReference>(c);
    independent_not_used_ = why_not;
  }
}

NumericalTruth::~NumericalTruth() = default;

void NumericalTruth::advance_to(double t_s) {
  if (independent_) {
    independent_->advance_to(t_s);
  } else {
    reference_->advance_to(t_s);
  }
}

void NumericalTruth::body_states(std::vector<BodyState>& out) const {
  if (independent_) {
    independent_->body_states(out);
  } else {
    reference_->body_states(out);
  }
}

void NumericalTruth::contacts(std::vector<ContactSample>& out) const {
  if (independent_) {
    independent_->contacts(out);
  } else {
    reference_->contacts(out);
  }
}

std::vector<ContactEpisode> NumericalTruth::episodes() const {
  return independent_ ? independent_->episodes() : reference_->episodes();
}

long NumericalTruth::steps() const {
  return independent_ ? independent_->steps() : reference_->steps();
}

nlohmann::json NumericalTruth::description() const {
  if (!independent_) {
    nlohmann::json j = reference_->description();
    j["independent_truth_not_used"] = independent_not_used_;
    j["judged_against_itself"] =
        "the reference solver is the truth here, at settings tighter than its default run "
        "(exact geometry, rtol 1e-12 against 1e-10): its own error measures its convergence, "
        "not its correctness";
    return j;
  }
  nlohmann::json j = independent_->description();
  j["agreement_with_converged_reference"] = agreement_;
  return j;
}

}  // namespace pb::internal
