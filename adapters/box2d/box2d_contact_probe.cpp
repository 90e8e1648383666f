#include "box2d_contact_probe.hpp"

#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <limits>
#include <vector>

#include <box2d/b2_contact.h>

#include "box2d_frame.hpp"

namespace pb::internal::box2d {

namespace {

// one collidable primitive: a circle, a polygon or an edge (a chain's child
// edge is copied out with its ghost vertices, b2ChainShape::GetChildEdge)
struct Primitive {
  enum Kind { circle, polygon, edge } kind = circle;
  const b2Shape* shape = nullptr;  // the fixture's shape (for b2DistanceProxy)
  int child = 0;
  b2EdgeShape child_edge;  // valid when the shape is a chain
  float radius = 0.0f;     // m, core-to-surface distance

  const b2CircleShape* as_circle() const { return static_cast<const b2CircleShape*>(shape); }
  const b2PolygonShape* as_polygon() const { return static_cast<const b2PolygonShape*>(shape); }
  const b2EdgeShape* as_edge() const {
    return shape->GetType() == b2Shape::e_chain ? &child_edge
                                                : static_cast<const b2EdgeShape*>(shape);
  }
};

Primitive primitive(const b2Fixture& f, int child) {
  Primitive p;
  p.shape = f.GetShape();
  p.child = child;
  p.radius = p.shape->m_radius;
  switch (p.shape->GetType()) {
    case b2Shape::e_circle:
      p.kind = Primitive::circle;
      break;
    case b2Shape::e_polygon:
      p.kind = Primitive::polygon;
      break;
    case b2Shape::e_edge:
      p.kind = Primitive::edge;
      break;
    case b2Shape::e_chain:
      p.kind = Primitive::edge;
      static_cast<const b2ChainShape*>(p.shape)->GetChildEdge(&p.child_edge, child);
      break;
    default:
      p.kind = Primitive::circle;
      break;
  }
  return p;
}

// Box2D's manifold of x against y; `swapped` when Box2D needs them the other
// way round (its functions take edge/polygon first). False: no such pair
// (edge-edge never collides in Box2D).
bool collide(const Primitive& x, const b2Transform& xfx, const Primitive& y, const b2Transform& xfy,
             b2Manifold& m, bool& swapped) {
  swapped = false;
  using K = Primitive::Kind;
  if (x.kind == K::circle && y.kind == K::circle) {
    b2CollideCircles(&m, x.as_circle(), xfx, y.as_circle(), xfy);
  } else if (x.kind == K::polygon && y.kind == K::circle) {
    b2CollidePolygonAndCircle(&m, x.as_polygon(), xfx, y.as_circle(), xfy);
  } else if (x.kind == K::circle && y.kind == K::polygon) {
    b2CollidePolygonAndCircle(&m, y.as_polygon(), xfy, x.as_circle(), xfx);
    swapped = true;
  } else if (x.kind == K::polygon && y.kind == K::polygon) {
    b2CollidePolygons(&m, x.as_polygon(), xfx, y.as_polygon(), xfy);
  } else if (x.kind == K::edge && y.kind == K::circle) {
    b2CollideEdgeAndCircle(&m, x.as_edge(), xfx, y.as_circle(), xfy);
  } else if (x.kind == K::circle && y.kind == K::edge) {
    b2CollideEdgeAndCircle(&m, y.as_edge(), xfy, x.as_circle(), xfx);
    swapped = true;
  } else if (x.kind == K::edge && y.kind == K::polygon) {
    b2CollideEdgeAndPolygon(&m, x.as_edge(), xfx, y.as_polygon(), xfy);
  } else if (x.kind == K::polygon && y.kind == K::edge) {
    b2CollideEdgeAndPolygon(&m, y.as_edge(), xfy, x.as_polygon(), xfx);
    swapped = true;
  } else {
    return false;
  }
  return true;
}

// position of fixture f in its body's fixture list
int fixture_index(const b2Fixture* f) {
  int i = 0;
  for (const b2Fixture* g = f->GetBody()->GetFixtureList(); g != nullptr && g != f; g = g->GetNext()) {
    ++i;
  }
  return i;
}

// one fixture-child pair of the two bodies: (fixture of a, its child,
// fixture of b, its child), ordered as the fixture lists and children are
struct ChildPair {
  int fixture_a, child_a, fixture_b, child_b;
  const b2Fixture* fa;
  const b2Fixture* fb;
  bool operator<(const ChildPair& o) const {
    if (fixture_a != o.fixture_a) return fixture_a < o.fixture_a;
    if (child_a != o.child_a) return child_a < o.child_a;
    if (fixture_b != o.fixture_b) return fixture_b < o.fixture_b;
    return child_b < o.child_b;
  }
};

// the fixture-child pair of a and b that contact c joins
ChildPair child_pair(const b2Body& a, const b2Contact& c) {
  const bool a_first = c.GetFixtureA()->GetBody() == &a;
  const b2Fixture* fa = a_first ? c.GetFixtureA() : c.GetFixtureB();
  const b2Fixture* fb = a_first ? c.GetFixtureB() : c.GetFixtureA();
  const int ca = a_first ? c.GetChildIndexA() : c.GetChildIndexB();
  const int cb = a_first ? c.GetChildIndexB() : c.GetChildIndexA();
  return ChildPair{fixture_index(fa), ca, fixture_index(fb), cb, fa, fb};
}

// Box2D's manifolds (or gaps) of the child pairs. Sorted into fixture-list
// order first, so that ties between equally deep points resolve as a pass
// over the lists would, whichever order the contacts came in.
ContactGeometry probe_pairs(const b2Body& a, const b2Body& b, std::vector<ChildPair>& pairs) {
  const b2Transform& xfa = a.GetTransform();
  const b2Transform& xfb = b.GetTransform();
  ContactGeometry deepest;  // from manifolds
  ContactGeometry closest;  // from b2Distance
  double best_separation = std::numeric_limits<double>::infinity();
  double best_gap = std::numeric_limits<double>::infinity();
  std::sort(pairs.begin(), pairs.end());

  for (const ChildPair& cp : pairs) {
    const Primitive x = primitive(*cp.fa, cp.child_a);
    const Primitive y = primitive(*cp.fb, cp.child_b);
    b2Manifold m;
    bool swapped = false;
    if (!collide(x, xfa, y, xfb, m, swapped)) continue;
    if (m.pointCount > 0) {
      // b2WorldManifold: normal from its first shape to its second,
      // points midway between the two skinned surfaces
      b2WorldManifold wm;
      if (swapped) {
        wm.Initialize(&m, xfb, y.radius, xfa, x.radius);
      } else {
        wm.Initialize(&m, xfa, x.radius, xfb, y.radius);
      }
      const Vec2 n = swapped ? Vec2(-from_b2(wm.normal)) : from_b2(wm.normal);
      for (int i = 0; i < m.pointCount; ++i) {
        const double s = static_cast<double>(wm.separations[i]);
        if (s < best_separation) {
          best_separation = s;
          deepest.valid = true;
          deepest.touching = true;
          deepest.penetration_m = -s;
          deepest.normal = n;
          deepest.point_m = from_b2(wm.points[i]);
        }
      }
      continue;
    }
    if (deepest.valid) continue;  // a touching pair wins; no need for gaps
    // apart: GJK between the cores, radii subtracted
    b2DistanceInput in;
    in.proxyA.Set(x.shape, x.child);
    in.proxyB.Set(y.shape, y.child);
    in.transformA = xfa;
    in.transformB = xfb;
    in.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput out;
    b2Distance(&out, &cache, &in);
    if (!(out.distance > 0.0f)) continue;  // cores overlap: no gap to report
    const double gap = static_cast<double>(out.distance) - x.radius - y.radius;
    if (gap < best_gap) {
      best_gap = gap;
      const Vec2 pa = from_b2(out.pointA);
      const Vec2 pb = from_b2(out.pointB);
      const Vec2 n = (pb - pa).normalized();
      closest.valid = true;
      closest.penetration_m = -gap;
      closest.normal = n;
      closest.point_m = 0.5 * ((pa + x.radius * n) + (pb - y.radius * n));
    }
  }
  return deepest.valid ? deepest : closest;
}

}  // namespace

ContactGeometry probe_contact(const b2Body& a, const b2Body& b, ProbeScope scope) {
  // The fixture-child pairs Box2D's broad phase holds for the two bodies
  // (b2Body::GetContactList): those whose fat AABBs overlap, which includes
  // every pair a manifold can have points for (touching means within the
  // radii, where the AABBs, radii included, overlap). Pairs farther apart
  // than the fat margin (b2_aabbExtension, 0.1 m, plus the predicted motion)
  // are not measured: the probe costs what Box2D's own contacts cost, not a
  // pass over every child of a long chain (issue 15: a 1000 s run's ground
  // chain has ~1e6 segments).
  thread_local std::vector<ChildPair> pairs;
  pairs.clear();
  if (scope == ProbeScope::every_child) {
    int ia = 0;
    for (const b2Fixture* fa = a.GetFixtureList(); fa != nullptr; fa = fa->GetNext(), ++ia) {
      int ib = 0;
      for (const b2Fixture* fb = b.GetFixtureList(); fb != nullptr; fb = fb->GetNext(), ++ib) {
        for (int ca = 0; ca < fa->GetShape()->GetChildCount(); ++ca) {
          for (int cb = 0; cb < fb->GetShape()->GetChildCount(); ++cb) {
            pairs.push_back(ChildPair{ia, ca, ib, cb, fa, fb});
          }
        }
      }
    }
  }
  for (const b2ContactEdge* e = a.GetContactList();
       scope == ProbeScope::broad_phase && e != nullptr; e = e->next) {
    if (e->other == &b) pairs.push_back(child_pair(a, *e->contact));
  }
  return probe_pairs(a, b, pairs);
}

ContactGeometry probe_contact(const b2Body& a, const b2Body& b, const b2Contact* const* contacts,
                              int count) {
  thread_local std::vector<ChildPair> pairs;
  pairs.clear();
  for (int i = 0; i < count; ++i) pairs.push_back(child_pair(a, *contacts[i]));
  return probe_pairs(a, b, pairs);
}

bool broad_phase_pair(const b2Body& a, const b2Body& b) {
  for (const b2ContactEdge* e = a.GetContactList(); e != nullptr; e = e->next) {
    if (e->other == &b) return true;
  }
  return false;
}

}  // namespace pb::internal::box2d
