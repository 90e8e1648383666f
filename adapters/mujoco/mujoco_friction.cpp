#include "mujoco_friction.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

namespace pb::internal::mujoco {

nlohmann::json friction_mapping(double mu, const MujocoSettings& s, MujocoLine line) {
  const bool v3 = line == MujocoLine::v3;
  const bool own_solref = v3 && (s.solreffriction[0] != 0.0 || s.solreffriction[1] != 0.0);
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
  if (v3 && !own_solref) {
    lost.push_back(
        "the friction rows share the pair's solref (MuJoCo 3's default, solreffriction "
        "[0, 0]): inside the cone a slip decays as a_t = -b v_t at the law's b = c / m, so a "
        "short contact stops only part of it (mujoco3.solreffriction sets the rows' own)");
  } else if (!v3 && s.friction_damping == "shared") {
    lost.push_back(
        "the friction rows share the pair's solref (MuJoCo 2.2.2 has no friction solref): "
        "inside the cone a slip decays as a_t = -b v_t at the law's b = c / m, so a short "
        "contact stops only part of it (mujoco.friction_damping = stiff, with the elliptic "
        "cone, is the opt-in remedy)");
  }
  const std::string rows =
      own_solref
          ? fmt::format("the friction rows with their own solref [{}, {}] "
                        "(mujoco3.solreffriction, <pair solreffriction>) and the pair's solimp",
                        s.solreffriction[0], s.solreffriction[1])
      : !v3 && s.friction_damping == "stiff"
          ? std::string("the friction rows' damping B rewritten after mj_makeConstraint to "
                        "2 omega, omega = sqrt(K) of the contact's normal row "
                        "(mujoco.friction_damping = stiff): a slip inside the cone decays at "
                        "twice the normal oscillator's rate, stopping within the contact, while "
                        "the cone's coupling leaves the normal law as it was")
          : std::string("the friction rows sharing the pair's solref and solimp");
  return {{"coefficient", mu},
          {"expressed_as",
           fmt::format("exactly as the coefficient: the pair's <pair condim=\"3\" friction=\"{0} "
                       "{0} ...\"> (both tangents, no mixing for explicit pairs), {1}",
                       mu, rows)},
          {"model",
           fmt::format("MuJoCo's soft frictional contact, cone = {}, impratio = {}, "
                       "noslip_iterations = {}",
                       s.cone, s.impratio, s.noslip_iterations)},
          {"not_expressed", lost}};
}

void stiffen_friction_rows(const mjModel* /*m*/, mjData* d) {
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if (c.exclude != 0 || c.efc_address < 0 || c.dim < 3) continue;
    // the elliptic cone's friction rows have no spring (K = 0): their B alone
    // sets how fast a slip inside the cone decays (mj_referenceConstraint:
    // aref = -B v)
    // the normal row's K (1/s^2) is its oscillator's omega^2: the friction
    // rows critically damped at that frequency, B = 2 omega
    const mjtNum b = 2.0 * std::sqrt(std::max<mjtNum>(0.0, d->efc_KBIP[4 * c.efc_address]));
    for (int r = 1; r < c.dim; ++r) {
      const int row = c.efc_address + r;
      if (d->efc_type[row] == mjCNSTR_CONTACT_ELLIPTIC) d->efc_KBIP[4 * row + 1] = b;
    }
  }
}

}  // namespace pb::internal::mujoco
