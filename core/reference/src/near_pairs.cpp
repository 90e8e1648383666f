#include "planarbench/reference/near_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pb {

namespace {

double reach_of(const Shape& shape) {
  if (const auto* c = std::get_if<Circle>(&shape)) return c->radius_m;
  if (const auto* e = std::get_if<Ellipse>(&shape)) return std::max(e->semi_axis_a_m, e->semi_axis_b_m);
  double r = 0.0;
  if (const auto* p = std::get_if<Polygon>(&shape)) {
    for (const Vec2& v : p->points_m) r = std::max(r, v.norm());
  }
  return r;
}

// rad, the difference of two angles folded into [0, pi]
double angle_moved(double a, double b) {
  const double d = std::remainder(a - b, 2.0 * std::numbers::pi);
  return std::abs(d);
}

}  // namespace

NearPairs::NearPairs(const Case& c, const PlanarModel& model) : model_(&model), bodies_(&c.bodies) {
  std::vector<bool> member(c.bodies.size(), false);
  for (const ContactGroup& g : c.contact_groups) {
    for (const int i : g.bodies) member[static_cast<std::size_t>(i)] = true;
  }
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    if (!member[i]) continue;
    Member m;
    m.body = static_cast<int>(i);
    m.plane = std::holds_alternative<HalfPlane>(c.bodies[i].shape);
    m.reach_m = m.plane ? 0.0 : reach_of(c.bodies[i].shape);
    m.margin_m = kNearMarginFraction * m.reach_m;
    members_.push_back(m);
  }
  built_at_.resize(members_.size());
}

double NearPairs::excursion(ConstVectorRef q) const {
  if (!built_) return 1.0;
  double worst = 0.0;
  for (std::size_t u = 0; u < members_.size(); ++u) {
    const Member& m = members_[u];
    if (m.plane || model_->kind(m.body) == PlanarModel::Kind::fixed) continue;
    const Pose p = model_->pose(m.body, q);
    const double moved = (p.position_m - built_at_[u].position_m).norm() +
                         m.reach_m * angle_moved(p.angle_rad, built_at_[u].angle_rad);
    worst = std::max(worst, moved / m.margin_m);
  }
  return worst;
}

bool NearPairs::update(ConstVectorRef q, ContactPairs& pairs, std::vector<int>& near) {
  if (built_ && excursion(q) <= 0.5) return false;
  built_ = true;
  ++rebuilds_;
  boxes_.clear();
  ids_.clear();
  for (std::size_t u = 0; u < members_.size(); ++u) {
    const Member& m = members_[u];
    built_at_[u] = model_->pose(m.body, q);
    if (m.plane) continue;
    const Pose& p = built_at_[u];
    boxes_.push_back(shape_aabb((*bodies_)[static_cast<std::size_t>(m.body)].shape, p.position_m,
                                p.angle_rad)
                         .expanded(m.margin_m));
    ids_.push_back(m.body);
  }
  overlapping_pairs(boxes_, ids_, candidates_, order_);
  // a body near a half-plane: its fattened box reaches below the surface
  for (std::size_t u = 0; u < members_.size(); ++u) {
    if (!members_[u].plane) continue;
    const Pose& plane = built_at_[u];
    const int pb = members_[u].body;
    for (std::size_t v = 0; v < boxes_.size(); ++v) {
      if (height_above_half_plane(boxes_[v], plane.position_m, plane.angle_rad) <= 0.0) {
        candidates_.emplace_back(std::min(pb, ids_[v]), std::max(pb, ids_[v]));
      }
    }
  }
  near.clear();
  for (const auto& [i, j] : candidates_) {
    const int k = pairs.find_or_add(i, j);
    // declared pairs are evaluated always; pairs no rule covers never
    if (k >= pairs.declared()) near.push_back(k);
  }
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  return true;
}

}  // namespace pb
