// A run must not end inside a body it touches (issue 35): the runner applies
// this on every output sample of every engine, beside the energy budget
// (energy_budget.hpp). A half-plane is solid below its surface without end
// (SPEC §2); a body's centre of mass is the mass-weighted mean of its
// material points, each of which a contact can press at most a law's depth
// below the surface, so a centre below the surface is a body driven through
// the half-plane: a blow-up, or an engine's finite stand-in for the
// half-plane left behind (Box2D's ground box: disk_backspin at 1e4 rad/s and
// mu 10 rolled off its end and fell, centre 2.46 m below the ground, "ok").
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb {

// "" while every moving body of a pair with a half-plane has its centre of
// mass on the half-plane's open side (or on its surface); else what is where
[[nodiscard]] inline std::string body_inside_half_plane(const Case& c,
                                                        const std::vector<BodyState>& states) {
  for (const ContactPair& p : c.contacts) {
    for (const auto& [plane_i, body_i] : {std::pair{p.body_a, p.body_b}, std::pair{p.body_b, p.body_a}}) {
      const auto pi = static_cast<std::size_t>(plane_i);
      const auto bi = static_cast<std::size_t>(body_i);
      if (pi >= c.bodies.size() || bi >= c.bodies.size() || pi >= states.size() ||
          bi >= states.size()) {
        continue;
      }
      if (!std::holds_alternative<HalfPlane>(c.bodies[pi].shape) || c.bodies[bi].fixed) continue;
      const BodyState& plane = states[pi];
      // outward normal: +y turned by the half-plane's angle (SPEC §2)
      const Vec2 n(-std::sin(plane.angle_rad), std::cos(plane.angle_rad));
      const double height = (states[bi].position_m - plane.position_m).dot(n);
      if (height < 0.0) {
        return fmt::format(
            "the centre of mass of body '{}' is {:.6g} m below half-plane '{}' (contact '{}'): "
            "a body cannot be inside one it touches (a blow-up, or the engine's finite ground "
            "left behind)",
            c.bodies[bi].name, -height, c.bodies[pi].name, p.name);
      }
    }
  }
  return "";
}

}  // namespace pb
