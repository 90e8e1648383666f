#include "planarbench/impacts/rigid_impact.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace pb {

ImpactState rigid_impact(const ImpactObject& o, const ImpactState& before, double restitution,
                         double friction) {
  return rigid_compliant_impact(o, before, CompliantImpactLaw{restitution, 0.0, 0.0, friction, 1.0});
}

ImpactState rigid_compliant_impact(const ImpactObject& o, const ImpactState& before,
                                   const CompliantImpactLaw& law) {
  const double restitution =
      std::clamp(law.restitution + law.restitution_slope_s_per_m * before.velocity_mps.x(), 0.0,
                 1.0);
  const double friction = law.friction;
  const Vec2 r = lowest_point_offset(o, before.angle_rad);
  const Vec2 p(-r.y(), r.x());  // contact point velocity per unit omega
  const double m = o.mass_kg;
  const double inertia = o.inertia_kgm2() * law.gyration_scale * law.gyration_scale;
  const Eigen::Matrix2d w = Eigen::Matrix2d::Identity() / m + p * p.transpose() / inertia;
  const Vec2 u = before.velocity_mps + before.angular_velocity_radps * p;  // (tangent, normal)
  // inside the cone: the tangential velocity rebounds by e_t, the normal by e
  Vec2 impulse = w.ldlt().solve(
      Vec2(-(1.0 + law.tangential_restitution) * u.x(), -(1.0 + restitution) * u.y()));
  if (std::abs(impulse.x()) > friction * impulse.y()) {
    const double slide = u.x() > 0.0 ? 1.0 : (u.x() < 0.0 ? -1.0 : 0.0);
    const Vec2 direction(-friction * slide, 1.0);
    const double normal = -(1.0 + restitution) * u.y() / (w * direction).y();
    impulse = normal * direction;
  }
  ImpactState after = before;
  after.velocity_mps += impulse / m;
  after.angular_velocity_radps += (r.x() * impulse.y() - r.y() * impulse.x()) / inertia;
  return after;
}

ImpactState naive_bounce(const ImpactState& before, double restitution) {
  ImpactState after = before;
  after.velocity_mps.y() = -restitution * before.velocity_mps.y();
  return after;
}

}  // namespace pb
