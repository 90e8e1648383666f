// The numerical part of the truth where no closed form and no independent
// integrator (core/independent) holds (SPEC §3): the reference solver at
// exact geometry (geometry = exact: true circles, ellipses, polygons and
// lines) and a tolerance two decades tighter than the reference's default
// (rk45, rtol 1e-12, atol 1e-14, against the default 1e-10): the reference
// is then judged against itself, at settings tighter than the run it judges,
// and the report says so. Shown converged by a Richardson estimate: the same
// run at rtol 1e-10 and 1e-11 gives d1 = |y(1e-11) - y(1e-10)| and
// d2 = |y(1e-12) - y(1e-11)| of every body's position at the end; with the
// observed ratio q = d1 / d2 the error left at rtol 1e-12 is about
// d2 / (q - 1) (geometric convergence; e.g. Hairer, Norsett & Wanner,
// Solving ODEs I, §II.4).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb {
class ReferenceSolver;
}

namespace pb::internal {

class ConvergedReference {
 public:
  // throws EngineError when the case has no exact geometry for a pair
  explicit ConvergedReference(const Case& c);
  ~ConvergedReference();
  ConvergedReference(const ConvergedReference&) = delete;
  ConvergedReference& operator=(const ConvergedReference&) = delete;

  void advance_to(double t_s);
  [[nodiscard]] double time() const;
  void body_states(std::vector<BodyState>& out) const;
  void contacts(std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const;
  [[nodiscard]] long steps() const;
  // the settings, and the Richardson estimate over the case's duration
  [[nodiscard]] nlohmann::json description() const;

 private:
  Case case_;
  std::unique_ptr<ReferenceSolver> solver_;
  nlohmann::json convergence_ = nlohmann::json::object();
};

}  // namespace pb::internal
