#include "box2d_frame.hpp"

namespace pb::internal::box2d {

b2Vec2 to_b2(const Vec2& v) {
  return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y()));
}

Vec2 from_b2(const b2Vec2& v) {
  return Vec2(static_cast<double>(v.x), static_cast<double>(v.y));
}

b2Transform to_b2_transform(const Vec2& position_m, double angle_rad) {
  return b2Transform(to_b2(position_m), b2Rot(static_cast<float>(angle_rad)));
}

b2BodyDef body_def(const Body& body) {
  b2BodyDef def;
  def.type = body.fixed ? b2_staticBody : b2_dynamicBody;
  def.position = to_b2(body.position_m);
  def.angle = static_cast<float>(body.angle_rad);
  if (!body.fixed) {
    def.linearVelocity = to_b2(body.velocity_mps);
    def.angularVelocity = static_cast<float>(body.angular_velocity_radps);
  }
  // measurements need every body awake for the whole run
  def.allowSleep = false;
  def.awake = true;
  def.bullet = false;
  return def;
}

BodyState body_state(const b2Body& body) {
  BodyState s;
  s.position_m = from_b2(body.GetWorldCenter());
  s.angle_rad = static_cast<double>(body.GetAngle());
  s.velocity_mps = from_b2(body.GetLinearVelocity());
  s.angular_velocity_radps = static_cast<double>(body.GetAngularVelocity());
  return s;
}

}  // namespace pb::internal::box2d
