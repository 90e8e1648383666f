// How many contacts and constraint rows MuJoCo 2.2.2 can hold (<size
// nconmax njmax>). 2.2.2 sizes mjData once, at mj_makeData, for nconmax
// contacts and njmax rows (mjxmacro.h: efc_J and efc_JT njmax x nv,
// efc_AR njmax x njmax, their int twins beside them; the buffer's size is an
// int and it is zeroed whole) and stops adding at either
// (mjWARN_CONTACTFULL / mjWARN_CNSTRFULL: the run ends, the reason names
// the setting); without <size> it compiles in 100 and 500 (user_model.cc),
// which a scene of ten boxes already passes. A scene's capacity comes from
// the scene, by a stated rule, per moving body of a contact group:
//   contacts: kPairsPerBody pairs with moving members at once (each counted
//   once, for one of its two bodies) plus one with each fixed member, each
//   pair the most contacts its collider reports (contacts_per_pair);
//   rows: every contact pressed, times the rows MuJoCo makes of one (condim
//   1: 1; condim 3: 4 in the pyramidal cone, 3 in the elliptic), but no more
//   than kMaxCapacityBytes of mjData allow (njmax^2 grows past any machine:
//   a 1000-disk pile would need 2.8 GB); a run that needs more ends with
//   mjWARN_CNSTRFULL naming mujoco.njmax.
// A case without groups keeps MuJoCo's defaults (its MJCF unchanged).
// mujoco.nconmax and mujoco.njmax override the rule; the mapping states the
// capacity and the bytes, extra_attributes the most of it a run used.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "mujoco_plan.hpp"
#include "mujoco_settings.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

// pairs of moving bodies one body is in at once, each counted once: a disk
// among equal disks touches at most 6 (the plane's kissing number), a brick
// in a wall 6 (two below, two above, two beside), 3 per body. Measured most
// contacts per moving body (extra_attributes): pile_100 2.4, stack_50 3.0,
// pyramid_5 6.0, pyramid_20 7.4 (multiccd: up to 5 a pair)
inline constexpr int kPairsPerBody = 3;
// bytes of 2.2.2's mjData the rule's njmax may take (capacity_bytes)
inline constexpr double kMaxCapacityBytes = 1024.0 * 1024.0 * 1024.0;
// MuJoCo's compiled-in capacity (user_model.cc, 2.2.2): the declared pairs' room
inline constexpr int kDefaultNconmax = 100;
inline constexpr int kDefaultNjmax = 500;

struct ContactCapacity {
  int nconmax = 0;  // 0: not written (MuJoCo's 100)
  int njmax = 0;    // 0: not written (MuJoCo's 500)
  std::string rule;
  // bytes of 2.2.2's mjData arrays sized by nconmax and njmax (sizeof
  // mjContact x nconmax, efc_* with njmax x nv and njmax^2 parts)
  double data_bytes = 0.0;
  [[nodiscard]] nlohmann::json json() const;
};

// the model's DOFs: 3 per free planar body (slide x, slide z, hinge), 1 per pendulum
[[nodiscard]] int model_dofs(const Case& c, const MujocoPlan& plan);

// the most contacts MuJoCo's collider reports for two geoms of these types
// (2.2.2 and 3.3.8): plane-mesh 3 (mjc_PlaneConvex's maxplanemesh),
// mesh-mesh 1, or with multiccd 5 (2.2.2: one and four turned; 3.3.8: 4),
// every other pair 1 (spheres and ellipsoids take no multiccd)
[[nodiscard]] int contacts_per_pair(GeomType a, GeomType b, bool multiccd);

// nv: the model's DOFs (model_dofs); multiccd: the flag the model has
[[nodiscard]] ContactCapacity contact_capacity(const Case& c, const MujocoPlan& plan,
                                               const MujocoSettings& s, int nv, bool multiccd);

// the bytes 2.2.2's mjData spends on nconmax contacts and njmax rows at nv
[[nodiscard]] double capacity_bytes(int nconmax, int njmax, int nv);

}  // namespace pb::internal::mujoco
