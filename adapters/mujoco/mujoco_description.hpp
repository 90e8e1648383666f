// The words of a MuJoCo run's mapping (SPEC §5 `mapping`) that both MuJoCo
// engines write alike ("mujoco", 2.2.2; "mujoco3", 3.3.8): how each body
// became MuJoCo geoms and joints, what native mode makes of a pair's law,
// what MuJoCo's soft contact does not express, and each pair's collider.
#pragma once

#include <nlohmann/json.hpp>

#include "mujoco_mjcf.hpp"
#include "mujoco_plan.hpp"
#include "mujoco_settings.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

// native mode: what a pair's law becomes, before the run (the rule, no
// numbers from the future)
[[nodiscard]] nlohmann::json native_pair_json(const ContactLaw& law);

// what MuJoCo's soft contact at impedance d (solimp's dmax) does not express
void add_soft_contact_notes(double d, nlohmann::json& lost);

// each case body: shape, MuJoCo geom(s), joints, inertial
[[nodiscard]] nlohmann::json describe_bodies(const Case& c, const MujocoPlan& plan);

// each contact group: its members, collision bit, condim, friction, the
// margins its geom types get, solimp, and what native mode makes of its law
// (`solimp`: the groups' geoms')
[[nodiscard]] nlohmann::json describe_groups(const Case& c, const MujocoPlan& plan,
                                             const std::vector<double>& solimp,
                                             nlohmann::json& lost,
                                             MujocoLine line = MujocoLine::v2);

// pair k's names, collider, condim, margin and gap (`p`), solimp unless
// `inject`; an MPR pair's depth caveat goes to `lost` (2.2.2's libccd MPR;
// 3.3.8's native convex collider)
void describe_pair(const Case& c, const MujocoPlan& plan, std::size_t k, const PairParams& p,
                   bool inject, nlohmann::json& j, nlohmann::json& lost,
                   MujocoLine line = MujocoLine::v2);

}  // namespace pb::internal::mujoco
