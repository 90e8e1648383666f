#include "ode_pair_contact.hpp"

#include <algorithm>
#include <cmath>

namespace pb::internal::ode {

namespace {

// a convex prism of n outline points reports at most 2n vertices
constexpr int kMinContactBuffer = 16;

int contact_capacity(const Case& c) {
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
    : case_(&c), world_(&world), buffer_(static_cast<std::size_t>(contact_capacity(c))) {
  const std::size_t n = c.bodies.size();
  pair_of_.assign(n * n, -1);
  for (std::size_t p = 0; p < c.contacts.size(); ++p) {
    const auto a = static_cast<std::size_t>(c.contacts[p].body_a);
    const auto b = static_cast<std::size_t>(c.contacts[p].body_b);
    pair_of_[a * n + b] = static_cast<int>(p);
    pair_of_[b * n + a] = static_cast<int>(p);
  }
}

void PairCollider::collide(std::vector<PairContact>& out) {
  out.resize(case_->contacts.size());
  for (PairContact& pc : out) pc.touching = false;
  out_ = &out;
  dSpaceCollide(world_->space(), this, &PairCollider::near_callback);
  out_ = nullptr;
}

void PairCollider::near_callback(void* data, dGeomID o1, dGeomID o2) {
  auto* self = static_cast<PairCollider*>(data);
  const auto n = self->case_->bodies.size();
  const auto i = static_cast<std::size_t>(OdeWorld::body_index_of(o1));
  const auto j = static_cast<std::size_t>(OdeWorld::body_index_of(o2));
  // only the case's contact pairs collide
  const int pair = self->pair_of_[i * n + j];
  if (pair < 0) return;
  self->collide_pair(pair, (*self->out_)[static_cast<std::size_t>(pair)]);
}

void PairCollider::collide_pair(int pair, PairContact& out) {
  const ContactPair& cp = case_->contacts[static_cast<std::size_t>(pair)];
  const dBodyID body_a = world_->body(cp.body_a);
  const dBodyID body_b = world_->body(cp.body_b);
  if (body_a == nullptr && body_b == nullptr) return;  // two fixed bodies never move
  // g1 must have a body: a contact joint attached to (0, body) is stored
  // reversed by ODE, and its feedback f1 would then belong to the other side
  const bool a_first = body_a != nullptr;
  const dGeomID o1 = a_first ? world_->geom(cp.body_a) : world_->geom(cp.body_b);
  const dGeomID o2 = a_first ? world_->geom(cp.body_b) : world_->geom(cp.body_a);
  const int count = dCollide(o1, o2, static_cast<int>(buffer_.size()), buffer_.data(),
                             static_cast<int>(sizeof(dContactGeom)));
  out.contacts_reported = count;
  if (count <= 0) return;

  // one contact per pair, the deepest: a prism reports each penetrating
  // vertex twice (z = -w and z = +w) and several soft contacts would add
  // their springs (the paper too uses one contact point per pair)
  int deepest = 0;
  for (int k = 1; k < count; ++k) {
    if (buffer_[static_cast<std::size_t>(k)].depth >
        buffer_[static_cast<std::size_t>(deepest)].depth) {
      deepest = k;
    }
  }
  dContactGeom g = buffer_[static_cast<std::size_t>(deepest)];
  // keep the contact in the plane z = 0
  g.pos[2] = 0.0;
  g.normal[2] = 0.0;
  const double len = std::hypot(g.normal[0], g.normal[1]);
  if (!(len > 0.0)) return;  // a normal along z: not a planar contact
  g.normal[0] /= len;
  g.normal[1] /= len;

  out.touching = true;
  out.geom = g;
  out.depth_m = g.depth;
  // ODE's normal points into g1, i.e. from g2 to g1
  const Vec2 n_into_g1(g.normal[0], g.normal[1]);
  out.normal_ab = a_first ? Vec2(-n_into_g1) : n_into_g1;
  out.point_m = contact_midpoint(g);
  out.approach_speed_mps = approach_speed_mps(*world_, cp, out.point_m, out.normal_ab);
}

double approach_speed_mps(const OdeWorld& world, const ContactPair& pair, const Vec2& point_m,
                          const Vec2& normal_ab) {
  const Vec2 v_rel = point_velocity(world.body(pair.body_b), point_m) -
                     point_velocity(world.body(pair.body_a), point_m);
  return -v_rel.dot(normal_ab);
}

}  // namespace pb::internal::ode
