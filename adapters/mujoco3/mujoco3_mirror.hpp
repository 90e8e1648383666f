// The 2.2.2 mirror of a MuJoCo 3.3.8 run. The per-step contact rule
// (mujoco_solref_rule.hpp) and the observations (mujoco_sampler.hpp) are
// written once, against MuJoCo's C structures (mjModel, mjData: Jacobians
// from mj_jac, M^-1 from mj_solveM, contacts from mjData::contact). For
// engine "mujoco3" they read a MuJoCo 2.2.2 model compiled from the same MJCF
// (the same bodies, joints, inertials, geoms and pairs, so the same qpos
// layout, mass matrix and Jacobians; only options 2.2.2 lacks are left out),
// whose state and contacts are copied, at every step, from what MuJoCo 3.3.8
// computed: the mirror integrates nothing and collides nothing.
#pragma once

#include <mujoco/mujoco.h>

#include <span>

#include "mujoco3_batch.hpp"  // kContactNumbers, kRecordContactNumbers, kWarnings

namespace pb::internal::mujoco3 {

// qpos, qvel into the mirror, then the stages whose results the rule and the
// observations read: mj_kinematics, mj_comPos, mj_crb, mj_factorM (M and its
// factor, for mj_solveM), mj_comVel (cvel, for mj_objectVelocity)
void mirror_state(const mjModel* m, mjData* d, std::span<const double> qpos,
                  std::span<const double> qvel);

// the `n` contacts 3.3.8's mj_collision found, `stride` numbers each
// (kContactNumbers first; a record's carry efc_address next, which is set
// too; their integers checked by read_batch), as the mirror's d->contact;
// throws EngineError beyond its nconmax
void mirror_contacts(const mjModel* m, mjData* d, std::span<const double> contacts,
                     std::size_t n, std::size_t stride);

// 3.3.8's warning counters (numbers[8], then lastinfo[8]) as the mirror's
void mirror_warnings(mjData* d, std::span<const double> numbers_then_lastinfo);

}  // namespace pb::internal::mujoco3
