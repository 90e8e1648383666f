#include "impact_models.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

#include "planarbench/did_you_mean.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/impacts/impact_residual.hpp"

namespace pb::cli {

const std::vector<std::string>& impact_engine_names() {
  static const std::vector<std::string> names = {"reference", "reference_exact", "reference_ln",
                                                 "reference_hc", "mujoco", "box2d", "ode"};
  return names;
}

namespace {

EngineModelSpec spec_of(const std::string& name) {
  EngineModelSpec s;
  s.name = name;
  s.engine = name.rfind("reference", 0) == 0 ? "reference" : name;
  const std::string engine = s.engine;
  s.factory = [engine] { return make_engine(engine); };
  // every reference_* model runs the reference at exact geometry
  if (s.engine == "reference" && name != "reference") {
    s.settings = {{"reference.geometry", "\"exact\""}};
  }
  if (name == "reference") {
    s.representation = "the paper's outline contact: 180 outline points of the ellipse";
  } else if (name == "reference_exact") {
    s.representation = "the reference at exact geometry: the true ellipse against the line";
  } else if (name == "reference_ln") {
    s.law = ImpactLawKind::lankarani_nikravesh;
    s.representation =
        "the reference at exact geometry with the paper's Lankarani-Nikravesh law (eq. 7: a Hertz "
        "exponent and the law's restitution fitted, not Kelvin-Voigt's)";
  } else if (name == "reference_hc") {
    s.law = ImpactLawKind::hunt_crossley;
    s.representation =
        "the reference at exact geometry with Hunt and Crossley's own law K delta^n (1 + alpha "
        "delta'): its restitution falls with the approach speed (alpha, n fitted)";
  } else if (name == "mujoco") {
    s.representation = "MuJoCo's ellipsoid geom against a plane (its soft contact, condim 3)";
  } else if (name == "box2d") {
    // Box2D is tuned for moving objects of 0.1 to 10 m (its manual's "Units";
    // its skin b2_polygonRadius is 10 mm, its weld 2.5 mm): the 70 x 50 mm
    // ellipse is run in a world of decimetres, as Box2D's users scale theirs,
    // so its 180 outline points survive the skin and the welding (in metres
    // at most 24 did: at 32 the skinned core's vertices came 2.2 mm apart).
    // Measured on the training file (5-fold CV median eps): 24 points in
    // metres 0.0712, 24 in decimetres 0.0827, 60 0.0745, 180 0.0689.
    // Its rigid contact makes K no parameter.
    s.outline_points = 180;
    s.length_scale = 10.0;
    s.fit_stiffness = false;
    s.representation =
        "Box2D polygon fan of 180 outline points in a world of decimetres (Box2D's size range; "
        "rigid contact: K is not fitted)";
  } else if (name == "ode") {
    s.representation = "ODE convex prism of 180 outline points against a plane";
  }
  return s;
}

}  // namespace

std::vector<std::unique_ptr<ImpactModel>> impact_models(const std::string& engines, bool stored) {
  std::vector<std::string> chosen;
  if (engines.empty()) {
    // "" is no engine list: none must be said (issue 35 item 11)
    throw InputError("--engine", 0, "",
                     fmt::format("is empty: one of {}, all, none (the baselines only), or a "
                                 "comma-separated list",
                                 fmt::join(impact_engine_names(), ", ")));
  }
  if (engines == "all") {
    chosen = impact_engine_names();
  } else if (engines != "none") {
    std::stringstream in(engines);
    for (std::string name; std::getline(in, name, ',');) {
      const auto& known = impact_engine_names();
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        throw InputError("--engine", 0, name,
                         fmt::format("is no engine of `impacts`: one of {}, all, none (the "
                                     "baselines only), or a comma-separated list{}",
                                     fmt::join(known, ", "), did_you_mean(name, known)));
      }
      if (std::find(chosen.begin(), chosen.end(), name) == chosen.end()) chosen.push_back(name);
    }
  }
  std::vector<std::unique_ptr<ImpactModel>> models;
  for (const std::string& name : chosen) models.push_back(engine_impact_model(spec_of(name)));
  models.push_back(rigid_impact_model());
  models.push_back(rigid_compliant_model());
  models.push_back(naive_bounce_model());
  models.push_back(learned_residual_model());
  if (stored) {
    for (std::size_t k = 0; k < kStoredModelNames.size(); ++k) models.push_back(stored_impact_model(k));
  }
  return models;
}

}  // namespace pb::cli
