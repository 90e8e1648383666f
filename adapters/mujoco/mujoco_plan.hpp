// The MuJoCo form of a case, decided once per build, before any MJCF is
// written: what each case body becomes (geom type, convex pieces and their
// bipyramid apexes, joints), each declared case pair (collider, margin,
// contact dimension, friction) and each contact group (its collision bit and
// the geom attributes MuJoCo's own broad phase mixes into a contact).
// write_mjcf, model_layout and the engine read it, so a polygon is decomposed
// once and every stage agrees on what it wrote.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mujoco_geometry.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

struct BodyPlan {
  GeomType geom = GeomType::plane;
  // mesh: the convex polygons, one geom each (the polygon itself when convex),
  // and the apex over which each one's bipyramid stands (mujoco_geometry.hpp)
  std::vector<Polygon> pieces;
  std::vector<Vec2> apexes;
  bool decomposed = false;
  std::string decomposition;  // how, when decomposed
  int joint = -1;             // the case joint of a pendulum body, -1 otherwise
  // contact groups (SPEC §11): one copy of the body's geoms per group it is
  // in (copy c for groups[c]), each colliding through its group's bit only
  // and carrying its group's attributes, so that a body in two groups meets
  // each with that group's law; a body in no group has one copy (copy 0)
  // that collides through explicit <pair>s only. copy_margin_m[c]: m, the
  // copy's geom margin (and gap) in its group (GroupPlan)
  std::vector<int> groups;
  std::vector<double> copy_margin_m;
  // geoms of one copy (one per convex piece)
  [[nodiscard]] int geom_count() const {
    return pieces.empty() ? 1 : static_cast<int>(pieces.size());
  }
  [[nodiscard]] int copy_count() const {
    return groups.empty() ? 1 : static_cast<int>(groups.size());
  }
  // the copy of group g (0 when the body is not in it)
  [[nodiscard]] int copy_of_group(int g) const;
};

// A contact group as geoms MuJoCo collides by itself (mj_collision's broad
// phase, engine_collision_driver.c): every geom of the group's copies has
// contype = conaffinity = 1 << bit, so two geoms meet iff they share a group
// ((contype1 & conaffinity2) || (contype2 & conaffinity1)); MuJoCo mixes two
// geoms' attributes into a contact by max (condim, friction, margin, gap),
// min (a direct solref), or the mean (solimp): equal attributes on every
// geom of the group give the group's own. Margin: a geom gets the detection
// margin when every geom type it can meet in its group has an exact collider
// (plane-*, sphere-sphere), else 0 (a margin spoils MPR's depth); the max of
// two geoms' margins is then 0 on every MPR pair and the detection margin on
// the exact pairs of a group without MPR partners.
struct GroupPlan {
  int bit = 0;  // contype = conaffinity = 1 << bit
  int condim = 1;
  // geom friction (sliding, torsional, rolling): mu, then MuJoCo's defaults;
  // MuJoCo unpacks it to (mu, mu, torsional, rolling, rolling), the declared
  // pairs' five numbers
  std::array<double, 3> friction = {1.0, 0.005, 0.0001};
};

struct PairPlan {
  bool present = false;  // false when both bodies are fixed (no <pair> written)
  GeomType geom_a = GeomType::plane;
  GeomType geom_b = GeomType::plane;
  Collider collider = Collider::none;
  // m: MuJoCo reports the pair below this distance (exact colliders only: a
  // margin spoils MPR's depth)
  double margin_m = 0.0;
  // condim 1 (frictionless) or 3 (Coulomb friction, SPEC §7), and the pair's
  // friction (tangent1, tangent2, spin, roll1, roll2): mu on both tangents,
  // MuJoCo's pair defaults for spin and roll (unused at condim 3). In the
  // x-z plane MuJoCo's first tangent is world y, where no body has a degree
  // of freedom; the second is the plane's (mju_makeFrame), so mu must be on both
  int condim = 1;
  std::array<double, 5> friction = {1.0, 1.0, 0.005, 0.0001, 0.0001};
  // MPR pair with an exact penetration to check MuJoCo's depth against
  bool check_depth = false;
};

struct MujocoPlan {
  std::vector<BodyPlan> bodies;   // index = Case::bodies index
  std::vector<PairPlan> pairs;    // index = Case::contacts index
  std::vector<GroupPlan> groups;  // index = Case::contact_groups index
};

// one collision bit per group (contype, conaffinity): MuJoCo's are an int's,
// bit 31 its sign, so 31
inline constexpr int kMaxContactGroups = 31;

// Memory: MuJoCo collides only explicit <pair>s here, one per two convex
// pieces of a case pair: pieces_a x pieces_b. Its compiler and model take
// ~2900 bytes a pair (measured with /usr/bin/time -v: two 400-point concave
// stars, 200 x 200 = 4e4 pairs, peak 139 MB against 24 MB for a disk on the
// ground). Above kMaxGeomPairs (1e5, ~0.29 GB) plan_mujoco refuses the case
// before MuJoCo allocates anything, naming the count: two 2000-point stars
// would need 1e6 pairs, ~2.9 GB. A star on a half-plane needs pieces x 1.
inline constexpr long kMaxGeomPairs = 100'000;
inline constexpr long kBytesPerGeomPair = 2900;

// detection_margin_m: the margin of exact-collider pairs (mujoco.detection_margin).
// Throws EngineError when the case needs more than kMaxGeomPairs geom pairs
// or kMaxContactGroups groups.
[[nodiscard]] MujocoPlan plan_mujoco(const Case& c, double detection_margin_m);

// whether a contact group lets two polygons (mesh geoms) meet, one moving
[[nodiscard]] bool group_meshes_meet(const Case& c, const MujocoPlan& plan);

// whether MuJoCo's depth of bodies a and b is checked against the exact
// geometry (an MPR pair whose exact penetration is known: circle-ellipse)
[[nodiscard]] bool depth_checked(const Case& c, const MujocoPlan& plan, int a, int b);

}  // namespace pb::internal::mujoco
