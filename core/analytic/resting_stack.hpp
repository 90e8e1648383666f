// The closed-form truth of a stack at rest (SPEC §11): N bodies stacked on a
// fixed half-plane along its normal, gravity along the inward normal, each
// interface pressed by the weight above it. Nothing moves: the interface
// below body k carries W_k = g_n sum_{j >= k} m_j exactly (statics of a
// column: each body's weight and the interface above it are balanced by the
// interface below), its penetration is the law's at rest under W_k
// (Kelvin-Voigt W / K, Hertz and Lankarani-Nikravesh (W / K)^(1/n)), and
// each body stays at the height the support's surface, the bodies' extents
// along the normal and those penetrations give. The truth recomputes that
// pose itself and refuses a case that does not start in it (a stack started
// touching sinks first: no closed form).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

class RestingStack {
 public:
  // throws std::invalid_argument with the reason when the case is not a
  // resting stack (why_not says it without throwing)
  explicit RestingStack(const Case& c);
  [[nodiscard]] static std::string why_not(const Case& c);

  void body_states(double t_s, std::vector<BodyState>& out) const;
  void contacts(double t_s, std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes(double now_s) const;
  [[nodiscard]] nlohmann::json mapping() const;

 private:
  struct Interface {
    int body_a = -1;            // the lower body (the support for the first)
    int body_b = -1;            // the upper body
    double load_n = 0.0;        // N, the weight above
    double penetration_m = 0.0; // m, the law's at rest
    Vec2 point_m = Vec2::Zero();  // m, the middle of the interface
  };
  std::vector<BodyState> states_;  // every body, at rest
  std::vector<Interface> interfaces_;
  Vec2 normal_ = Vec2(0.0, 1.0);
};

}  // namespace pb::internal
