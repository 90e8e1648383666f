// Small cases built in code for the Box2D adapter's tests (the case files in
// cases/ are used by the acceptance tests of box2d_engine_test.cpp).
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "planarbench/case.hpp"
#include "planarbench/settings.hpp"

namespace pb::box2d_test {

inline Body ground_body(double angle_rad = 0.0, const Vec2& position = Vec2::Zero()) {
  Body g;
  g.name = "ground";
  g.fixed = true;
  g.shape = HalfPlane{40.0};
  g.position_m = position;
  g.angle_rad = angle_rad;
  return g;
}

// uniform disk: I = m R^2 / 2
inline Body disk_body(const std::string& name, double radius, double mass, const Vec2& position) {
  Body b;
  b.name = name;
  b.shape = Circle{radius};
  b.mass_kg = mass;
  b.inertia_kgm2 = 0.5 * mass * radius * radius;
  b.position_m = position;
  return b;
}

// uniform ellipse: I = m (a^2 + b^2) / 4
inline Body ellipse_body(const std::string& name, double a, double b, double mass,
                         const Vec2& position, double angle_rad) {
  Body e;
  e.name = name;
  e.shape = Ellipse{a, b};
  e.mass_kg = mass;
  e.inertia_kgm2 = 0.25 * mass * (a * a + b * b);
  e.position_m = position;
  e.angle_rad = angle_rad;
  return e;
}

inline ContactPair kv_pair(int a, int b, double k = 1e4, double c = 10.0) {
  ContactPair p;
  p.name = "pair";
  p.body_a = a;
  p.body_b = b;
  p.law = KelvinVoigt{k, c, 0.0};
  return p;
}

// a case with the given bodies, standard gravity and a 1e-4 s grid
inline Case make_case(const std::string& name, double duration_s) {
  Case c;
  c.name = name;
  c.duration_s = duration_s;
  c.output_interval_s = 1e-4;
  c.gravity_mps2 = Vec2(0.0, -9.8066);
  return c;
}

inline SettingsOverrides overrides(std::initializer_list<std::pair<const char*, const char*>> kv) {
  SettingsOverrides o;
  for (const auto& [k, v] : kv) o.set(k, v, SettingSource{"test", 0});
  return o;
}

// the clamped Kelvin-Voigt restitution without gravity (ENGINES.md):
// e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)), zeta = c / (2 sqrt(k m))
inline double clamped_kv_restitution(double k, double c, double m) {
  const double zeta = c / (2.0 * std::sqrt(k * m));
  return std::exp(-zeta * (std::numbers::pi - 2.0 * std::asin(zeta)) /
                  std::sqrt(1.0 - zeta * zeta));
}

}  // namespace pb::box2d_test
