#include "planarbench/impacts/impact_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "planarbench/errors.hpp"
#include "planarbench/overloaded.hpp"

namespace pb {

namespace {

// the state at time t of the arc that passes through `at_touch` at kLeadTime_s
struct ArcPoint {
  Vec2 position_m;
  double angle_rad;
  Vec2 velocity_mps;
};

ArcPoint arc(const ImpactObject& o, const ImpactState& at_touch, double t_s) {
  const double back = kLeadTime_s - t_s;  // s before the touch
  const double g = kImpactGravity_mps2;
  ArcPoint p;
  p.angle_rad = at_touch.angle_rad - at_touch.angular_velocity_radps * back;
  p.velocity_mps = Vec2(at_touch.velocity_mps.x(), at_touch.velocity_mps.y() + g * back);
  // y(touch) = touching height; y(t) = y(touch) - v_y(touch) back - g back^2 / 2
  p.position_m = Vec2(-at_touch.velocity_mps.x() * back,
                      touching_height(o, at_touch.angle_rad) - at_touch.velocity_mps.y() * back -
                          0.5 * g * back * back);
  return p;
}

}  // namespace

double ballistic_gap(const ImpactObject& o, const ImpactState& at_touch, double t_s) {
  const ArcPoint p = arc(o, at_touch, t_s);
  return p.position_m.y() - touching_height(o, p.angle_rad);
}

std::string impact_arc_problem(const ImpactObject& o, const ImpactState& at_touch) {
  for (int k = 0; k < 20; ++k) {
    const double t = kLeadTime_s * k / 20.0;
    if (ballistic_gap(o, at_touch, t) <= 0.0) {
      return fmt::format(
          "the impact at angle {:.4f} rad, velocity ({:.3f}, {:.3f}) m/s, {:.3f} rad/s: its "
          "ballistic arc touches the ground {:.2g} s before the impact (its lowest point does not "
          "approach the ground)",
          at_touch.angle_rad, at_touch.velocity_mps.x(), at_touch.velocity_mps.y(),
          at_touch.angular_velocity_radps, kLeadTime_s - t);
    }
  }
  return "";
}

Case impact_case(const ImpactObject& o, const ImpactState& at_touch, const ImpactLaw& law,
                 int outline_points) {
  if (const std::string problem = impact_arc_problem(o, at_touch); !problem.empty()) {
    throw InputError(problem);
  }
  Case c;
  c.name = "impact";
  c.description = "Measured impact: the ellipse dropped on horizontal ground";
  c.gravity_mps2 = Vec2(0.0, -kImpactGravity_mps2);
  c.duration_s = kImpactRunLimit_s;
  c.output_interval_s = 1e-4;
  c.truth = TruthKind::none;

  Body ground;
  ground.name = "ground";
  ground.shape = HalfPlane{1.0};  // m: 1 m of surface, the ellipse stays within 0.1 m of x = 0
  ground.fixed = true;
  ground.outline_points = outline_points;
  c.bodies.push_back(ground);

  const ArcPoint start = arc(o, at_touch, 0.0);
  Body ellipse;
  ellipse.name = "ellipse";
  ellipse.shape = Ellipse{o.semi_axis_a_m, o.semi_axis_b_m};
  ellipse.outline_points = outline_points;
  ellipse.mass_kg = o.mass_kg;
  ellipse.inertia_kgm2 = o.inertia_kgm2();
  ellipse.position_m = start.position_m;
  ellipse.angle_rad = start.angle_rad;
  ellipse.velocity_mps = start.velocity_mps;
  ellipse.angular_velocity_radps = at_touch.angular_velocity_radps;
  c.bodies.push_back(ellipse);

  ContactPair pair;
  pair.name = "ground_ellipse";
  pair.body_a = 0;
  pair.body_b = 1;
  if (law.kind == ImpactLawKind::hunt_crossley) {
    // the contact point's approach speed at the touch: the speed eq. 7's
    // family latches at the onset, which the arc reaches there
    const Vec2 r = lowest_point_offset(o, at_touch.angle_rad);
    const double approach =
        -(at_touch.velocity_mps.y() + at_touch.angular_velocity_radps * r.x());
    pair.law = LankaraniNikravesh{law.stiffness_n_per_m, law.exponent, 0.0, {},
                                  law.damping_s_per_m * approach};
  } else if (law.kind == ImpactLawKind::lankarani_nikravesh) {
    pair.law = LankaraniNikravesh{law.stiffness_n_per_m, law.exponent, law.restitution, {}, {}};
  } else {
    pair.law = KelvinVoigt{law.stiffness_n_per_m,
                           2.0 * law.damping_ratio * std::sqrt(law.stiffness_n_per_m * o.mass_kg),
                           0.0};
  }
  pair.friction = law.friction;
  c.contacts.push_back(pair);
  return c;
}

Case scaled_impact_case(Case c, double s) {
  c.gravity_mps2 *= s;
  for (Body& b : c.bodies) {
    std::visit(overloaded{[s](Circle& x) { x.radius_m *= s; },
                          [s](Ellipse& x) {
                            x.semi_axis_a_m *= s;
                            x.semi_axis_b_m *= s;
                          },
                          [s](Polygon& x) {
                            for (Vec2& p : x.points_m) p *= s;
                          },
                          [s](HalfPlane& x) { x.extent_m *= s; }},
               b.shape);
    b.inertia_kgm2 *= s * s;
    b.position_m *= s;
    b.velocity_mps *= s;
  }
  // F = K delta^n: force and delta both scale by s, so K by s^(1 - n)
  for (ContactPair& p : c.contacts) {
    std::visit(overloaded{[](KelvinVoigt&) {},
                          [s](Hertz& x) { x.stiffness *= std::pow(s, 1.0 - x.exponent); },
                          [s](LankaraniNikravesh& x) {
                            x.stiffness *= std::pow(s, 1.0 - x.exponent);
                          }},
               p.law);
  }
  return c;
}

ImpactObject scaled_impact_object(ImpactObject o, double s) {
  o.semi_axis_a_m *= s;
  o.semi_axis_b_m *= s;
  o.gyration_radius_m *= s;
  return o;
}

}  // namespace pb
