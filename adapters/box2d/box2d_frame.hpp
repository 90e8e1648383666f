// The one mapping between a case's frame and Box2D's. Box2D is natively
// planar with the same axes (x right, y up, angles counter-clockwise positive,
// b2Rot = [cos -sin; sin cos]), so the mapping is the identity up to the
// double -> float conversion; every conversion goes through these functions.
#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_math.h>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::box2d {

// case vector (double, m or m/s) -> Box2D vector (float)
[[nodiscard]] b2Vec2 to_b2(const Vec2& v);
// Box2D vector (float) -> case vector (double)
[[nodiscard]] Vec2 from_b2(const b2Vec2& v);
// pose of a body frame: position of its origin (m) and angle (rad, CCW)
[[nodiscard]] b2Transform to_b2_transform(const Vec2& position_m, double angle_rad);

// b2BodyDef of a case body: static for fixed bodies, else dynamic; pose and
// velocities from the case. The body origin is the case body's centre of
// mass (the adapter sets b2MassData::center = 0). Sleeping off.
[[nodiscard]] b2BodyDef body_def(const Body& body);

// state of a Box2D body in the case frame: centre of mass, angle (continuous,
// b2Body::GetAngle is the unwrapped sweep angle), velocities
[[nodiscard]] BodyState body_state(const b2Body& body);

// (the velocity of a material point: pb::point_velocity, planarbench/engine.hpp)

}  // namespace pb::internal::box2d
