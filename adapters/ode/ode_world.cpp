#include "ode_world.hpp"

#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "ode_frame.hpp"
#include "ode_library.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::ode {

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

OdeWorld::OdeWorld(const Case& c) : case_bodies_(c.bodies) {
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
  space_ = dSimpleSpaceCreate(nullptr);
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
  geoms_.assign(n, nullptr);
  planar_.assign(n, false);
  descriptions_.resize(n);

  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = c.bodies[i];
    if (!b.fixed) bodies_[i] = make_body(world_, b);

    // geometry: half-planes are non-placeable ODE planes, so they must be fixed
    dGeomID g = nullptr;
    auto prism = std::make_unique<ConvexPrism>();
    if (std::holds_alternative<HalfPlane>(b.shape)) {
      if (!b.fixed) {
        throw EngineError(
            fmt::format("ode: body '{}' is a moving half-plane; ODE planes cannot move", b.name));
      }
      const PlaneCoefficients pc = halfplane_plane(b.position_m, b.angle_rad);
      g = dCreatePlane(space_, pc.a, pc.b, pc.c, pc.d);
    } else {
      g = create_shape_geom(space_, b, *prism);
      if (bodies_[i] != nullptr) {
        dGeomSetBody(g, bodies_[i]);
      } else {
        const Vector3 p = to_ode_vector(b.position_m);
        dGeomSetPosition(g, p[0], p[1], p[2]);
        const Quaternion q = to_ode_quaternion(b.angle_rad);
        const dQuaternion dq = {q[0], q[1], q[2], q[3]};
        dGeomSetQuaternion(g, dq);
      }
    }
    geom_data_.push_back(std::make_unique<int>(static_cast<int>(i)));
    dGeomSetData(g, geom_data_.back().get());
    descriptions_[i] = describe_shape_geom(b, *prism);
    prisms_.push_back(std::move(prism));
    geoms_[i] = g;
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

int OdeWorld::first_blown_up_body() const {
  constexpr double kMaxPosition = 1e6;  // m
  constexpr double kMaxSpeed = 1e6;     // m/s
  constexpr double kMaxSpin = 1e8;      // rad/s
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const dBodyID b = bodies_[i];
    if (b == nullptr) continue;
    const dReal* p = dBodyGetPosition(b);
    const dReal* v = dBodyGetLinearVel(b);
    const dReal* w = dBodyGetAngularVel(b);
    const dReal* q = dBodyGetQuaternion(b);
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
      ok = ok && std::isfinite(p[k]) && std::abs(p[k]) <= kMaxPosition;
      ok = ok && std::isfinite(v[k]) && std::abs(v[k]) <= kMaxSpeed;
      ok = ok && std::isfinite(w[k]) && std::abs(w[k]) <= kMaxSpin;
    }
    for (int k = 0; k < 4; ++k) ok = ok && std::isfinite(q[k]);
    if (!ok) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace pb::internal::ode
