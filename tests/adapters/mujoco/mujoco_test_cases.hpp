// Small cases built in code for the MuJoCo adapter's tests, each stated in
// prose where it is used. They mirror the physics of cases/*.toml without
// reading them, so that the adapter's tests do not depend on the loader.
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "mujoco_mjcf.hpp"
#include "mujoco_model.hpp"
#include "mujoco_plan.hpp"
#include "planarbench/case.hpp"

namespace pb::test {

inline constexpr double kG = 9.8066;  // m/s^2, SPEC §2

// a fixed half-plane whose surface passes through the origin, its outward
// normal turned by `angle_rad` from +y (the surface declines toward +x for
// negative angles)
inline Body ground(double angle_rad = 0.0) {
  Body g;
  g.name = "ground";
  g.fixed = true;
  g.shape = HalfPlane{20.0};
  g.angle_rad = angle_rad;
  return g;
}

// a free disk of radius r (m), mass m (kg), I = m r^2 / 2, centre at p
inline Body disk(const std::string& name, double r, double m, const Vec2& p) {
  Body b;
  b.name = name;
  b.shape = Circle{r};
  b.mass_kg = m;
  b.inertia_kgm2 = 0.5 * m * r * r;
  b.position_m = p;
  return b;
}

inline ContactPair kelvin_voigt_pair(int a, int b, double k, double c) {
  ContactPair cp;
  cp.name = "contact";
  cp.body_a = a;
  cp.body_b = b;
  cp.law = KelvinVoigt{k, c, 0.0};
  return cp;
}

// one disk over the horizontal ground, Kelvin-Voigt contact ground -> disk
inline Case disk_drop(double height_m, double k = 1e4, double c = 10.0, double duration_s = 0.8) {
  Case cs;
  cs.name = "disk_drop";
  cs.duration_s = duration_s;
  cs.gravity_mps2 = Vec2(0.0, -kG);
  cs.bodies.push_back(disk("disk", 0.5, 1.0, Vec2(0.0, 0.5 + height_m)));
  cs.bodies.push_back(ground());
  cs.contacts.push_back(kelvin_voigt_pair(1, 0, k, c));
  return cs;
}

// SPEC §2 `sliding`: a disk R = 0.25 m, m = 1 kg at rest touching the line
// through the origin declining toward +x at 45 degrees
inline Case sliding(double duration_s = 1.0) {
  Case cs;
  cs.name = "sliding";
  cs.duration_s = duration_s;
  cs.gravity_mps2 = Vec2(0.0, -kG);
  const double r = 0.25;
  const double s45 = std::sin(std::numbers::pi / 4.0);
  cs.bodies.push_back(disk("disk", r, 1.0, Vec2(r * s45, r * s45)));
  cs.bodies.push_back(ground(-std::numbers::pi / 4.0));
  cs.contacts.push_back(kelvin_voigt_pair(1, 0, 1e4, 10.0));
  return cs;
}

// SPEC §2 `dual_pendulum`: an ellipse (a = 0.7071, b = 0.25) hanging from its
// tip at the origin, released at 45 degrees on the -x side (centre at
// (-0.5, -0.5)), and a disk R = 0.5 on a massless rod from (0.75, 0), centre at
// rest at (0.75, -0.7071); m = 1 kg each; Lankarani-Nikravesh contact.
inline Case dual_pendulum(double duration_s = 2.0) {
  Case cs;
  cs.name = "dual_pendulum";
  cs.duration_s = duration_s;
  cs.gravity_mps2 = Vec2(0.0, -kG);
  Body e;
  e.name = "ellipse";
  const double a = 0.7071;
  const double b = 0.25;
  e.shape = Ellipse{a, b};
  e.mass_kg = 1.0;
  e.inertia_kgm2 = (a * a + b * b) / 4.0;
  e.position_m = Vec2(-0.5, -0.5);
  e.angle_rad = std::numbers::pi / 4.0;  // major axis toward the pivot
  cs.bodies.push_back(e);
  cs.bodies.push_back(disk("disk", 0.5, 1.0, Vec2(0.75, -0.7071)));
  RevoluteJoint je;
  je.name = "ellipse_pivot";
  je.body = 0;
  je.anchor_world_m = Vec2(0.0, 0.0);
  je.anchor_local_m = Vec2(a, 0.0);
  RevoluteJoint jd;
  jd.name = "disk_pivot";
  jd.body = 1;
  jd.anchor_world_m = Vec2(0.75, 0.0);
  jd.anchor_local_m = Vec2(0.0, 0.7071);
  cs.joints = {je, jd};
  HertzMaterial mat{210e9, 210e9, 0.33, 0.33, 0.0085, 0.0085};
  ContactPair cp;
  cp.name = "contact";
  cp.body_a = 0;
  cp.body_b = 1;
  cp.law = LankaraniNikravesh{hertz_stiffness(mat), 1.5, 0.7, mat, {}};
  cs.contacts.push_back(cp);
  return cs;
}

// native mode's options for c: every declared pair and contact group with
// the direct solref (0, 0), set by the rule once pressed, and solimp at the
// adapter's default
inline internal::mujoco::MjcfOptions native_options(const Case& c) {
  internal::mujoco::MjcfOptions o;
  internal::mujoco::PairParams p;
  p.solref = {0.0, 0.0};
  p.solimp = {0.9999, 0.9999, 0.001, 0.5, 2.0};
  o.pairs.assign(c.contacts.size(), p);
  o.groups.assign(c.contact_groups.size(), p);
  return o;
}

// the MuJoCo model of c under options o, written from c's plan with the
// given detection margin (m), and the layout of its names
inline internal::mujoco::ModelPtr load_case(const Case& c, const internal::mujoco::MjcfOptions& o,
                                            internal::mujoco::ModelLayout& layout,
                                            double margin_m = 0.0) {
  const internal::mujoco::MujocoPlan plan = internal::mujoco::plan_mujoco(c, margin_m);
  internal::mujoco::ModelPtr m = internal::mujoco::load_mjcf(internal::mujoco::write_mjcf(c, plan, o));
  layout = internal::mujoco::model_layout(m.get(), c, plan);
  return m;
}

}  // namespace pb::test
