// Starting states no engine can resolve (issue 24): a body of a contact pair
// whose centre lies inside the other body of the pair. From there the
// direction out is undefined (coincident centres: MuJoCo and ODE push the
// bodies apart along an arbitrary +x) or leads through the body (a ball whose
// centre starts below the ground's surface: Box2D lets it fall through,
// reporting ok). Every engine would run something different, and none of it
// is the case's physics, so the loader refuses the case. A shallow overlap,
// up to the centre (a pre-loaded contact, block_hold), is allowed.
#pragma once

#include <optional>
#include <string>

#include "planarbench/case.hpp"

namespace pb::internal {

// when `point` (world frame) lies strictly inside body `b`'s shape at its
// starting pose: how, in words ("0.3 m below its surface", "inside its
// outline"); nullopt otherwise. A half-plane's inside is below its surface
// line, whatever its extent (engines with an infinite ground see it there).
[[nodiscard]] std::optional<std::string> point_inside_body(const Body& b, const Vec2& point);

}  // namespace pb::internal
