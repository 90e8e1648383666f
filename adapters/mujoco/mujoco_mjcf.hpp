// MJCF text of a case: one MuJoCo body per moving case body, one geom per
// body (one per convex piece of a non-convex polygon), one explicit <pair>
// per declared case contact pair (per two pieces); the bodies of a contact
// group collide by MuJoCo's own broad phase through their group's collision
// bit (one copy of a body's geoms per group it is in, mujoco_plan.hpp);
// everything else unable to collide.
// Written from the pb::Case and its MujocoPlan (mujoco_plan.hpp): no code
// path per case, and no geometry decided here.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mujoco_plan.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

// MuJoCo's solver parameters of one case contact pair (the geometry, condim
// and friction are the plan's)
struct PairParams {
  std::array<double, 2> solref = {0.02, 1.0};  // MuJoCo's default; direct form (-k, -b) when < 0
  std::array<double, 5> solimp = {0.9, 0.95, 0.001, 0.5, 2.0};
  double gap_m = 0.0;  // m, contacts with distance >= margin - gap are inactive
};

struct MjcfOptions {
  double dt_s = 1e-4;
  std::string integrator = "Euler";
  std::string solver = "Newton";
  int iterations = 100;
  double tolerance = 1e-8;
  // friction cone (mjOption::cone), impratio and noslip_iterations: MuJoCo's
  // defaults, which leave a frictionless (condim 1) model as it was
  std::string cone = "pyramidal";
  double impratio = 1.0;
  int noslip_iterations = 0;
  std::vector<PairParams> pairs;  // index = Case::contacts index
  // index = Case::contact_groups index: the solref and solimp of the group's
  // geoms (its gap is each copy's margin, GroupPlan: active below distance 0)
  std::vector<PairParams> groups;
  // <size nconmax njmax> (MuJoCo 2.2.2's fixed contact and constraint
  // capacity; mujoco_capacity.hpp); 0: not written (MuJoCo's defaults, 100
  // and 500, and for MuJoCo 3 its default arena)
  int nconmax = 0;
  int njmax = 0;
  // MuJoCo 3 only: <size memory="NM"> (its arena, MB); 0: not written
  int memory_mb = 0;
  // <flag multiccd="enable">: MuJoCo's convex-convex collider (mesh-mesh)
  // reports several contacts of a flat contact, not one (mujoco_settings.hpp)
  bool multiccd = false;
  // the MuJoCo the text is for: 2 (2.2.2) or 3 (3.3.8). What 3 reads that 2
  // refuses: solreffriction on a <pair> (2.3.6 on) and the integrators
  // "implicit" (2.3.0) and "implicitfast" (2.3.3); the writer refuses them
  // for 2 rather than write text 2.2.2 would reject
  int mujoco_major = 2;
  // the friction rows' own solref on every pair with friction; {0, 0}:
  // none written (MuJoCo's default: the contact's solref)
  std::array<double, 2> solreffriction = {0.0, 0.0};
};

// names of the MuJoCo elements of case body i and pair k; a polygon cut into
// convex pieces has one geom (and mesh) per piece, and a case pair one
// MuJoCo <pair> per two pieces (piece 0 keeps the plain names)
[[nodiscard]] std::string body_name(int i);
[[nodiscard]] std::string geom_name(int i, int piece = 0, int copy = 0);
[[nodiscard]] std::string mesh_name(int i, int piece = 0);
[[nodiscard]] std::string pair_name(int k, int piece_a = 0, int piece_b = 0);
[[nodiscard]] std::string slide_x_name(int i);
[[nodiscard]] std::string slide_z_name(int i);
[[nodiscard]] std::string hinge_name(int i);

// The joint set of a moving body: a free body gets slide x, slide z, hinge y
// (in this order, so that the slides move along world axes and the hinge
// turns about the centre of mass); a body with a revolute joint to ground gets
// one hinge about y at its pivot. Index of the case joint of body i, or -1.
[[nodiscard]] int joint_of_body(const Case& c, int body);

// The pivot in the body frame, derived from the case at t = 0 (the case's
// anchor_world and the body's pose): R(-theta0) (anchor_world - position).
[[nodiscard]] Vec2 pivot_in_body_m(const Case& c, const RevoluteJoint& j);

// The MJCF text. Every moving body is placed in its reference pose (angle 0;
// a free body at its initial position, a pendulum body at its pivot); the
// initial angle and velocities are set on qpos/qvel after loading
// (initial_state below), so that joint coordinates start at known values.
// Throws EngineError for shapes or joints MuJoCo cannot take (see supports()).
[[nodiscard]] std::string write_mjcf(const Case& c, const MujocoPlan& plan,
                                     const MjcfOptions& options);

}  // namespace pb::internal::mujoco
