// Small cases built in code for the ODE adapter's tests (the case files in
// cases/ are used by the acceptance tests of ode_engine_test.cpp).
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "planarbench/case.hpp"

namespace pb::ode_test {

inline Body ground_body(double angle_rad = 0.0, Vec2 position = Vec2::Zero()) {
  Body g;
  g.name = "ground";
  g.fixed = true;
  g.shape = HalfPlane{40.0};
  g.position_m = position;
  g.angle_rad = angle_rad;
  return g;
}

// uniform disk: I = m R^2 / 2
inline Body disk_body(const std::string& name, double radius, double mass, Vec2 position) {
  Body b;
  b.name = name;
  b.shape = Circle{radius};
  b.mass_kg = mass;
  b.inertia_kgm2 = 0.5 * mass * radius * radius;
  b.position_m = position;
  return b;
}

// uniform ellipse: I = m (a^2 + b^2) / 4
inline Body ellipse_body(const std::string& name, double a, double b, double mass, Vec2 position,
                         double angle_rad) {
  Body e;
  e.name = name;
  e.shape = Ellipse{a, b};
  e.mass_kg = mass;
  e.inertia_kgm2 = 0.25 * mass * (a * a + b * b);
  e.position_m = position;
  e.angle_rad = angle_rad;
  return e;
}

inline ContactPair pair(int a, int b, ContactLaw law, const std::string& name = "pair") {
  ContactPair p;
  p.name = name;
  p.body_a = a;
  p.body_b = b;
  p.law = law;
  return p;
}

// The ENGINES.md reference drop: a 1 kg disk (R = 0.5 m) whose lowest point
// is `drop_m` above a horizontal line, Kelvin-Voigt k = 1e4 N/m, c = 10 N s/m.
inline Case kelvin_voigt_drop(double drop_m = 1.5, double duration_s = 0.65) {
  Case c;
  c.name = "kv_drop";
  c.duration_s = duration_s;
  c.bodies = {ground_body(), disk_body("ball", 0.5, 1.0, Vec2(0.0, 0.5 + drop_m))};
  c.contacts = {pair(0, 1, KelvinVoigt{1e4, 10.0, 0.0}, "ground_ball")};
  return c;
}

}  // namespace pb::ode_test
