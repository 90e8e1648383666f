#include "closed_form_match.hpp"

#include "disk_row.hpp"
#include "resting_stack.hpp"

#include <fmt/format.h>

#include <cmath>
#include <variant>
#include <vector>

#include "body_on_line.hpp"
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

// the one plain Kelvin-Voigt law of the case's one contact pair, or why not
std::string plain_kelvin_voigt_reason(const Case& c) {
  if (c.contacts.size() != 1) {
    return fmt::format("{} contact pairs: the closed form has exactly one", c.contacts.size());
  }
  const ContactPair& p = c.contacts[0];
  if (!valid_body(c, p.body_a) || !valid_body(c, p.body_b)) {
    return fmt::format("contact pair '{}' names a body that does not exist", p.name);
  }
  const auto* kv = std::get_if<KelvinVoigt>(&p.law);
  if (kv == nullptr) {
    return fmt::format(
        "the contact law is {}: only Kelvin-Voigt (linear in delta and delta_dot) has a closed "
        "form here",
        contact_law_name(p.law));
  }
  if (kv->damping_depth_m > 0.0) return "the damping ramp (damping_depth_m > 0) has no closed form";
  if (!(kv->stiffness_n_per_m > 0.0) || !(kv->damping_ns_per_m >= 0.0)) {
    return "the closed form needs stiffness > 0 and damping >= 0";
  }
  return {};
}

// two free disks on the line of their centres, moving along it, one plain
// Kelvin-Voigt pair between them
ClosedFormMatch match_two_disks(const Case& c, const std::vector<int>& moving) {
  const Body& a = body(c, moving[0]);
  const Body& b = body(c, moving[1]);
  for (const Body* d : {&a, &b}) {
    if (!std::holds_alternative<Circle>(d->shape)) {
      return none(fmt::format("two moving bodies: the head-on closed form needs two circles, "
                              "'{}' is a {}",
                              d->name, shape_type_name(d->shape)));
    }
    if (!(d->mass_kg > 0.0)) return none(fmt::format("the disk '{}' needs a mass > 0", d->name));
  }
  if (c.bodies.size() != 2) {
    return none(fmt::format("{} bodies: the head-on closed form has the two disks only",
                            c.bodies.size()));
  }
  if (auto why = plain_kelvin_voigt_reason(c); !why.empty()) return none(why);
  if (c.contacts[0].has_friction()) {
    return none("two moving bodies with friction: the head-on closed form is frictionless");
  }
  const Vec2 dx = b.position_m - a.position_m;
  const Vec2 dv = b.velocity_mps - a.velocity_mps;
  // head on: the relative velocity along the line of centres (cross product
  // within the rounding of the stated numbers, 1e-12 relative)
  const double cross = dx.x() * dv.y() - dx.y() * dv.x();
  if (!(dx.norm() > 0.0) || std::abs(cross) > 1e-12 * dx.norm() * dv.norm()) {
    return none(
        "the two disks do not move along the line of their centres: the head-on closed form "
        "needs a relative velocity parallel to it");
  }
  ClosedFormMatch m;
  m.kind = ClosedFormKind::two_disks_head_on;
  m.disk = moving[0];
  m.line = moving[1];
  m.pair = 0;
  return m;
}

// one moving body translating on one fixed half-plane (a disk, or a polygon
// pressed flat and centred: translating_support), one plain Kelvin-Voigt pair;
// or two free disks head on
ClosedFormMatch match_analytic(const Case& c) {
  if (!c.joints.empty()) {
    return none("the analytic closed forms have no joints, the case has revolute joints");
  }
  std::vector<int> moving;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    if (!c.bodies[i].fixed) moving.push_back(static_cast<int>(i));
  }
  if (moving.size() == 2) return match_two_disks(c, moving);
  if (moving.size() != 1) {
    return none(fmt::format(
        "{} moving bodies: the closed forms have one body on a line or two disks head on",
        moving.size()));
  }
  const Body& d = body(c, moving[0]);
  if (!(d.mass_kg > 0.0)) return none(fmt::format("the body '{}' needs a mass > 0", d.name));
  if (auto why = plain_kelvin_voigt_reason(c); !why.empty()) return none(why);
  const ContactPair& p = c.contacts[0];
  const int other = p.body_a == moving[0] ? p.body_b : p.body_a;
  if ((p.body_a != moving[0] && p.body_b != moving[0]) || other == moving[0]) {
    return none(
        fmt::format("contact pair '{}' does not join the body '{}' to the ground", p.name, d.name));
  }
  const Body& l = body(c, other);
  if (!std::holds_alternative<HalfPlane>(l.shape)) {
    return none(fmt::format("the body touches '{}', a {}: the closed form needs a half-plane",
                            l.name, shape_type_name(l.shape)));
  }
  const Vec2 n(-std::sin(l.angle_rad), std::cos(l.angle_rad));
  std::string why;
  const auto support = translating_support(d, n, &why, static_level_m(c, moving[0], other, 0));
  if (!support) return none(why);
  // issue 49: a 0.1 x 0.3 m block on its short face on 22 deg (tan 22 > w/h)
  // was predicted to hold, so every engine's correct tip breached
  if (const std::string tip = tipping_reason(c, d, p, n, *support); !tip.empty()) return none(tip);
  ClosedFormMatch m;
  m.kind = ClosedFormKind::body_on_line;
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

// a scene's closed forms: a resting stack, a row of disks (the reasons of both
// when neither holds)
ClosedFormMatch match_scene(const Case& c) {
  ClosedFormMatch m;
  const std::string stack = RestingStack::why_not(c);
  if (stack.empty()) {
    m.kind = ClosedFormKind::resting_stack;
    return m;
  }
  const std::string row = DiskRow::why_not(c);
  if (row.empty()) {
    m.kind = ClosedFormKind::disk_row;
    return m;
  }
  return none(fmt::format("a scene with a closed form is a resting stack ({}) or a row of disks "
                          "without gravity ({})",
                          stack, row));
}

ClosedFormMatch match_closed_form(const Case& c) {
  switch (c.truth) {
    case TruthKind::none:
      return none("the case states truth = none: it has no closed form");
    case TruthKind::analytic:
      return c.generated.empty() && !c.has_contact_groups() ? match_analytic(c) : match_scene(c);
    case TruthKind::converged:
      return none("the case states truth = converged: it has no closed form");
    case TruthKind::analytic_until_first_contact:
      return match_pendulums(c);
  }
  return none("unknown truth kind");
}

}  // namespace pb::internal
