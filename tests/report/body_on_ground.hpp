// A constructed case for the contact-validity tests: one body on a fixed
// half-plane (body 0, at the origin, normal +y) through one pair (body 1 its
// body_b), output every 1e-3 s for 0.1 s.
#pragma once

#include <string>

#include "planarbench/case.hpp"

namespace pb::test {

inline Case body_on_ground(const std::string& case_name, const std::string& body_name,
                           const Shape& shape, double friction, const ContactLaw& law) {
  Case c;
  c.name = case_name;
  c.duration_s = 0.1;
  c.output_interval_s = 1e-3;
  Body ground;
  ground.name = "ground";
  ground.shape = HalfPlane{};
  ground.fixed = true;
  Body body;
  body.name = body_name;
  body.shape = shape;
  body.mass_kg = 1.0;
  c.bodies = {ground, body};
  ContactPair p;
  p.name = "ground_" + body_name;
  p.body_a = 0;
  p.body_b = 1;
  p.law = law;
  p.friction = friction;
  c.contacts = {p};
  return c;
}

}  // namespace pb::test
