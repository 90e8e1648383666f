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
//   - the friction rows share the pair's solref (2.2.2 has no solreffriction):
//     inside the cone a slip decays as a_t = -b v_t at the law's b = c / m;
//     friction_damping = stiff (opt-in, elliptic cone) rewrites those rows' B
//     in efc_KBIP after mj_makeConstraint to 2 omega, omega = sqrt(K) of the
//     contact's normal row: the slip decays at twice the normal oscillator's
//     rate, so it stops within the contact (disk_oblique_roll: e^(-2 pi)),
//     while a larger B (measured: 1e4/s, MuJoCo's stiffest) drags the normal
//     force through the elliptic cone's coupling (peak 2988 N for 852 N)
//     (stiffen_friction_rows).
#pragma once

#include <mujoco/mujoco.h>

#include <nlohmann/json.hpp>

#include "mujoco_settings.hpp"

namespace pb::internal::mujoco {

// the mapping's description of a pair's friction with coefficient mu under s
[[nodiscard]] nlohmann::json friction_mapping(double mu, const MujocoSettings& s,
                                              MujocoLine line = MujocoLine::v2);

// friction_damping = stiff: every elliptic friction row of the contacts made
// (rows efc_address + 1 .. + dim - 1) gets B = 2 sqrt(K) of the contact's
// normal row (efc_address); a ConstraintHook (mujoco_stepping.hpp)
void stiffen_friction_rows(const mjModel* m, mjData* d);

}  // namespace pb::internal::mujoco
