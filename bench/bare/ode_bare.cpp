// Bare ODE loop (issue 22): ODE 0.16.2 (double) used directly, as a user
// would, on exactly the scene and settings the "ode" adapter (native mode,
// stepper "world") builds for falling_ball and disk_roll, so that callgrind's
// instructions per step of this program against the adapter's measure only
// the adapter's overhead.
//
// Mirrors:
//   adapters/ode/ode_library.cpp   dInitODE2(0), dAllocateODEDataForThread;
//   adapters/ode/ode_world.cpp     one world with its own self-threaded
//       threading implementation, a simple space, a contact joint group;
//       gravity, no auto-disable, contact surface layer 0, no cap on the
//       correcting velocity, no damping; the disk's mass by dMassSetParameters
//       (m, centre at the origin, I_xx = I_yy = I_zz = I); a Plane2D joint; the
//       orientation's planar drift re-zeroed after every step
//       (remove_planar_drift, ode_frame.cpp planar_quaternion);
//   adapters/ode/ode_geometry.cpp  the half-plane as dCreatePlane with normal
//       (-sin a, cos a, 0), offset n . position = 0; the disk a sphere;
//   adapters/ode/ode_pair_contact.cpp   dCollide called directly on the case's
//       pair (no space traversal), the geom with a body first, the contact kept
//       in z = 0 (pos z and normal z zeroed, normal renormalised), buffer of
//       2 x 180 + 4 contacts;
//   adapters/ode/ode_engine.cpp (add_native_joints, step_once)   a contact
//       joint per contact with depth > 0: dContactSoftERP | dContactSoftCFM,
//       mu = 0, ERP/CFM from the Kelvin-Voigt law at the step (one contact: the
//       law itself), dJointSetFeedback, dWorldStep(h), dJointGroupEmpty;
//   adapters/ode/ode_contact_mapping.cpp (soft_row, "corrected")   c' = c - hk
//       (c >= hk here), ERP = hk / (hk + c'), CFM = 1 / (hk + c');
//   adapters/ode/ode_friction.cpp  with friction: dContactApprox1 | dContactFDir1
//       | dContactMu2, mu, mu2 = 0, fdir1 = the normal turned by +90 deg.
// Leaves out, deliberately (that is the adapter's overhead being measured):
//   the per-step pair summary (deepest contact, depth-weighted point, approach
//   speed), the law's linearisation and spread over a pair's contacts (one
//   contact: ERP/CFM computed inline), the feedback's force sum, the runaway
//   check, the unwrapped angle, the episode tracker, the message counter.
//
// Usage: ode_bare <falling_ball|disk_roll> <steps>
// Build: g++ -O3 -DNDEBUG -std=c++20 ode_bare.cpp -o ode_bare $(pkg-config --cflags --libs ode)
#include <ode/ode.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "bare_scene.hpp"

using namespace bare;

namespace {

// the adapter's contact buffer per geom pair: max(16, 2 outline_points + 4)
constexpr int kContactBuffer = 2 * 180 + 4;

}  // namespace

int main(int argc, char** argv) {
  long steps = 0;
  const Scene* s = parse_command_line(argc, argv, steps);
  if (s == nullptr) return 2;

  dInitODE2(0);
  dAllocateODEDataForThread(dAllocateMaskAll);
  dWorldID world = dWorldCreate();
  dThreadingImplementationID threading = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading),
                                       threading);
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  dJointGroupID contacts = dJointGroupCreate(0);
  dWorldSetGravity(world, 0.0, -kGravity, 0.0);
  dWorldSetAutoDisableFlag(world, 0);
  dWorldSetContactSurfaceLayer(world, 0.0);
  dWorldSetContactMaxCorrectingVel(world, dInfinity);
  dWorldSetLinearDamping(world, 0.0);
  dWorldSetAngularDamping(world, 0.0);

  // ground: the plane n . x = 0, n = (-sin a, cos a) (the surface line's +90 deg turn)
  dGeomID plane =
      dCreatePlane(space, -std::sin(s->ground_angle_rad), std::cos(s->ground_angle_rad), 0.0, 0.0);

  // the disk
  dBodyID body = dBodyCreate(world);
  dMass mass;
  dMassSetParameters(&mass, s->mass_kg, 0.0, 0.0, 0.0, s->inertia_kgm2, s->inertia_kgm2,
                     s->inertia_kgm2, 0.0, 0.0, 0.0);
  dBodySetMass(body, &mass);
  dBodySetPosition(body, s->x0_m, s->y0_m, 0.0);
  const dQuaternion identity = {1.0, 0.0, 0.0, 0.0};
  dBodySetQuaternion(body, identity);
  dBodySetLinearVel(body, 0.0, 0.0, 0.0);
  dBodySetAngularVel(body, 0.0, 0.0, 0.0);
  dBodySetAutoDisableFlag(body, 0);
  dGeomID sphere = dCreateSphere(space, s->radius_m);
  dGeomSetBody(sphere, body);
  dJointID planar = dJointCreatePlane2D(world, nullptr);
  dJointAttach(planar, body, nullptr);

  // soft contact of the Kelvin-Voigt law, corrected mapping (c >= hk in both scenes)
  const double hk = kDt * s->stiffness_n_per_m;
  const double c_used = s->damping_ns_per_m >= hk ? s->damping_ns_per_m - hk : 0.0;
  const double erp = hk / (hk + c_used);
  const double cfm = 1.0 / (hk + c_used);

  static dContactGeom buffer[kContactBuffer];
  static dJointFeedback feedback[kContactBuffer];
  for (long n = 0; n < steps; ++n) {
    // the contacts of the state this step starts from; the geom with a body first
    const int count = dCollide(sphere, plane, kContactBuffer, buffer, sizeof(dContactGeom));
    for (int k = 0; k < count; ++k) {
      dContactGeom g = buffer[k];
      g.pos[2] = 0.0;
      g.normal[2] = 0.0;
      const double len = std::hypot(g.normal[0], g.normal[1]);
      if (!(len > 0.0)) continue;
      g.normal[0] /= len;
      g.normal[1] /= len;
      if (!(g.depth > 0.0)) continue;
      dContact contact{};
      contact.surface.mode = dContactSoftERP | dContactSoftCFM;
      contact.surface.mu = 0.0;
      contact.surface.soft_erp = erp;
      contact.surface.soft_cfm = cfm;
      contact.geom = g;
      if (s->friction > 0.0) {
        contact.surface.mode |= dContactApprox1 | dContactFDir1 | dContactMu2;
        contact.surface.mu = s->friction;
        contact.surface.mu2 = 0.0;
        contact.fdir1[0] = -g.normal[1];
        contact.fdir1[1] = g.normal[0];
        contact.fdir1[2] = 0.0;
      }
      dJointID j = dJointCreateContact(world, contacts, &contact);
      dJointAttach(j, dGeomGetBody(g.g1), dGeomGetBody(g.g2));
      dJointSetFeedback(j, &feedback[k]);
    }
    dWorldStep(world, kDt);
    dJointGroupEmpty(contacts);
    // Plane2D leaves the orientation's drift to the application: keep the z turn and spin
    const dReal* q = dBodyGetQuaternion(body);
    const double qn = std::hypot(q[0], q[3]);
    const dQuaternion planar_q = {q[0] / qn, 0.0, 0.0, q[3] / qn};
    dBodySetQuaternion(body, planar_q);
    const dReal* w = dBodyGetAngularVel(body);
    dBodySetAngularVel(body, 0.0, 0.0, w[2]);

    const dReal* p = dBodyGetPosition(body);
    const dReal* r = dBodyGetRotation(body);
    const dReal* v = dBodyGetLinearVel(body);
    Sample& o = g_samples[n & 63];
    o.x = p[0];
    o.y = p[1];
    o.angle = std::atan2(r[4], r[0]);
    o.vx = v[0];
    o.vy = v[1];
    o.omega = dBodyGetAngularVel(body)[2];
  }
  const Sample last = steps > 0 ? g_samples[(steps - 1) & 63] : Sample{s->x0_m, s->y0_m, 0, 0, 0, 0};
  std::printf("ode %s steps=%ld x=%.17g y=%.17g\n", s->name, steps, last.x, last.y);

  dJointGroupDestroy(contacts);
  dSpaceDestroy(space);
  dWorldDestroy(world);
  dThreadingFreeImplementation(threading);
  dCloseODE();
  return 0;
}
