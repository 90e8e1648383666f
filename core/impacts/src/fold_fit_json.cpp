// A fold's fit as JSON: a shard's task file and a study's description
// (impact_study.hpp). Kept apart from the fitting so that what reads the
// files (apps/impact_tasks.cpp, the fuzz target tests/fuzz/fuzz_impact_work.cpp)
// needs no engine and no optimiser.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "planarbench/impacts/impact_study.hpp"
#include "planarbench/json_integer.hpp"

namespace pb {

// the fit of a fold without its predictions: what a table's description keeps
nlohmann::ordered_json fit_json(const FoldFit& f) {
  nlohmann::ordered_json j;
  j["fold"] = f.fold;
  j["parameters"] = f.fit.parameters;
  j["objective"] = std::isfinite(f.fit.objective) ? nlohmann::ordered_json(f.fit.objective) : nullptr;
  j["evaluations"] = f.fit.evaluations;
  j["stop"] = f.fit.stop;
  j["wall_time_s"] = f.wall_time_s;
  return j;
}

nlohmann::ordered_json fold_fit_json(const FoldFit& f) {
  nlohmann::ordered_json j;
  j["model"] = f.model;
  j.update(fit_json(f));
  j["predicted"] = f.predicted;
  nlohmann::ordered_json outcomes = nlohmann::ordered_json::array();
  for (const ImpactOutcome& o : f.outcomes) {
    outcomes.push_back({o.after.angle_rad, o.after.velocity_mps.x(), o.after.velocity_mps.y(),
                        o.after.angular_velocity_radps, o.read_time_s, o.contact_s, o.episodes,
                        o.steps, o.failure});
  }
  j["outcomes"] = outcomes;
  return j;
}

FoldFit fold_fit_from_json(const nlohmann::json& j) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  FoldFit f;
  f.model = j.at("model").get<std::string>();
  f.fold = json_integer<int>(j.at("fold"), "fold");
  f.fit.parameters = j.at("parameters").get<std::vector<double>>();
  f.fit.objective = j.at("objective").is_null() ? kNaN : j.at("objective").get<double>();
  f.fit.evaluations = json_integer<int>(j.at("evaluations"), "evaluations");
  f.fit.stop = j.at("stop").get<std::string>();
  f.wall_time_s = j.at("wall_time_s").get<double>();
  f.predicted = json_integers<std::size_t>(j.at("predicted"), "predicted");
  const auto& outcomes = j.at("outcomes");
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    const auto& o = outcomes[k];
    ImpactOutcome out;
    out.after.angle_rad = o.at(0).get<double>();
    out.after.velocity_mps = Vec2(o.at(1).get<double>(), o.at(2).get<double>());
    out.after.angular_velocity_radps = o.at(3).get<double>();
    out.read_time_s = o.at(4).get<double>();
    out.contact_s = o.at(5).get<double>();
    out.episodes = json_integer<int>(o.at(6), fmt::format("outcomes[{}][6] (episodes)", k));
    out.steps = json_integer<long>(o.at(7), fmt::format("outcomes[{}][7] (steps)", k));
    out.failure = o.at(8).get<std::string>();
    f.outcomes.push_back(std::move(out));
  }
  if (f.outcomes.size() != f.predicted.size()) {
    throw std::runtime_error(fmt::format("fit of {} fold {}: {} outcomes for {} impacts", f.model,
                                         f.fold, f.outcomes.size(), f.predicted.size()));
  }
  return f;
}

}  // namespace pb
