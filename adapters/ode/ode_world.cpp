#include "ode_world.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "ode_frame.hpp"
#include "ode_library.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::ode {

namespace {
thread_local long t_world_steps = 0;
}  // namespace

void step_world(dWorldID world, double step_s) {
  dWorldStep(world, step_s);
  ++t_world_steps;
}

void quick_step_world(dWorldID world, double step_s) {
  dWorldQuickStep(world, step_s);
  ++t_world_steps;
}

long world_steps_on_this_thread() { return t_world_steps; }

namespace {

// ODE body with the case's mass and inertia; I_xx = I_yy = I_zz = the case's
// planar inertia: a valid inertia tensor (positive, triangle inequality
// holds) whose out-of-plane entries never act, since Plane2D or the z hinge
// removes rotation about x and y
dBodyID make_body(dWorldID world, const Body& b) {
  if (!(b.mass_kg > 0.0) || !(b.inertia_kgm2 > 0.0)) {
    throw EngineError(
        fmt::format("ode: body '{}' needs mass > 0 and inertia > 0 (got {} kg, {} kg m^2)", b.name,
                    b.mass_kg, b.inertia_kgm2));
  }
  dBodyID body = dBodyCreate(world);
  dMass m;
  dMassSetParameters(&m, b.mass_kg, 0.0, 0.0, 0.0, b.inertia_kgm2, b.inertia_kgm2, b.inertia_kgm2,
                     0.0, 0.0, 0.0);
  if (dMassCheck(&m) == 0) {
    throw EngineError(fmt::format("ode: dMassCheck refused the mass of body '{}'", b.name));
  }
  dBodySetMass(body, &m);
  const Vector3 p = to_ode_vector(b.position_m);
  dBodySetPosition(body, p[0], p[1], p[2]);
  const Quaternion q = to_ode_quaternion(b.angle_rad);
  const dQuaternion dq = {q[0], q[1], q[2], q[3]};
  dBodySetQuaternion(body, dq);
  const Vector3 v = to_ode_vector(b.velocity_mps);
  dBodySetLinearVel(body, v[0], v[1], v[2]);
  dBodySetAngularVel(body, 0.0, 0.0, b.angular_velocity_radps);
  // no sleeping: every step is measured
  dBodySetAutoDisableFlag(body, 0);
  return body;
}

}  // namespace

OdeWorld::OdeWorld(const Case& c)
    : case_bodies_(c.bodies), gravity_mps2_(c.gravity_mps2), duration_s_(c.duration_s) {
  // E(0) = KE(0) until the engine adds the contacts' elastic energy
  energy_bound_.gravity_mps2 = c.gravity_mps2.norm();
  for (const Body& b : c.bodies) {
    if (b.fixed) continue;
    energy_bound_.moving_mass_kg += b.mass_kg;
    energy_bound_.initial_j += 0.5 * b.mass_kg * b.velocity_mps.squaredNorm() +
                               0.5 * b.inertia_kgm2 * b.angular_velocity_radps *
                                   b.angular_velocity_radps;
  }
  kinetic_start_j_ = energy_bound_.initial_j;
  set_runaway_bounds();
  ensure_ode_ready_in_this_thread();
  // the destructor does not run when a constructor throws: release here
  try {
    build(c);
  } catch (...) {
    destroy();
    throw;
  }
}

void OdeWorld::build(const Case& c) {
  world_ = dWorldCreate();
  // a threading implementation of its own: without one every world shares
  // ODE's global default, and two worlds stepped at once in two threads
  // corrupt it (threading_impl.h; seen as "ODE INTERNAL ERROR 1 ...
  // m_dependencies_count" in ode_engine_test's two-thread run)
  threading_ = dThreadingAllocateSelfThreadedImplementation();
  if (threading_ == nullptr)
    throw EngineError("ode: dThreadingAllocateSelfThreadedImplementation failed");
  dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_),
                                       threading_);
  // a scene's pairs come from ODE's broad phase (ode_space_collider.hpp):
  // sweep and prune along the axis the bodies spread over (scene_space); a
  // case of declared pairs collides them directly (PairCollider) and never
  // traverses its space
  space_ = c.has_contact_groups() ? scene_space(c) : dSimpleSpaceCreate(nullptr);
  contact_group_ = dJointGroupCreate(0);
  dWorldSetGravity(world_, c.gravity_mps2.x(), c.gravity_mps2.y(), 0.0);
  // ODE defaults stated explicitly: no sleeping, no surface layer (it would
  // shift the penetration), no cap on the ERP correcting velocity (it would
  // cap the soft contact's spring term), no velocity damping
  dWorldSetAutoDisableFlag(world_, 0);
  dWorldSetContactSurfaceLayer(world_, 0.0);
  dWorldSetContactMaxCorrectingVel(world_, dInfinity);
  dWorldSetLinearDamping(world_, 0.0);
  dWorldSetAngularDamping(world_, 0.0);

  const std::size_t n = c.bodies.size();
  bodies_.assign(n, nullptr);
  geoms_.assign(n, {});
  planar_.assign(n, false);
  descriptions_.resize(n);
  vertex_counts_.assign(n, 0);

  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = c.bodies[i];
    if (!b.fixed) bodies_[i] = make_body(world_, b);

    // geometry: half-planes are non-placeable ODE planes, so they must be fixed
    std::vector<dGeomID> gs;
    if (std::holds_alternative<HalfPlane>(b.shape)) {
      if (!b.fixed) {
        throw EngineError(
            fmt::format("ode: body '{}' is a moving half-plane; ODE planes cannot move", b.name));
      }
      const PlaneCoefficients pc = halfplane_plane(b.position_m, b.angle_rad);
      gs.push_back(dCreatePlane(space_, pc.a, pc.b, pc.c, pc.d));
      descriptions_[i] = describe_shape_geom(b, ConvexPrism{});
      vertex_counts_[i] = 1;
    } else {
      ShapeGeoms sg = create_shape_geoms(space_, b, prisms_, c.has_contact_groups());
      vertex_counts_[i] = sg.vertices;
      gs = std::move(sg.geoms);
      descriptions_[i] = std::move(sg.description);
      const double cos_a = std::cos(b.angle_rad);
      const double sin_a = std::sin(b.angle_rad);
      for (std::size_t k = 0; k < gs.size(); ++k) {
        const dGeomID g = gs[k];
        const Vec2& off = sg.offsets_m[k];
        if (bodies_[i] != nullptr) {
          dGeomSetBody(g, bodies_[i]);
          if (!off.isZero(0.0)) dGeomSetOffsetPosition(g, off.x(), off.y(), 0.0);
        } else {
          const Vector3 p = to_ode_vector(b.position_m + Vec2(cos_a * off.x() - sin_a * off.y(),
                                                              sin_a * off.x() + cos_a * off.y()));
          dGeomSetPosition(g, p[0], p[1], p[2]);
          const Quaternion q = to_ode_quaternion(b.angle_rad);
          const dQuaternion dq = {q[0], q[1], q[2], q[3]};
          dGeomSetQuaternion(g, dq);
        }
      }
    }
    geom_data_.push_back(std::make_unique<int>(static_cast<int>(i)));
    for (const dGeomID g : gs) dGeomSetData(g, geom_data_.back().get());
    geoms_[i] = std::move(gs);
  }

  // revolute joints to ground: a hinge about z through the anchor
  std::vector<int> joint_count(n, 0);
  for (const RevoluteJoint& j : c.joints) {
    const auto bi = static_cast<std::size_t>(j.body);
    if (j.body < 0 || bi >= n || bodies_[bi] == nullptr) {
      throw EngineError(fmt::format("ode: joint '{}' needs a moving body", j.name));
    }
    ++joint_count[bi];
    dJointID h = dJointCreateHinge(world_, nullptr);
    dJointAttach(h, bodies_[bi], nullptr);
    dJointSetHingeAnchor(h, j.anchor_world_m.x(), j.anchor_world_m.y(), 0.0);
    dJointSetHingeAxis(h, 0.0, 0.0, 1.0);
  }
  // free bodies stay in z = 0 through Plane2D; hinged ones through the hinge
  for (std::size_t i = 0; i < n; ++i) {
    if (bodies_[i] == nullptr || joint_count[i] > 0) continue;
    dJointID p = dJointCreatePlane2D(world_, nullptr);
    dJointAttach(p, bodies_[i], nullptr);
    planar_[i] = true;
  }
}

// ODE's sweep and prune space sorts the geoms' boxes along its first axis
// (a radix sort each dSpaceCollide) and tests the other two axes for the
// pairs overlapping along it; infinite boxes (planes) are collided with
// every geom. The first axis is the one the moving bodies' centres spread
// over most at the start (ties: x), so that few boxes share a slab along
// it: x for a pile or a pyramid, y for a stack (all at x = 0, where x first
// would pair every box with every box). Measured on pile_1000
// (dWorldQuickStep, 2 s): 112 s of CPU with x first against 158 s with
// dHashSpace at levels fitted to the disks (ODE's defaults, -3 .. 10, made
// every disk visit 14 levels). The space decides the order in which pairs
// are first met, hence their indices and the order of the joints (made in
// pair order): another space gives another, equally valid, rounding.
dSpaceID OdeWorld::scene_space(const Case& c) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const Body& b : c.bodies) {
    if (b.fixed) continue;
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], b.position_m[k]);
      hi[k] = std::max(hi[k], b.position_m[k]);
    }
  }
  const bool y_first = hi[1] - lo[1] > hi[0] - lo[0];
  sweep_axes_ = y_first ? "y, then x and z" : "x, then y and z";
  return dSweepAndPruneSpaceCreate(nullptr, y_first ? dSAP_AXES_YXZ : dSAP_AXES_XYZ);
}

OdeWorld::~OdeWorld() {
  destroy();
}

void OdeWorld::destroy() {
  // the space destroys its geoms (cleanup mode is on by default); the world
  // destroys its bodies and joints
  if (contact_group_ != nullptr) dJointGroupDestroy(contact_group_);
  if (space_ != nullptr) dSpaceDestroy(space_);
  if (world_ != nullptr) dWorldDestroy(world_);
  if (threading_ != nullptr) dThreadingFreeImplementation(threading_);
  contact_group_ = nullptr;
  space_ = nullptr;
  world_ = nullptr;
  threading_ = nullptr;
}

int OdeWorld::body_index_of(dGeomID g) {
  return *static_cast<const int*>(dGeomGetData(g));
}

BodyState OdeWorld::state(int i) const {
  const auto idx = static_cast<std::size_t>(i);
  BodyState s;
  const dBodyID b = bodies_[idx];
  if (b == nullptr) {
    s.position_m = case_bodies_[idx].position_m;
    s.angle_rad = case_bodies_[idx].angle_rad;
    return s;
  }
  s.position_m = to_case_vector(dBodyGetPosition(b));
  s.angle_rad = angle_from_ode_rotation(dBodyGetRotation(b));
  s.velocity_mps = to_case_vector(dBodyGetLinearVel(b));
  s.angular_velocity_radps = dBodyGetAngularVel(b)[2];
  return s;
}

std::vector<Vec2> OdeWorld::centres() const {
  std::vector<Vec2> out;
  out.reserve(bodies_.size());
  for (int i = 0; i < body_count(); ++i) out.push_back(state(i).position_m);
  return out;
}

void OdeWorld::remove_planar_drift() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!planar_[i]) continue;
    const dBodyID b = bodies_[i];
    const Quaternion q = planar_quaternion(dBodyGetQuaternion(b));
    const dQuaternion dq = {q[0], q[1], q[2], q[3]};
    dBodySetQuaternion(b, dq);
    const dReal* w = dBodyGetAngularVel(b);
    dBodySetAngularVel(b, 0.0, 0.0, w[2]);
  }
}

void OdeWorld::set_initial_contact_energy(double elastic_j) {
  energy_bound_.initial_j = kinetic_start_j_ + std::max(0.0, elastic_j);
  set_runaway_bounds();
}

void OdeWorld::set_runaway_bounds() {
  // the bounds at the end of the run hold for the whole run (they grow with
  // t); E(0) gets the budget's floor (every body at kEnergyFloorSpeedMps) so
  // that a case where nothing moves has bounds > 0
  EnergyBound bound = energy_bound_;
  for (const Body& b : case_bodies_) {
    if (!b.fixed) bound.initial_j += 0.5 * b.mass_kg * kEnergyFloorSpeedMps * kEnergyFloorSpeedMps;
  }
  const double ke_j = kRunawayEnergyFactor * bound.kinetic_j(duration_s_);
  const double reach = std::sqrt(kRunawayEnergyFactor);
  bounds_.assign(case_bodies_.size(), Bounds{});
  for (std::size_t i = 0; i < case_bodies_.size(); ++i) {
    const Body& b = case_bodies_[i];
    if (b.fixed) continue;
    bounds_[i].speed_mps = std::sqrt(2.0 * ke_j / b.mass_kg);
    bounds_[i].spin_radps = std::sqrt(2.0 * ke_j / b.inertia_kgm2);
    bounds_[i].displacement_m = reach * bound.displacement_m(b.mass_kg, duration_s_);
  }
}

namespace {

// |(x, y, z)|
double norm3(const dReal* v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

int OdeWorld::first_blown_up_body() const {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const dBodyID b = bodies_[i];
    if (b == nullptr) continue;
    const dReal* p = dBodyGetPosition(b);
    const dReal* q = dBodyGetQuaternion(b);
    const Vec2& p0 = case_bodies_[i].position_m;
    const dReal moved[3] = {p[0] - p0.x(), p[1] - p0.y(), p[2]};
    // NaN fails every comparison: !(x <= bound) catches it
    bool ok = norm3(moved) <= bounds_[i].displacement_m &&
              norm3(dBodyGetLinearVel(b)) <= bounds_[i].speed_mps &&
              norm3(dBodyGetAngularVel(b)) <= bounds_[i].spin_radps;
    for (int k = 0; k < 4; ++k) ok = ok && std::isfinite(q[k]);
    if (!ok) return static_cast<int>(i);
  }
  return -1;
}

std::string OdeWorld::blow_up_reason(int i) const {
  const auto idx = static_cast<std::size_t>(i);
  const BodyState s = state(i);
  const dReal* q = dBodyGetQuaternion(bodies_[idx]);
  const bool finite = s.position_m.allFinite() && s.velocity_mps.allFinite() &&
                      std::isfinite(s.angular_velocity_radps) && std::isfinite(q[0]) &&
                      std::isfinite(q[1]) && std::isfinite(q[2]) && std::isfinite(q[3]);
  if (!finite) return "its state is not finite (NaN or inf)";
  return fmt::format(
      "it runs away: |v| = {:.4g} m/s (bound {:.4g}), |omega| = {:.4g} rad/s (bound {:.4g}), "
      "{:.4g} m from its start (bound {:.4g}); the bounds are {} times the most kinetic energy a "
      "passive system starting with {:.4g} J can reach in {} s under gravity",
      s.velocity_mps.norm(), bounds_[idx].speed_mps, std::abs(s.angular_velocity_radps),
      bounds_[idx].spin_radps, (s.position_m - case_bodies_[idx].position_m).norm(),
      bounds_[idx].displacement_m, kRunawayEnergyFactor, energy_bound_.initial_j, duration_s_);
}

std::string OdeWorld::applied_force_reason(int i, const Vec2& force_n, double torque_nm,
                                           double step_s) const {
  const auto idx = static_cast<std::size_t>(i);
  const Body& b = case_bodies_[idx];
  const BodyState s = state(i);
  // ODE's semi-implicit Euler: v += h (g + F / m), omega += h tau / I
  const Vec2 v = s.velocity_mps + step_s * (gravity_mps2_ + force_n / b.mass_kg);
  const double w = s.angular_velocity_radps + step_s * torque_nm / b.inertia_kgm2;
  if (v.norm() <= bounds_[idx].speed_mps && std::abs(w) <= bounds_[idx].spin_radps) return "";
  return fmt::format(
      "the contact force it is about to get, |F| = {:.4g} N (torque {:.4g} N m), would take it to "
      "|v| = {:.4g} m/s (bound {:.4g}), |omega| = {:.4g} rad/s (bound {:.4g}) in one step of {} "
      "s: the explicit force law runs away (too stiff for this step; use more ode.substeps)",
      force_n.norm(), torque_nm, v.norm(), bounds_[idx].speed_mps, std::abs(w),
      bounds_[idx].spin_radps, step_s);
}

}  // namespace pb::internal::ode
