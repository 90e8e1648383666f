// How a case pair's Coulomb friction (SPEC §7) is set in MuJoCo 2.2.2, and
// what of it MuJoCo's soft frictional contact cannot express, stated before
// the run. Facts from MuJoCo 2.2.2's sources (engine_core_constraint.c
// mj_instantiateContact, mj_makeImpedance, mj_diagApprox; engine_solver.c
// mj_solNoSlip; engine_util_spatial.c mju_makeFrame), checked by measurement:
//   - the pair has condim 3 and friction (mu, mu, ...): MuJoCo's first
//     tangent is world y, where no case body moves, its second the plane's;
//   - pyramidal cone (the default): four rows J_n +- mu J_t1, J_n +- mu J_t2,
//     each with the pair's solref on the contact distance; the two t1 rows
//     are pure normal rows, so the pyramid splits the normal load between
//     pure-normal and frictional rows and all rows stay active only while
//     |F_t| <= mu F_n / 2; the normal force follows the direct solref as with
//     condim 1 (its regulariser changes by O(1 - d));
//   - elliptic cone: rows n, t1, t2; the tangent rows' reference acceleration
//     is -b v_t (no spring), their regulariser the normal's / impratio;
//   - both are soft: a load f_t inside the cone is held by a tangential speed
//     v = R_t f_t / b (b the solref damping per unit mass, R_t the friction
//     rows' regulariser ~ (1 - d)/d x the inverse effective mass / impratio):
//     MuJoCo creeps, at a speed proportional to 1 - d and 1 / impratio;
//   - noslip_iterations runs a projected Gauss-Seidel pass on the friction
//     rows without their regulariser; in the plane it is a no-op with the
//     elliptic cone (the y tangent's zero row makes its 2x2 QCQP singular)
//     and, with the pyramidal cone, only removes creep while |F_t| <= mu F_n / 2.
#pragma once

#include <nlohmann/json.hpp>

#include "mujoco_settings.hpp"

namespace pb::internal::mujoco {

// the mapping's description of a pair's friction with coefficient mu under s
[[nodiscard]] nlohmann::json friction_mapping(double mu, const MujocoSettings& s);

}  // namespace pb::internal::mujoco
