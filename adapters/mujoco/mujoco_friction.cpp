#include "mujoco_friction.hpp"

#include <fmt/format.h>

namespace pb::internal::mujoco {

nlohmann::json friction_mapping(double mu, const MujocoSettings& s) {
  nlohmann::json lost = nlohmann::json::array();
  lost.push_back(fmt::format(
      "soft friction: a tangential load inside the cone is held by a creep speed "
      "v = R_t f_t / b, proportional to 1 - d (solimp d = {}) and to 1 / impratio ({}); "
      "raising impratio lowers it in proportion",
      s.solimp[1], s.impratio));
  if (s.cone == "pyramidal") {
    lost.push_back(
        "pyramidal cone: MuJoCo's first tangent is world y (no degree of freedom), so two of "
        "the four pyramid rows push along the normal only and carry half of it; beyond "
        "|F_t| = mu F_n / 2 the creep grows faster, as F_n (3 |F_t| / F_n - mu)");
    if (s.noslip_iterations > 0) {
      lost.push_back(fmt::format(
          "noslip_iterations = {}: removes the creep only while |F_t| <= mu F_n / 2",
          s.noslip_iterations));
    }
  } else if (s.noslip_iterations > 0) {
    lost.push_back(fmt::format(
        "noslip_iterations = {} has no effect in the plane with the elliptic cone: the y "
        "tangent's zero Jacobian row makes the noslip pass's 2x2 cone projection singular "
        "(mju_QCQP2) and every update is reverted",
        s.noslip_iterations));
  }
  return {{"coefficient", mu},
          {"expressed_as",
           fmt::format("exactly as the coefficient: the pair's <pair condim=\"3\" friction=\"{0} "
                       "{0} ...\"> (both tangents, no mixing for explicit pairs), the "
                       "friction rows sharing the pair's solref and solimp",
                       mu)},
          {"model",
           fmt::format("MuJoCo's soft frictional contact, cone = {}, impratio = {}, "
                       "noslip_iterations = {}",
                       s.cone, s.impratio, s.noslip_iterations)},
          {"not_expressed", lost}};
}

}  // namespace pb::internal::mujoco
