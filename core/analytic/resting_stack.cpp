#include "resting_stack.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "planarbench/contact_pairs.hpp"

namespace pb::internal {

namespace {

// m, the farthest reach of a body's shape along world direction d at its angle
double reach(const Body& b, const Vec2& d) {
  const double c = std::cos(b.angle_rad);
  const double s = std::sin(b.angle_rad);
  const Vec2 local(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  if (const auto* circle = std::get_if<Circle>(&b.shape)) return circle->radius_m;
  if (const auto* e = std::get_if<Ellipse>(&b.shape)) {
    return std::hypot(e->semi_axis_a_m * local.x(), e->semi_axis_b_m * local.y());
  }
  double best = -std::numeric_limits<double>::infinity();
  for (const Vec2& p : std::get<Polygon>(b.shape).points_m) best = std::max(best, p.dot(local));
  return best;
}

// the law's penetration at rest under load W: F_law(delta, 0) = W
double rest_penetration_m(const ContactLaw& law, double load_n) {
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) return load_n / kv->stiffness_n_per_m;
  if (const auto* h = std::get_if<Hertz>(&law)) return std::pow(load_n / h->stiffness, 1.0 / h->exponent);
  const auto& ln = std::get<LankaraniNikravesh>(law);
  return std::pow(load_n / ln.stiffness, 1.0 / ln.exponent);
}

const GeneratedBodies* the_stack(const Case& c, std::string* why) {
  const GeneratedBodies* stack = nullptr;
  for (const GeneratedBodies& g : c.generated) {
    if (g.kind != SceneKind::stack) continue;
    if (stack != nullptr) {
      *why = "two stacks: the closed form is one stack";
      return nullptr;
    }
    stack = &g;
  }
  if (stack == nullptr) *why = "no [[generate]] stack";
  return stack;
}

}  // namespace

std::string RestingStack::why_not(const Case& c) {
  try {
    const RestingStack s(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

RestingStack::RestingStack(const Case& c) {
  auto refuse = [](const std::string& why) { throw std::invalid_argument(why); };
  std::string why;
  const GeneratedBodies* g = the_stack(c, &why);
  if (g == nullptr) refuse(why);
  if (!c.joints.empty()) refuse("a resting stack has no joints");
  int moving = 0;
  for (const Body& b : c.bodies) moving += b.fixed ? 0 : 1;
  if (moving != g->count) {
    refuse(fmt::format("{} moving bodies besides the stack's {}: the closed form is the stack alone",
                       moving - g->count, g->count));
  }
  const Body& plane = c.bodies.at(static_cast<std::size_t>(g->support));
  normal_ = Vec2(-std::sin(plane.angle_rad), std::cos(plane.angle_rad));
  const Vec2 tangent(normal_.y(), -normal_.x());
  const double g_n = -c.gravity_mps2.dot(normal_);
  if (!(g_n > 0.0) || std::abs(c.gravity_mps2.dot(tangent)) > 1e-12 * c.gravity_mps2.norm()) {
    refuse("gravity is not along the support's inward normal: a frictional stack's pose is not "
           "the law's alone");
  }
  const ContactPairs rules(c);
  // loads from the top down
  std::vector<double> load(static_cast<std::size_t>(g->count));
  double above = 0.0;
  for (int k = g->count - 1; k >= 0; --k) {
    above += c.bodies[static_cast<std::size_t>(g->body(k))].mass_kg * g_n;
    load[static_cast<std::size_t>(k)] = above;
  }
  // heights from the support's surface up, checked against the case's pose
  const Vec2 origin = plane.position_m;
  double top_prev = 0.0;  // m, the surface's height for the first body
  for (int k = 0; k < g->count; ++k) {
    const int lower = k == 0 ? g->support : g->body(k - 1);
    const int upper = g->body(k);
    const ContactLaw* law = rules.law_between(lower, upper);
    if (law == nullptr) {
      refuse(fmt::format("no contact rule joins '{}' and '{}'", c.bodies[static_cast<std::size_t>(lower)].name,
                         c.bodies[static_cast<std::size_t>(upper)].name));
    }
    const Body& b = c.bodies[static_cast<std::size_t>(upper)];
    Interface f;
    f.body_a = lower;
    f.body_b = upper;
    f.load_n = load[static_cast<std::size_t>(k)];
    f.penetration_m = rest_penetration_m(*law, f.load_n);
    const double height = top_prev - f.penetration_m + reach(b, -normal_);
    const Vec2 expected = origin + tangent.dot(b.position_m - origin) * tangent + height * normal_;
    if ((expected - b.position_m).norm() > 1e-12 * (1.0 + expected.norm())) {
      refuse(fmt::format("body '{}' is not at the stack's resting pose ({:.9g}, {:.9g}) m (it is at "
                         "({:.9g}, {:.9g}) m): give start = \"resting\"",
                         b.name, expected.x(), expected.y(), b.position_m.x(), b.position_m.y()));
    }
    if (b.velocity_mps.norm() != 0.0 || b.angular_velocity_radps != 0.0) {
      refuse(fmt::format("body '{}' moves at t = 0: a resting stack starts at rest", b.name));
    }
    // the interface's middle: on the body's line, half its penetration below its bottom
    f.point_m = origin + tangent.dot(b.position_m - origin) * tangent +
                (top_prev - 0.5 * f.penetration_m) * normal_;
    interfaces_.push_back(f);
    top_prev = height + reach(b, normal_);
  }
  for (const Body& body : c.bodies) {
    BodyState s;
    s.position_m = body.position_m;
    s.angle_rad = body.angle_rad;
    states_.push_back(s);
  }
}

void RestingStack::body_states(double /*t_s*/, std::vector<BodyState>& out) const { out = states_; }

void RestingStack::contacts(double /*t_s*/, std::vector<ContactSample>& out) const {
  out.clear();
  for (const Interface& f : interfaces_) {
    ContactSample s;
    s.body_a = f.body_a;
    s.body_b = f.body_b;
    s.force_n = f.load_n;
    s.penetration_m = f.penetration_m;
    s.normal = normal_;
    s.point_m = f.point_m;
    out.push_back(s);
  }
}

std::vector<ContactEpisode> RestingStack::episodes(double now_s) const {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<ContactEpisode> out;
  for (const Interface& f : interfaces_) {
    ContactEpisode e;
    e.body_a = f.body_a;
    e.body_b = f.body_b;
    e.onset_time_s = 0.0;  // pressed from the start, never released
    e.offset_time_s = nan;
    e.approach_speed_mps = 0.0;
    e.separation_speed_mps = nan;
    e.restitution = nan;
    e.peak_force_n = f.load_n;
    e.impulse_ns = f.load_n * now_s;
    e.max_penetration_m = f.penetration_m;
    out.push_back(e);
  }
  return out;
}

nlohmann::json RestingStack::mapping() const {
  nlohmann::json j;
  j["closed_form"] = "resting_stack";
  j["description"] =
      "a stack at rest under gravity along the support's normal: the interface below body k "
      "carries the weight above it exactly, pressed by the law's penetration at rest under that "
      "load; nothing moves";
  nlohmann::json f = nlohmann::json::array();
  for (const Interface& i : interfaces_) {
    f.push_back({{"load_n", i.load_n}, {"penetration_m", i.penetration_m}});
  }
  j["interfaces_from_the_bottom"] = f;
  j["not_expressed"] = nlohmann::json::array();
  return j;
}

}  // namespace pb::internal
