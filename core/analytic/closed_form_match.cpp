#include "closed_form_match.hpp"

#include <fmt/format.h>

#include <cmath>
#include <variant>
#include <vector>

#include "exact_gap.hpp"

namespace pb::internal {

namespace {

ClosedFormMatch none(std::string reason) {
  ClosedFormMatch m;
  m.reason = std::move(reason);
  return m;
}

bool valid_body(const Case& c, int i) {
  return i >= 0 && static_cast<std::size_t>(i) < c.bodies.size();
}

const Body& body(const Case& c, int i) {
  return c.bodies[static_cast<std::size_t>(i)];
}

// exactly one moving disk, one fixed half-plane, one plain Kelvin-Voigt pair
ClosedFormMatch match_disk_on_line(const Case& c) {
  if (!c.joints.empty()) {
    return none("the disk-on-line closed form has no joints, the case has revolute joints");
  }
  std::vector<int> moving;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    if (!c.bodies[i].fixed) moving.push_back(static_cast<int>(i));
  }
  if (moving.size() != 1) {
    return none(
        fmt::format("{} moving bodies: the disk-on-line closed form has exactly one "
                    "(two moving bodies in contact have none here)",
                    moving.size()));
  }
  const Body& d = body(c, moving[0]);
  if (!std::holds_alternative<Circle>(d.shape)) {
    return none(fmt::format("the moving body '{}' is a {}: the closed form needs a circle", d.name,
                            shape_type_name(d.shape)));
  }
  if (!(d.mass_kg > 0.0) || !(std::get<Circle>(d.shape).radius_m > 0.0)) {
    return none(fmt::format("the disk '{}' needs a positive mass and radius", d.name));
  }
  if (c.contacts.size() != 1) {
    return none(fmt::format("{} contact pairs: the disk-on-line closed form has exactly one",
                            c.contacts.size()));
  }
  const ContactPair& p = c.contacts[0];
  if (!valid_body(c, p.body_a) || !valid_body(c, p.body_b)) {
    return none(fmt::format("contact pair '{}' names a body that does not exist", p.name));
  }
  const int other = p.body_a == moving[0] ? p.body_b : p.body_a;
  if ((p.body_a != moving[0] && p.body_b != moving[0]) || other == moving[0]) {
    return none(
        fmt::format("contact pair '{}' does not join the disk '{}' to the ground", p.name, d.name));
  }
  const Body& l = body(c, other);
  if (!std::holds_alternative<HalfPlane>(l.shape)) {
    return none(fmt::format("the disk touches '{}', a {}: the closed form needs a half-plane",
                            l.name, shape_type_name(l.shape)));
  }
  const auto* kv = std::get_if<KelvinVoigt>(&p.law);
  if (kv == nullptr) {
    return none(
        fmt::format("the contact law is {}: only Kelvin-Voigt (linear in delta and "
                    "delta_dot) has a closed form here",
                    contact_law_name(p.law)));
  }
  if (kv->damping_depth_m > 0.0) {
    return none("the damping ramp (damping_depth_m > 0) has no closed form");
  }
  if (!(kv->stiffness_n_per_m > 0.0) || !(kv->damping_ns_per_m >= 0.0)) {
    return none("the closed form needs stiffness > 0 and damping >= 0");
  }
  ClosedFormMatch m;
  m.kind = ClosedFormKind::disk_on_line;
  m.disk = moving[0];
  m.line = other;
  m.pair = 0;
  return m;
}

// every moving body on exactly one revolute joint to the ground; every pair
// of shapes with an exact gap
ClosedFormMatch match_pendulums(const Case& c) {
  std::vector<int> joints_of(c.bodies.size(), 0);
  for (const RevoluteJoint& j : c.joints) {
    if (!valid_body(c, j.body)) {
      return none(fmt::format("joint '{}' names a body that does not exist", j.name));
    }
    if (body(c, j.body).fixed) {
      return none(
          fmt::format("joint '{}' holds the fixed body '{}'", j.name, body(c, j.body).name));
    }
    ++joints_of[static_cast<std::size_t>(j.body)];
  }
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    if (b.fixed) continue;
    if (joints_of[i] != 1) {
      return none(
          fmt::format("the moving body '{}' has {} revolute joints: the pendulum closed "
                      "form needs exactly one",
                      b.name, joints_of[i]));
    }
    if (!(b.mass_kg > 0.0) || !(b.inertia_kgm2 >= 0.0)) {
      return none(fmt::format("the pendulum '{}' needs a positive mass and inertia >= 0", b.name));
    }
  }
  for (const ContactPair& p : c.contacts) {
    if (!valid_body(c, p.body_a) || !valid_body(c, p.body_b)) {
      return none(fmt::format("contact pair '{}' names a body that does not exist", p.name));
    }
    const Shape& a = body(c, p.body_a).shape;
    const Shape& b = body(c, p.body_b).shape;
    if (!exact_gap_supported(a, b)) {
      return none(
          fmt::format("contact pair '{}' ({} - {}): no exact gap for these shapes "
                      "(circle-circle, circle-ellipse, circle or ellipse - half-plane)",
                      p.name, shape_type_name(a), shape_type_name(b)));
    }
  }
  ClosedFormMatch m;
  m.kind = ClosedFormKind::pendulums_until_contact;
  return m;
}

}  // namespace

ClosedFormMatch match_closed_form(const Case& c) {
  switch (c.truth) {
    case TruthKind::none:
      return none("the case states truth = none: it has no closed form");
    case TruthKind::analytic:
      return match_disk_on_line(c);
    case TruthKind::analytic_until_first_contact:
      return match_pendulums(c);
  }
  return none("unknown truth kind");
}

}  // namespace pb::internal
