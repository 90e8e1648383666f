#include "box2d_settings.hpp"

namespace pb::internal::box2d {

void bind_settings(SettingsBinder& binder, Box2dSettings* s) {
  binder
      .real("dt", &s->dt_s, 1e-7, 0.1,
            "s, fixed step of b2World::Step (default 1e-4: the output grid)")
      .integer("velocity_iterations", &s->velocity_iterations, 1, 10000,
               "velocity iterations per step (default 8, the Box2D manual's)")
      .integer("position_iterations", &s->position_iterations, 0, 10000,
               "position iterations per step (Box2D manual: 3)")
      .real("restitution_threshold", &s->restitution_threshold_mps, 0.0, 100.0,
            "m/s, approach speed below which contacts do not bounce; 0 = auto, max(0.02, 2 |g| dt)")
      .boolean("warm_starting", &s->warm_starting, "b2World::SetWarmStarting (default true)")
      .boolean("continuous_physics", &s->continuous_physics,
               "b2World::SetContinuousPhysics, time-of-impact sub-steps (default true)")
      .choice("mode", &s->mode, {"native", "inject"},
              "native = Box2D's collision and rigid contact, restitution set in PreSolve from "
              "the law at the contact's onset (default); inject = the case's force law applied "
              "with b2Body::ApplyForce at the adapter's contact geometry")
      .choice("reported_force", &s->reported_force, {"auto", "step", "interval"},
              "contacts table force: step = the last step's impulse / dt; interval = the "
              "impulse over the output interval / its length (the mean force); auto = interval "
              "for cases with contact groups, step otherwise (default)");
}

}  // namespace pb::internal::box2d
