// The models `planarbench impacts` fits and scores (SPEC §8): each engine
// running the impacts as cases (the registry's engines, each with its own
// representation of the ellipse), the project's rigid baselines and the
// dataset's stored predictions.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "planarbench/impacts/impact_model.hpp"

namespace pb::cli {

// "reference", "reference_exact", "mujoco", "box2d", "ode"
[[nodiscard]] const std::vector<std::string>& impact_engine_names();

// NAME|all|none|comma-separated list of impact_engine_names() -> the engine
// models, then the baselines (rigid, naive_bounce) and, when `stored` is
// set, the dataset's six stored predictions. InputError naming --engine.
[[nodiscard]] std::vector<std::unique_ptr<ImpactModel>> impact_models(const std::string& engines,
                                                                      bool stored);

}  // namespace pb::cli
