// The canonical cases of SPEC §2 built directly as pb::Case from the numbers
// of cases/*.toml (the tests do not depend on the TOML loader).
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

#include "planarbench/case.hpp"

namespace pb::testing {

// falling_ball: disk R = 0.5 m, 1 kg, I = m R^2 / 2, from rest at (2, 2);
// ground: the line through the origin declining at 30 degrees; Kelvin-Voigt
// K = 1e4 N/m, c = 10 N s/m; 2.5 s.
inline Case falling_ball() {
  Case c;
  c.name = "falling_ball";
  c.truth = TruthKind::analytic;
  c.duration_s = 2.5;
  c.output_interval_s = 1e-4;
  Body ground;
  ground.name = "ground";
  ground.shape = HalfPlane{40.0};
  ground.fixed = true;
  ground.angle_rad = -30.0 * std::numbers::pi / 180.0;
  Body ball;
  ball.name = "ball";
  ball.shape = Circle{0.5};
  ball.mass_kg = 1.0;
  ball.inertia_kgm2 = 0.125;
  ball.position_m = Vec2(2.0, 2.0);
  c.bodies = {ground, ball};
  ContactPair p;
  p.name = "ground_ball";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  return c;
}

// sliding: disk R = 0.25 m, 1 kg, at rest touching the line through the
// origin declining at 45 degrees, centre (R sin45, R cos45) as the case file
// writes it; Kelvin-Voigt K = 1e4 N/m, c = 10 N s/m; 1 s.
inline Case sliding() {
  Case c = falling_ball();
  c.name = "sliding";
  c.duration_s = 1.0;
  c.bodies[0].shape = HalfPlane{20.0};
  c.bodies[0].angle_rad = -45.0 * std::numbers::pi / 180.0;
  c.bodies[1].shape = Circle{0.25};
  c.bodies[1].inertia_kgm2 = 0.5 * 0.25 * 0.25;
  c.bodies[1].position_m = Vec2(0.17677669529663688, 0.17677669529663688);
  return c;
}

// dual_pendulum: ellipse (a = 0.7071 m, b = 0.25 m, 1 kg, I = m (a^2 + b^2)/4)
// hung from its tip at the origin, centre a (-cos45, -sin45), body angle 45 degrees, released
// from rest; disk (R = 0.5 m, 1 kg, I = m R^2 / 2) hanging at rest from
// (0.75, 0), centre (0.75, -0.7071); Lankarani-Nikravesh pair; 2 s.
inline Case dual_pendulum() {
  Case c;
  c.name = "dual_pendulum";
  c.truth = TruthKind::analytic_until_first_contact;
  c.duration_s = 2.0;
  c.output_interval_s = 1e-4;
  Body e;
  e.name = "ellipse";
  e.shape = Ellipse{0.7071, 0.25};
  e.mass_kg = 1.0;
  e.inertia_kgm2 = (0.7071 * 0.7071 + 0.25 * 0.25) / 4.0;
  e.position_m = 0.7071 * Vec2(-std::cos(std::numbers::pi / 4.0), -std::sin(std::numbers::pi / 4.0));
  e.angle_rad = std::numbers::pi / 4.0;
  Body d;
  d.name = "disk";
  d.shape = Circle{0.5};
  d.mass_kg = 1.0;
  d.inertia_kgm2 = 0.125;
  d.position_m = Vec2(0.75, -0.7071);
  c.bodies = {e, d};
  RevoluteJoint je;
  je.name = "ellipse_pivot";
  je.body = 0;
  je.anchor_world_m = Vec2::Zero();
  // the pivot in the body frame, as the case loader derives it at t = 0:
  // R(-theta0) (anchor - position), the ellipse's tip (a, 0)
  je.anchor_local_m = Vec2(0.7071, 0.0);
  RevoluteJoint jd;
  jd.name = "disk_pivot";
  jd.body = 1;
  jd.anchor_world_m = Vec2(0.75, 0.0);
  jd.anchor_local_m = Vec2(0.0, 0.7071);
  c.joints = {je, jd};
  ContactPair p;
  p.name = "ellipse_disk";
  p.body_a = 0;
  p.body_b = 1;
  p.law = LankaraniNikravesh{1.0242e10, 1.5, 0.7, std::nullopt, {}};
  c.contacts = {p};
  return c;
}

}  // namespace pb::testing
