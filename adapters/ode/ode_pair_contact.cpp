#include "ode_pair_contact.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "planarbench/errors.hpp"

namespace pb::internal::ode {

namespace {

// a convex prism of n outline points reports at most 2n vertices
constexpr int kMinContactBuffer = 16;

// contacts dCollide may give for one geom pair, and for one case pair (every
// piece of one body against every piece of the other)
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
bool in_plane_duplicate(const PairContact& out, const dContactGeom& c) {
  for (int k = 0; k < out.count; ++k) {
    const dContactGeom& d = out.geoms[static_cast<std::size_t>(k)];
    if (std::abs(d.pos[0] - c.pos[0]) <= 1e-9 && std::abs(d.pos[1] - c.pos[1]) <= 1e-9) {
      return true;
    }
  }
  return false;
}

}  // namespace

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
    const long bound = pair_contact_bound(world.vertex_count(cp.body_a), world.vertex_count(cp.body_b));
    capacity_ = static_cast<int>(std::max<long>(capacity_, bound));
  }
}

long pair_contact_bound(int vertices_a, int vertices_b) {
  return 2L * (static_cast<long>(vertices_a) + vertices_b) + kMinContactBuffer;
}

void PairCollider::collide(std::vector<PairContact>& out) {
  out.resize(case_->contacts.size());
  for (PairContact& pc : out) {
    if (pc.geoms.size() != static_cast<std::size_t>(capacity_)) {
      pc.geoms.resize(static_cast<std::size_t>(capacity_));
    }
    pc.touching = false;
    pc.count = 0;
    pc.contacts_reported = 0;
    pc.deepest = -1;
  }
  // the case lists its pairs: dCollide on each of them, every piece of one
  // body against every piece of the other (ODE's manual: dCollide may be
  // called directly on two geoms). dSpaceCollide would also find them, after
  // recomputing every moved geom's bounding box (dxConvex::computeAABB walks
  // all vertices of a prism: a third of dual_pendulum x ode) to test pairs the
  // case does not list.
  for (std::size_t p = 0; p < case_->contacts.size(); ++p) {
    const ContactPair& cp = case_->contacts[p];
    for (const dGeomID g : world_->geoms(cp.body_a)) {
      for (const dGeomID h : world_->geoms(cp.body_b)) collide_geoms(static_cast<int>(p), g, h, out[p]);
    }
  }
  for (std::size_t p = 0; p < out.size(); ++p) summarise(static_cast<int>(p), out[p]);
}

void PairCollider::collide_geoms(int pair, dGeomID g, dGeomID h, PairContact& out) {
  const ContactPair& cp = case_->contacts[static_cast<std::size_t>(pair)];
  const dBodyID body_a = world_->body(cp.body_a);
  const dBodyID body_b = world_->body(cp.body_b);
  if (body_a == nullptr && body_b == nullptr) return;  // two fixed bodies never move
  // g1 must have a body: a contact joint attached to (0, body) is stored
  // reversed by ODE, and its feedback f1 would then belong to the other side
  const bool g_is_a = OdeWorld::body_index_of(g) == cp.body_a;
  const dGeomID geom_a = g_is_a ? g : h;
  const dGeomID geom_b = g_is_a ? h : g;
  const bool a_first = body_a != nullptr;
  const dGeomID o1 = a_first ? geom_a : geom_b;
  const dGeomID o2 = a_first ? geom_b : geom_a;
  const int count = dCollide(o1, o2, static_cast<int>(buffer_.size()), buffer_.data(),
                             static_cast<int>(sizeof(dContactGeom)));
  out.contacts_reported += std::max(count, 0);
  for (int k = 0; k < count; ++k) {
    dContactGeom c = buffer_[static_cast<std::size_t>(k)];
    // keep the contact in the plane z = 0
    c.pos[2] = 0.0;
    c.normal[2] = 0.0;
    const double len = std::hypot(c.normal[0], c.normal[1]);
    if (!(len > 0.0)) continue;  // a normal along z: not a planar contact
    c.normal[0] /= len;
    c.normal[1] /= len;
    if (in_plane_duplicate(out, c)) continue;
    if (out.count >= capacity_) {
      throw EngineError(fmt::format(
          "ode: pair '{}' has more than {} contacts in one step, the bound 2 (V_a + V_b) + {} "
          "of its geoms' vertices (prisms 2 n, spheres and planes 1) its buffers are sized by",
          cp.name, capacity_, kMinContactBuffer));
    }
    out.geoms[static_cast<std::size_t>(out.count++)] = c;
  }
}

void PairCollider::summarise(int pair, PairContact& out) const {
  if (out.count == 0) return;
  const ContactPair& cp = case_->contacts[static_cast<std::size_t>(pair)];
  int deepest = 0;
  double sum = 0.0;  // m
  for (int k = 0; k < out.count; ++k) {
    const dContactGeom& c = out.geoms[static_cast<std::size_t>(k)];
    sum += c.depth;
    if (c.depth > out.geoms[static_cast<std::size_t>(deepest)].depth) deepest = k;
  }
  const dContactGeom& g = out.geoms[static_cast<std::size_t>(deepest)];
  out.touching = true;
  out.deepest = deepest;
  out.depth_m = g.depth;
  out.depth_sum_m = sum;
  // ODE's normal points into g1, i.e. from g2 to g1; g1 is body_a's when a moves
  const bool a_first = world_->body(cp.body_a) != nullptr;
  const Vec2 n_into_g1(g.normal[0], g.normal[1]);
  out.normal_ab = a_first ? Vec2(-n_into_g1) : n_into_g1;
  if (out.count == 1 || !(sum > 0.0)) {
    out.point_m = contact_midpoint(g);
  } else {
    Vec2 moment = Vec2::Zero();  // m^2
    for (int k = 0; k < out.count; ++k) {
      const dContactGeom& c = out.geoms[static_cast<std::size_t>(k)];
      moment += c.depth * contact_midpoint(c);
    }
    out.point_m = moment / sum;
  }
  out.approach_speed_mps = approach_speed_mps(*world_, cp, out.point_m, out.normal_ab);
}

double approach_speed_mps(const OdeWorld& world, const ContactPair& pair, const Vec2& point_m,
                          const Vec2& normal_ab) {
  const Vec2 v_rel = point_velocity(world.body(pair.body_b), point_m) -
                     point_velocity(world.body(pair.body_a), point_m);
  return -v_rel.dot(normal_ab);
}

}  // namespace pb::internal::ode
