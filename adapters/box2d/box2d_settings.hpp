// Settings of the Box2D adapter (engine "box2d"), bound to keys through
// pb::SettingsBinder: "box2d.<key>" or the shared "<key>" (e.g. "dt").
#pragma once

#include <string>

#include "planarbench/settings.hpp"

namespace pb::internal::box2d {

// m/s, the floor of the automatic restitution threshold (see below)
constexpr double kFloatNoiseThreshold_mps = 0.02;

struct Box2dSettings {
  // s, fixed step of b2World::Step. Box2D is tuned for 1/60 s; 1e-4 s is the
  // common output grid of every case, so the one-step contact of a rigid
  // engine is resolved to 0.1 ms (the dual pendulum's first impact must land
  // within 1 ms), and the float state of a 1 m body still changes by far more
  // than its rounding each step (|v| dt / |x| ~ 1e-4 >> 6e-8).
  double dt_s = 1e-4;
  // b2World::Step velocity iterations (Box2D manual: 8). Measured on the dual
  // pendulum (one contact between two revolute joints): 8 to 1000 iterations
  // change the post-impact state by < 1e-5 (m/s, rad/s), so the manual's value
  // stays.
  int velocity_iterations = 8;
  // b2World::Step position iterations (Box2D manual: 3)
  int position_iterations = 3;
  // m/s, restitution velocity threshold of every contact (b2FixtureDef::
  // restitutionThreshold, Box2D default 1 m/s): slower impacts do not bounce.
  // 0 = automatic: max(kFloatNoiseThreshold_mps, 2 |g| dt). 2 |g| dt is above
  // the approach speed gravity gives a resting contact in one step; the floor
  // is above the speed of a resting body re-touching after a float-noise gap
  // (8 ulp at 10 m, 1e-5 m: sqrt(2 g 1e-5) = 0.014 m/s). Measured on the
  // sliding case: with 2e-3 m/s the resting disk micro-bounces on float noise
  // (peak 124 N against its 6.9 N load); from 5e-3 m/s up it does not.
  double restitution_threshold_mps = 0.0;
  bool warm_starting = true;       // b2World::SetWarmStarting (Box2D default on)
  bool continuous_physics = true;  // b2World::SetContinuousPhysics, TOI (default on)
  // "native": Box2D's collision and rigid contact, the law mapped to a
  // restitution in PreSolve at each onset (as MuJoCo's and ODE's "native");
  // "inject": contact pairs do not collide in Box2D, the adapter applies the
  // case's force law itself (b2Body::ApplyForce) from closed-form geometry.
  std::string mode = "native";
  // The contact force the contacts table gets (engine mode; the episodes
  // always take each step's): "step" = the last step's impulse / dt, a
  // sample of a rigid solver's one-step spikes (impulse / 1e-4 s: up to
  // 2.6 kN on pile_100's 0.1 kg disks); "interval" = the pair's impulse
  // over the output interval / its length, the mean force there, so the
  // table integrates to the impulses whatever the decimation (equal to
  // "step" when dt is the interval); "auto" = "interval" for a case with
  // contact groups (scenes, output 1e-3 s at dt 1e-4 s), "step" for one of
  // declared pairs only (their pinned results: dual_pendulum runs dt = 1e-5
  // on a 1e-4 grid).
  std::string reported_force = "auto";
};

// Binds every member of `s` to `binder` (keys documented with unit and range).
void bind_settings(SettingsBinder& binder, Box2dSettings* s);

}  // namespace pb::internal::box2d
