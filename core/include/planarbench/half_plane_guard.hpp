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
#include "planarbench/contact_pairs.hpp"
#include "planarbench/engine.hpp"

namespace pb {

// The moving bodies of a case that may touch a half-plane (a declared pair
// or a contact group: in a scene every body of the ground's group, not only
// the one resting on it) and the check that none is inside it.
class HalfPlaneGuard {
 public:
  explicit HalfPlaneGuard(const Case& c) : case_(&c) {
    const ContactPairs rules(c);
    for (std::size_t p = 0; p < c.bodies.size(); ++p) {
      if (!std::holds_alternative<HalfPlane>(c.bodies[p].shape)) continue;
      for (std::size_t b = 0; b < c.bodies.size(); ++b) {
        if (c.bodies[b].fixed) continue;
        const std::string rule = rules.rule_name(static_cast<int>(p), static_cast<int>(b));
        if (!rule.empty()) watched_.push_back(Watched{static_cast<int>(p), static_cast<int>(b), rule});
      }
    }
  }

  // "" while every watched body has its centre of mass on the half-plane's
  // open side (or on its surface); else what is where
  [[nodiscard]] std::string check(const std::vector<BodyState>& states) const {
    for (const Watched& w : watched_) {
      const auto pi = static_cast<std::size_t>(w.plane);
      const auto bi = static_cast<std::size_t>(w.body);
      if (pi >= states.size() || bi >= states.size()) continue;
      const BodyState& plane = states[pi];
      // outward normal: +y turned by the half-plane's angle (SPEC §2)
      const Vec2 n(-std::sin(plane.angle_rad), std::cos(plane.angle_rad));
      const double height = (states[bi].position_m - plane.position_m).dot(n);
      if (height < 0.0) {
        return fmt::format(
            "the centre of mass of body '{}' is {:.6g} m below half-plane '{}' (contact '{}'): "
            "a body cannot be inside one it touches (a blow-up, or the engine's finite ground "
            "left behind)",
            case_->bodies[bi].name, -height, case_->bodies[pi].name, w.rule);
      }
    }
    return "";
  }

 private:
  struct Watched {
    int plane = -1;
    int body = -1;
    std::string rule;
  };
  const Case* case_;
  std::vector<Watched> watched_;
};

}  // namespace pb
