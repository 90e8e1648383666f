// Bare MuJoCo loop (issue 22): MuJoCo used directly, as a user would, on
// exactly the scene and settings the "mujoco" adapter (native mode) builds for
// falling_ball and disk_roll, so that callgrind's instructions per step of this
// program against the adapter's measure only the adapter's overhead.
//
// Mirrors:
//   adapters/mujoco/mujoco_mjcf.cpp   the MJCF: the ground half-plane as a plane
//       geom of the world body turned (quat) so that its +z is the case normal,
//       the disk as a body with slide x, slide z and a hinge about +y, an explicit
//       <inertial> (mass, diaginertia I I I), a sphere geom, contype = conaffinity
//       = 0 and one explicit <pair> (condim 1, or 3 with friction
//       "mu mu 0.005 0.0001 0.0001" for a pair with friction, mujoco_plan.cpp);
//   adapters/mujoco/mujoco_settings.hpp   timestep 1e-4, Euler, Newton, 100
//       iterations, tolerance 1e-8, pyramidal cone, impratio 1, noslip 0,
//       solimp (0.9999 0.9999 0.001 0.5 2), margin 0.01 (exact collider);
//   adapters/mujoco/mujoco_engine.cpp   gap = margin (pair_params), case (x, y)
//       -> MuJoCo (x, z), gravity along -z;
//   adapters/mujoco/mujoco_model.cpp   the MJCF loaded from memory (mjVFS,
//       mj_loadXML), the initial state in the joints (qpos = 0 at the body's pos);
//   adapters/mujoco/mujoco_solref_rule.cpp   the direct solref (-K / m_eff,
//       -c / m_eff): a free disk on fixed ground has m_eff = m = 1 kg at every
//       step, so this loop writes it once into the <pair>;
//   adapters/mujoco/mujoco_stepping.cpp   mj_checkPos/Vel, mj_forward, mj_checkAcc,
//       mj_Euler per step, i.e. mj_step (the adapter splits it to sample the
//       state each step starts from: the same work).
// Leaves out, deliberately (that is the adapter's overhead being measured):
//   the solref rule run between mj_collision and mj_makeConstraint every step
//   (mj_jac, mj_solveM, the law linearised at the current penetration), the
//   warning watch, the per-step sampling of pair observations (contact
//   point, force, approach speed), the episode tracker, mj_objectVelocity (the
//   state is read from qpos/qvel, which hold the current centre and its
//   velocity directly: the body's frame origin is its centre of mass).
//
// Usage: mujoco_bare <falling_ball|disk_roll> <steps>
// Build: g++ -O3 -DNDEBUG -std=c++20 mujoco_bare.cpp -o mujoco_bare -lmujoco
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numbers>
#include <string>

#include "bare_scene.hpp"

using namespace bare;

namespace {

constexpr double kMargin = 0.01;     // m, detection margin of an exact collider; gap = margin

}  // namespace

namespace {

std::string num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

std::string mjcf(const Scene& s) {
  // the ground's plane: +z turned to the case normal, i.e. the case angle a
  // (ccw in x-y) is a turn of -a about MuJoCo's +y (mujoco_frame.cpp)
  const double phi = -s.ground_angle_rad;
  const std::string quat = num(std::cos(0.5 * phi)) + " 0 " + num(std::sin(0.5 * phi)) + " 0";
  const std::string common = R"( contype="0" conaffinity="0" condim="1")";
  const std::string i = num(s.inertia_kgm2);
  std::string friction;
  int condim = 1;
  if (s.friction > 0.0) {
    condim = 3;
    friction = " friction=\"" + num(s.friction) + " " + num(s.friction) + " 0.005 0.0001 0.0001\"";
  }
  // direct solref (negative): K and c per unit effective mass
  const double m_eff = s.mass_kg;
  const std::string solref = num(-s.stiffness_n_per_m / m_eff) + " " + num(-s.damping_ns_per_m / m_eff);
  std::string x;
  x += "<mujoco model=\"planarbench\">\n";
  x += "<compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
  x += "<option timestep=\"" + num(kDt) +
       "\" integrator=\"Euler\" solver=\"Newton\" iterations=\"100\" tolerance=\"1e-08\" "
       "gravity=\"0 0 " + num(-kGravity) +
       "\" cone=\"pyramidal\" impratio=\"1\" noslip_iterations=\"0\"/>\n";
  x += "<worldbody>\n";
  x += "<geom name=\"geom0\" pos=\"0 0 0\" quat=\"" + quat + "\"" + common +
       " type=\"plane\" size=\"" + num(0.5 * s.extent_m) + " 1 1\"/>\n";
  x += "<body name=\"body1\" pos=\"" + num(s.x0_m) + " 0 " + num(s.y0_m) + "\">";
  x += "<joint name=\"body1_x\" type=\"slide\" axis=\"1 0 0\"/>";
  x += "<joint name=\"body1_z\" type=\"slide\" axis=\"0 0 1\"/>";
  x += "<joint name=\"body1_hinge\" type=\"hinge\" axis=\"0 1 0\"/>";
  x += "<inertial pos=\"0 0 0\" mass=\"" + num(s.mass_kg) + "\" diaginertia=\"" + i + " " + i +
       " " + i + "\"/>";
  x += "<geom name=\"geom1\" pos=\"0 0 0\" quat=\"1 0 0 0\"" + common + " type=\"sphere\" size=\"" +
       num(s.radius_m) + "\"/>";
  x += "</body>\n</worldbody>\n<contact>\n";
  x += "<pair name=\"pair0\" geom1=\"geom0\" geom2=\"geom1\" condim=\"" + std::to_string(condim) +
       "\"" + friction + " solref=\"" + solref +
       "\" solimp=\"0.9999 0.9999 0.001 0.5 2\" margin=\"" + num(kMargin) + "\" gap=\"" +
       num(kMargin) + "\"/>\n";
  x += "</contact>\n</mujoco>\n";
  return x;
}

mjModel* load(const std::string& xml) {
  const char* file = "bare.xml";
  auto vfs = std::make_unique<mjVFS>();  // too large for the stack
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(xml.size())) != 0) return nullptr;
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), file)], xml.data(), xml.size());
  char error[1024] = "";
  mjModel* m = mj_loadXML(file, vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (!m) std::fprintf(stderr, "mj_loadXML: %s\n", error);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  long steps = 0;
  const Scene* s = parse_command_line(argc, argv, steps);
  if (s == nullptr) return 2;

  mjModel* m = load(mjcf(*s));
  if (!m) return 1;
  mjData* d = mj_makeData(m);
  // qpos = qvel = 0: the disk at rest at its body position, angle 0
  mj_resetData(m, d);
  const int jx = mj_name2id(m, mjOBJ_JOINT, "body1_x");
  const int jz = mj_name2id(m, mjOBJ_JOINT, "body1_z");
  const int jh = mj_name2id(m, mjOBJ_JOINT, "body1_hinge");
  const int qx = m->jnt_qposadr[jx], qz = m->jnt_qposadr[jz], qh = m->jnt_qposadr[jh];
  const int vx = m->jnt_dofadr[jx], vz = m->jnt_dofadr[jz], vh = m->jnt_dofadr[jh];

  for (long n = 0; n < steps; ++n) {
    mj_step(m, d);
    // centre = body position + slide coordinates; ccw angle = -hinge (mujoco_frame.cpp)
    Sample& o = g_samples[n & 63];
    o.x = s->x0_m + d->qpos[qx];
    o.y = s->y0_m + d->qpos[qz];
    o.angle = -d->qpos[qh];
    o.vx = d->qvel[vx];
    o.vy = d->qvel[vz];
    o.omega = -d->qvel[vh];
  }
  const Sample last = steps > 0 ? g_samples[(steps - 1) & 63] : Sample{s->x0_m, s->y0_m, 0, 0, 0, 0};
  std::printf("mujoco %s steps=%ld x=%.17g y=%.17g\n", s->name, steps, last.x, last.y);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
