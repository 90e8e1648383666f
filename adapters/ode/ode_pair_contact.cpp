#include "ode_pair_contact.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <fmt/format.h>

#include "planarbench/errors.hpp"

namespace pb::internal::ode {

namespace {

// a convex prism of n outline points reports at most 2n vertices
constexpr int kMinContactBuffer = 16;

Vec2 point_velocity(dBodyID b, const Vec2& p) {
  if (b == nullptr) return Vec2::Zero();
  dVector3 v;
  dBodyGetPointVel(b, p.x(), p.y(), 0.0, v);
  return {v[0], v[1]};
}

// Whether contact c lies (in the plane) where one already kept does: a prism
// reports each vertex on both faces, z = +w and z = -w, and a vertex where a
// seam of a concave polygon's decomposition ends is a vertex of two prisms
// (the L's outer corner, concave_corner; the boot's heel, concave_seam_face).
// One contact is kept per point. With friction a repeat would be the same
// friction row twice, hard (no soft CFM), which makes dWorldStep's LCP
// singular (measured on block_hold: "LCP internal error, s <= 0" at 1784
// steps, and a creep of 1.8e-5 m/s). Without it the law's spread over the
// depths (spread_law) would count a shared vertex twice and every other
// vertex once: on concave_seam_face the heel then carried 2/3 of a uniform
// penetration's force instead of 1/2, and the boot turned (3.5 rad, a
// restitution of 1.7). The normal law is spread over the contacts kept, so
// the pair's force is the same. 1e-9 m: far below a prism's smallest edge,
// far above rounding.
bool in_plane_duplicate(const StepContacts& out, const PairContact& pc, const dContactGeom& c) {
  for (int k = 0; k < pc.count; ++k) {
    const dContactGeom& d = out.geom(pc, k);
    if (std::abs(d.pos[0] - c.pos[0]) <= 1e-9 && std::abs(d.pos[1] - c.pos[1]) <= 1e-9) {
      return true;
    }
  }
  return false;
}

}  // namespace

int geom_pair_capacity(const Case& c) {
  int most = kMinContactBuffer;
  for (const Body& b : c.bodies) {
    const int pts = std::holds_alternative<Polygon>(b.shape)
                        ? static_cast<int>(std::get<Polygon>(b.shape).points_m.size())
                        : b.outline_points;
    most = std::max(most, 2 * pts + 4);
  }
  return std::min(most, 0xffff);  // dCollide's flags carry the count in 16 bits
}

long pair_contact_bound(int vertices_a, int vertices_b) {
  return 2L * (static_cast<long>(vertices_a) + vertices_b) + kMinContactBuffer;
}

bool flatten_to_plane(dContactGeom& c) {
  c.pos[2] = 0.0;
  c.normal[2] = 0.0;
  const double len = std::hypot(c.normal[0], c.normal[1]);
  if (!(len > 0.0)) return false;
  c.normal[0] /= len;
  c.normal[1] /= len;
  return true;
}

void keep_contact(const dContactGeom& c, long bound, const std::string& pair_name,
                  StepContacts& out, PairContact& pc) {
  if (in_plane_duplicate(out, pc, c)) return;
  if (pc.count >= bound) {
    throw EngineError(fmt::format(
        "ode: pair '{}' has more than {} contacts in one step, the bound 2 (V_a + V_b) + {} "
        "of its geoms' vertices (prisms 2 n, spheres and planes 1)",
        pair_name, bound, kMinContactBuffer));
  }
  out.geoms.push_back(c);
  ++pc.count;
}

Vec2 contact_midpoint(const dContactGeom& g) {
  const int c1 = dGeomGetClass(g.g1);
  const int c2 = dGeomGetClass(g.g2);
  const Vec2 pos(g.pos[0], g.pos[1]);
  const Vec2 n(g.normal[0], g.normal[1]);
  if (c1 == dSphereClass && c2 == dSphereClass) return pos;
  // which geom carries pos: the sphere of a sphere pair, else the convex
  int owner_class = -1;
  if (c1 == dSphereClass || c2 == dSphereClass) {
    owner_class = dSphereClass;
  } else if ((c1 == dConvexClass && c2 == dPlaneClass) ||
             (c1 == dPlaneClass && c2 == dConvexClass)) {
    owner_class = dConvexClass;
  } else if ((c1 == dBoxClass && c2 == dPlaneClass) || (c1 == dPlaneClass && c2 == dBoxClass)) {
    owner_class = dBoxClass;  // dCollideBoxPlane: pos is the box's vertex
  } else {
    return pos;
  }
  // the normal points into g1: from g1's deepest point the surface of g2 lies
  // `depth` along +normal; from g2's deepest point, g1's surface lies along -normal
  const double half = 0.5 * g.depth;
  return c1 == owner_class ? Vec2(pos + half * n) : Vec2(pos - half * n);
}

PairCollider::PairCollider(const Case& c, const OdeWorld& world)
    : case_(&c), world_(&world), buffer_(static_cast<std::size_t>(geom_pair_capacity(c))) {
  for (const ContactPair& cp : c.contacts) {
    bounds_.push_back(
        pair_contact_bound(world.vertex_count(cp.body_a), world.vertex_count(cp.body_b)));
  }
}

void PairCollider::collide(StepContacts& out) {
  out.clear();
  for (std::size_t p = 0; p < case_->contacts.size(); ++p) {
    const ContactPair& cp = case_->contacts[p];
    PairContact pc;
    pc.pair = static_cast<int>(p);
    pc.first = static_cast<int>(out.geoms.size());
    // g1 must have a body: a contact joint attached to (0, body) is stored
    // reversed by ODE, and its feedback f1 would then belong to the other side
    pc.g1_is_a = world_->body(cp.body_a) != nullptr;
    for (const dGeomID g : world_->geoms(cp.body_a)) {
      for (const dGeomID h : world_->geoms(cp.body_b)) collide_geoms(static_cast<int>(p), g, h, out, pc);
    }
    if (pc.count == 0) continue;
    summarise_pair(*world_, cp, out, pc);
    out.pairs.push_back(pc);
  }
}

void PairCollider::collide_geoms(int pair, dGeomID g, dGeomID h, StepContacts& out,
                                 PairContact& pc) {
  const ContactPair& cp = case_->contacts[static_cast<std::size_t>(pair)];
  if (world_->body(cp.body_a) == nullptr && world_->body(cp.body_b) == nullptr) {
    return;  // two fixed bodies never move
  }
  const bool g_is_a = OdeWorld::body_index_of(g) == cp.body_a;
  const dGeomID geom_a = g_is_a ? g : h;
  const dGeomID geom_b = g_is_a ? h : g;
  const dGeomID o1 = pc.g1_is_a ? geom_a : geom_b;
  const dGeomID o2 = pc.g1_is_a ? geom_b : geom_a;
  const int count = dCollide(o1, o2, static_cast<int>(buffer_.size()), buffer_.data(),
                             static_cast<int>(sizeof(dContactGeom)));
  pc.contacts_reported += std::max(count, 0);
  for (int k = 0; k < count; ++k) {
    dContactGeom c = buffer_[static_cast<std::size_t>(k)];
    if (!flatten_to_plane(c)) continue;  // a normal along z: not a planar contact
    keep_contact(c, bounds_[static_cast<std::size_t>(pair)], cp.name, out, pc);
  }
}

void summarise_pair(const OdeWorld& world, const ContactPair& cp, const StepContacts& out,
                    PairContact& pc) {
  int deepest = 0;
  double sum = 0.0;  // m
  for (int k = 0; k < pc.count; ++k) {
    const dContactGeom& c = out.geom(pc, k);
    sum += c.depth;
    if (c.depth > out.geom(pc, deepest).depth) deepest = k;
  }
  const dContactGeom& g = out.geom(pc, deepest);
  pc.deepest = deepest;
  pc.depth_m = g.depth;
  pc.depth_sum_m = sum;
  // ODE's normal points into g1, i.e. from g2 to g1
  const Vec2 n_into_g1(g.normal[0], g.normal[1]);
  pc.normal_ab = pc.g1_is_a ? Vec2(-n_into_g1) : n_into_g1;
  if (pc.count == 1 || !(sum > 0.0)) {
    pc.point_m = contact_midpoint(g);
  } else {
    Vec2 moment = Vec2::Zero();  // m^2
    for (int k = 0; k < pc.count; ++k) {
      const dContactGeom& c = out.geom(pc, k);
      moment += c.depth * contact_midpoint(c);
    }
    pc.point_m = moment / sum;
  }
  pc.approach_speed_mps = approach_speed_mps(world, cp, pc.point_m, pc.normal_ab);
}

double approach_speed_mps(const OdeWorld& world, const ContactPair& pair, const Vec2& point_m,
                          const Vec2& normal_ab) {
  const Vec2 v_rel = point_velocity(world.body(pair.body_b), point_m) -
                     point_velocity(world.body(pair.body_a), point_m);
  return -v_rel.dot(normal_ab);
}

}  // namespace pb::internal::ode
