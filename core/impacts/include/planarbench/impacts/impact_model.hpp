// What predicts an impact (SPEC §8): an engine running the impact as a case,
// one of the project's rigid baselines, or one of the dataset's stored
// predictions. Each names its free parameters (what the fit may change,
// with bounds) and makes predictors, one per worker thread.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "planarbench/engine.hpp"
#include "planarbench/impacts/impact_case.hpp"
#include "planarbench/impacts/impact_data.hpp"
#include "planarbench/impacts/impact_object.hpp"
#include "planarbench/impacts/impact_simulation.hpp"

namespace pb {

struct FitOptions;  // impact_fit.hpp

// The impacts of a file, prepared once: states in the project's convention.
struct ImpactTable {
  ImpactObject object;
  AngleConvention convention;
  std::vector<ImpactState> before;      // at the touch, measured
  std::vector<ImpactState> after;       // after the impact, measured
  std::vector<std::array<double, 18>> stored;  // the file's v_models (stored convention)
  std::vector<double> drop;             // the impact's row in the original file
  [[nodiscard]] std::size_t size() const { return before.size(); }
};
// InputError naming the file and the row of an impact whose lowest point does
// not approach the ground (impact_case.hpp: no arc leads to it).
[[nodiscard]] ImpactTable make_impact_table(const ImpactSet& set, const ImpactObject& o,
                                            AngleConvention c);

// One free parameter of a model. The optimiser works on the unit interval
// mapped onto [lower, upper] (logarithmically when log_scale).
struct ImpactParameter {
  std::string name;      // e.g. "stiffness_n_per_m"
  std::string unit;      // e.g. "N/m", "-"
  double lower = 0.0;
  double upper = 1.0;
  double start = 0.5;    // where the fit starts
  bool log_scale = false;
  std::string doc;       // one line: what it sets in the engine's own model
};

class ImpactPredictor {
 public:
  virtual ~ImpactPredictor() = default;
  // the prediction of impact i of `table` with the model's parameters
  [[nodiscard]] virtual ImpactOutcome predict(const ImpactTable& table, std::size_t i,
                                              const std::vector<double>& parameters) = 0;
};

class ImpactModel {
 public:
  virtual ~ImpactModel() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  // "engine", "baseline" or "stored"
  [[nodiscard]] virtual std::string kind() const = 0;
  // one line: the model, its representation of the ellipse, how its parameters act
  [[nodiscard]] virtual std::string description() const = 0;
  [[nodiscard]] virtual std::vector<ImpactParameter> parameters() const = 0;
  [[nodiscard]] virtual std::unique_ptr<ImpactPredictor> predictor() const = 0;
  // the engine's version ("" for the project's own models)
  [[nodiscard]] virtual std::string version() const { return ""; }
  // the fewest objective evaluations its fit deserves (0: the command's
  // --max-evaluations); a closed form costs microseconds an evaluation
  [[nodiscard]] virtual int evaluations_hint() const { return 0; }
  // A model that learns from data (kind "learned"): the model trained on the
  // impacts `training` of `table` only (a fold's training set), whose
  // predictions are then made; nullptr for every other model. Its own fits
  // minimise `options.objective` on `options.jobs` threads.
  [[nodiscard]] virtual std::unique_ptr<ImpactModel> trained(
      const ImpactTable& /*table*/, const std::vector<std::size_t>& /*training*/,
      const FitOptions& /*options*/) const {
    return nullptr;
  }
};

using EngineFactory = std::function<std::unique_ptr<Engine>()>;

// An engine running each impact as a case with the Kelvin-Voigt law and
// Coulomb friction of impact_case.hpp. `settings` are passed to every build
// (e.g. reference.geometry=exact); `outline_points` sets the ellipse's
// outline; `fit_stiffness` = false keeps K at its start (an engine whose
// contact is rigid: K changes nothing it computes).
struct EngineModelSpec {
  std::string name;          // e.g. "reference_exact"
  std::string engine;        // the engine's registry name
  EngineFactory factory;
  std::vector<std::pair<std::string, std::string>> settings;
  int outline_points = 180;
  // the impact run in a world of length unit 1/length_scale m
  // (scaled_impact_case), its velocities read back in m/s
  double length_scale = 1.0;
  bool fit_stiffness = true;
  // the law fitted: Kelvin-Voigt (K, zeta, mu); Lankarani-Nikravesh (K in
  // N/m^n, n, e, mu) and Hunt-Crossley (K, n, alpha in s/m, mu) for an engine
  // that takes the law as the case states it (the reference)
  ImpactLawKind law = ImpactLawKind::kelvin_voigt;
  std::string representation;  // one line: how the engine represents the ellipse
};
[[nodiscard]] std::unique_ptr<ImpactModel> engine_impact_model(EngineModelSpec spec);

// The project's baselines (rigid_impact.hpp): "rigid" (e, mu) and "naive_bounce" (e).
[[nodiscard]] std::unique_ptr<ImpactModel> rigid_impact_model();
// "rigid_compliant" (rigid_impact.hpp): e0, de/dx', e_t, mu, k's scale
[[nodiscard]] std::unique_ptr<ImpactModel> rigid_compliant_model();
[[nodiscard]] std::unique_ptr<ImpactModel> naive_bounce_model();
// The dataset's stored prediction number `k` (kStoredModelNames), as given.
[[nodiscard]] std::unique_ptr<ImpactModel> stored_impact_model(std::size_t k);

}  // namespace pb
