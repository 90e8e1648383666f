// A concave star dropped in the fault tests of geometry memory (issue 24):
// `points` outline points alternating between radii 0.5 m (tips) and 0.35 m
// (notches), each tip a convex piece of the decomposition. On level ground,
// or, with `on_star`, on a fixed copy of itself (star on star: pieces x
// pieces geom pairs). It falls 0.1 m: the first touch at t = 0.143 s.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "planarbench/case_loader.hpp"

namespace pb::faults_test {

inline std::string star_points(int points) {
  std::string pts;
  for (int i = 0; i < points; ++i) {
    const double a = 2.0 * std::numbers::pi * i / points;
    const double r = i % 2 == 0 ? 0.5 : 0.35;  // m: tips and notches
    pts += fmt::format("[{:.12f}, {:.12f}],", r * std::cos(a), r * std::sin(a));
  }
  return pts;
}

inline Case star_case(int points, bool on_star) {
  const std::string below =
      on_star ? fmt::format(R"(shape = {{ type = "polygon", points = [{}] }})", star_points(points))
              : std::string(R"(shape = { type = "halfplane", extent = 10.0 })");
  const std::string text = fmt::format(R"(
[case]
description = "a {}-point concave star dropped on {}"
duration = 0.3
output_interval = 1e-3
truth = "none"
[[bodies]]
name = "below"
fixed = true
{}
position = [0.0, 0.0]
[[bodies]]
name = "star"
shape = {{ type = "polygon", points = [{}] }}
mass = 1.0
inertia = "shape"
position = [0.0, {}]
[[contacts]]
name = "below_star"
bodies = ["below", "star"]
law = "kelvin_voigt"
stiffness = 1e4
damping = 10.0
)",
                                       points, on_star ? "a fixed copy of itself" : "level ground",
                                       below, star_points(points), on_star ? 1.1 : 0.6);
  return parse_case(text, "star.toml", "star", {});
}

}  // namespace pb::faults_test
