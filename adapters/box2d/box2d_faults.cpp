#include "box2d_faults.hpp"

#include <box2d/b2_common.h>
#include <fmt/format.h>

#include <cfloat>
#include <cmath>

#include "box2d_frame.hpp"

namespace pb::internal::box2d {

namespace {

// m and rad per step, Box2D's clamps (b2_common.h)
constexpr double kMaxTranslation_m = static_cast<double>(b2_maxTranslation);
constexpr double kMaxRotation_rad = static_cast<double>(b2_maxRotation);
// relative: the clamp leaves |v| h = 2 m up to a few float ulps (1e-7 each)
constexpr double kAtClamp = 1.0 - 1e-5;

// a positive value that stays a normal float (not 0, not denormal, not inf)
bool normal_float(double x) {
  return x >= static_cast<double>(FLT_MIN) && x <= static_cast<double>(FLT_MAX);
}

// |v| without overflow: Eigen's norm() squares first, so a finite speed of
// 1e308 m/s came out as inf (issue 24); hypot is finite wherever |v| is
double speed(const Vec2& v) { return std::hypot(v.x(), v.y()); }

// how a message says a body's speed: the number, or, beyond the largest
// double, the velocity as given
std::string speed_text(const Vec2& v) {
  const double s = speed(v);
  if (std::isfinite(s)) return fmt::format("speed {:.4g} m/s", s);
  return fmt::format("velocity ({:.4g}, {:.4g}) m/s, a speed beyond {:.4g} m/s,", v.x(), v.y(),
                     DBL_MAX);
}

}  // namespace

std::string refused_input_reason(const Case& c, double dt_s) {
  // gravity alone must not reach the clamp from rest in one step: |g| h^2 < 2 m
  const double g = c.gravity_mps2.norm();
  if (!(g * dt_s * dt_s < kMaxTranslation_m)) {
    return fmt::format(
        "gravity {:.4g} m/s^2 moves a body from rest {:.4g} m in one step of {} s, beyond "
        "Box2D's b2_maxTranslation = {} m per step: use a smaller box2d.dt",
        g, g * dt_s * dt_s, dt_s, kMaxTranslation_m);
  }
  for (const Body& b : c.bodies) {
    const bool finite = b.position_m.allFinite() && std::isfinite(b.angle_rad) &&
                        b.velocity_mps.allFinite() && std::isfinite(b.angular_velocity_radps);
    if (!finite) return fmt::format("body '{}' has a non-finite initial state", b.name);
    if (b.fixed) continue;
    if (!normal_float(b.mass_kg) || !normal_float(b.inertia_kgm2)) {
      return fmt::format(
          "moving body '{}': mass {:g} kg and inertia {:g} kg m^2 must be normal floats, in "
          "[{:g}, {:g}] (Box2D computes in float: b2Body::SetMassData asserts I > 0, which an "
          "overflow to inf fails, and below that range float loses precision down to 0, where "
          "Box2D takes 1 kg)",
          b.name, b.mass_kg, b.inertia_kgm2, static_cast<double>(FLT_MIN),
          static_cast<double>(FLT_MAX));
    }
    if (!(speed(b.velocity_mps) * dt_s < kMaxTranslation_m * kAtClamp)) {
      const double step_m = speed(b.velocity_mps) * dt_s;
      return fmt::format(
          "moving body '{}': its initial {} covers {} m in one step of {} s; Box2D clamps a "
          "step at b2_maxTranslation = {} m: use a smaller box2d.dt",
          b.name, speed_text(b.velocity_mps),
          std::isfinite(step_m) ? fmt::format("{:.4g}", step_m) : fmt::format("more than {:.4g}", DBL_MAX),
          dt_s, kMaxTranslation_m);
    }
    if (!(std::abs(b.angular_velocity_radps) * dt_s < kMaxRotation_rad * kAtClamp)) {
      return fmt::format(
          "moving body '{}': its initial spin {:.4g} rad/s turns it {:.4g} rad in one step of {} "
          "s; Box2D clamps a step at b2_maxRotation = pi/2: use a smaller box2d.dt",
          b.name, std::abs(b.angular_velocity_radps), std::abs(b.angular_velocity_radps) * dt_s,
          dt_s);
    }
  }
  return "";
}

std::string clamped_velocity_reason(const BodyState& s, double dt_s) {
  const double step_m = speed(s.velocity_mps) * dt_s;
  const double turn_rad = std::abs(s.angular_velocity_radps) * dt_s;
  if (step_m >= kMaxTranslation_m * kAtClamp) {
    return fmt::format(
        "Box2D clamped its translation to b2_maxTranslation = {} m per step (|v| = {:.6g} m/s at "
        "dt = {} s): a runaway, or a speed this step cannot carry (use a smaller box2d.dt)",
        kMaxTranslation_m, speed(s.velocity_mps), dt_s);
  }
  if (turn_rad >= kMaxRotation_rad * kAtClamp) {
    return fmt::format(
        "Box2D clamped its rotation to b2_maxRotation = pi/2 per step (|omega| = {:.6g} rad/s at "
        "dt = {} s): a runaway, or a spin this step cannot carry (use a smaller box2d.dt)",
        std::abs(s.angular_velocity_radps), dt_s);
  }
  return "";
}

std::string injected_force_reason(const b2Body& body, const Body& case_body,
                                  const Vec2& gravity_mps2, const Vec2& force_n, double torque_nm,
                                  double dt_s) {
  const BodyState s = body_state(body);
  // b2Island::Solve: v += h (gravityScale g + invMass f), w += h invI torque
  const Vec2 v = s.velocity_mps + dt_s * (gravity_mps2 + force_n / case_body.mass_kg);
  const double w = s.angular_velocity_radps + dt_s * torque_nm / case_body.inertia_kgm2;
  const bool moves_too_far = !(speed(v) * dt_s < kMaxTranslation_m * kAtClamp);
  const bool turns_too_far = !(std::abs(w) * dt_s < kMaxRotation_rad * kAtClamp);
  if (!moves_too_far && !turns_too_far) return "";
  return fmt::format(
      "the injected contact force |F| = {:.4g} N (torque {:.4g} N m) would take it to |v| = "
      "{:.4g} m/s, |omega| = {:.4g} rad/s: {:.4g} m and {:.4g} rad in one step of {} s, beyond "
      "Box2D's clamps b2_maxTranslation = {} m and b2_maxRotation = pi/2 per step; the explicit "
      "force law is running away (too stiff for this step: use a smaller box2d.dt)",
      speed(force_n), torque_nm, speed(v), std::abs(w), speed(v) * dt_s, std::abs(w) * dt_s, dt_s,
      kMaxTranslation_m);
}

}  // namespace pb::internal::box2d
