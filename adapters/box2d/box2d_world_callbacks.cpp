#include "box2d_world_callbacks.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "box2d_frame.hpp"

namespace pb::internal::box2d {

int body_index(b2Fixture& fixture) {
  return static_cast<int>(fixture.GetUserData().pointer) - 1;
}

bool PairContactFilter::ShouldCollide(b2Fixture* fixture_a, b2Fixture* fixture_b) {
  return enabled_ && pairs_.may_touch(body_index(*fixture_a), body_index(*fixture_b));
}

void PairContactListener::PreSolve(b2Contact* contact, const b2Manifold* old_manifold) {
  // only a contact that begins now: its old manifold had no points
  if (old_manifold->pointCount > 0) return;
  const int ia = body_index(*contact->GetFixtureA());
  const int ib = body_index(*contact->GetFixtureB());
  const int k = pairs_.find_or_add(ia, ib);
  if (k < 0) return;
  PairState& st = pairs_.state(k);
  b2Body& body_a = *contact->GetFixtureA()->GetBody();
  b2Body& body_b = *contact->GetFixtureB()->GetBody();
  // the pair's contacts, from the list of its body that is not static (the
  // same contacts in the same order as the other's, box2d_world_callbacks.hpp)
  b2Body& listed = body_a.GetType() == b2_staticBody ? body_b : body_a;
  const b2Body* other = &listed == &body_a ? &body_b : &body_a;
  if (st.per_onset) {
    // the manifold points of every touching contact of the pair (this one's
    // is fresh, b2Contact::Update; the others were updated this step or keep
    // last step's): the pair's contact is the depth-weighted centroid of
    // their region (SPEC §1), along the deepest point's normal from the case
    // pair's body a to b
    const BodyState sa = body_state(body_a);
    const BodyState sb = body_state(body_b);
    int points = 0;
    double deepest = -std::numeric_limits<double>::infinity();
    Vec2 normal = Vec2::Zero();
    double approach = 0.0;  // m/s, the largest normal approach speed among the points
    for (b2ContactEdge* e = listed.GetContactList(); e != nullptr; e = e->next) {
      b2Contact* c = e->contact;
      if (e->other != other || !c->IsTouching()) continue;
      const int ca = body_index(*c->GetFixtureA());
      b2WorldManifold wm;
      c->GetWorldManifold(&wm);
      // the manifold normal points from fixture A to fixture B
      const Vec2 n = ca == ia ? from_b2(wm.normal) : Vec2(-from_b2(wm.normal));
      for (int i = 0; i < c->GetManifold()->pointCount; ++i) {
        const Vec2 p = from_b2(wm.points[i]);
        const double depth = -static_cast<double>(wm.separations[i]);
        if (depth > deepest) {
          deepest = depth;
          normal = n;
        }
        ++points;
        const double v = -n.dot(point_velocity(sb, p) - point_velocity(sa, p));
        approach = points == 1 ? v : std::max(approach, v);
      }
    }
    if (points > 0) {
      // the contact region's extent along the surface: its two end points
      // along the tangent of the deepest normal. Several convex pieces of one
      // body split one face into several manifolds whose points crowd where
      // the pieces meet (concave_seam_face: two of four at the heel, 3 mm
      // apart), so the mean of all points is not the region's middle; with
      // depths linear between its ends, the region's depth-weighted centroid
      // is the depth-weighted mean of its two ends: a uniform penetration
      // acts at the face's middle (SPEC §1), a single point (or points that
      // coincide, a vertex two pieces share) at that point
      const Vec2 t(-normal.y(), normal.x());
      Vec2 lo = Vec2::Zero();
      Vec2 hi = Vec2::Zero();
      double lo_depth = 0.0;  // m
      double hi_depth = 0.0;  // m
      double lo_s = std::numeric_limits<double>::infinity();
      double hi_s = -std::numeric_limits<double>::infinity();
      for (b2ContactEdge* e = listed.GetContactList(); e != nullptr; e = e->next) {
        b2Contact* c = e->contact;
        if (e->other != other || !c->IsTouching()) continue;
        b2WorldManifold wm;
        c->GetWorldManifold(&wm);
        for (int i = 0; i < c->GetManifold()->pointCount; ++i) {
          const Vec2 p = from_b2(wm.points[i]);
          const double depth = std::max(-static_cast<double>(wm.separations[i]), 0.0);
          const double s_along = t.dot(p);
          if (s_along < lo_s) {
            lo_s = s_along;
            lo = p;
            lo_depth = depth;
          }
          if (s_along > hi_s) {
            hi_s = s_along;
            hi = p;
            hi_depth = depth;
          }
        }
      }
      const double ends = lo_depth + hi_depth;  // m
      const Vec2 at = ends > 0.0 ? Vec2((lo_depth * lo + hi_depth * hi) / ends)
                                 : Vec2(0.5 * (lo + hi));
      BodyInertia a = inertia_[static_cast<std::size_t>(ia)];
      BodyInertia b = inertia_[static_cast<std::size_t>(ib)];
      a.centre_m = sa.position_m;
      b.centre_m = sb.position_m;
      const double m_eff = point_effective_mass_kg(a, b, at, normal);
      if (m_eff > 0.0 && std::isfinite(m_eff)) {
        st.restitution = law_restitution(st.law, m_eff, approach);
        // Box2D updates contacts one by one (b2ContactManager::Collide), so
        // an earlier new contact of the pair in this step saw only part of
        // the points; the last one sees them all and its value is the one
        // the solver takes: one record per pair and step, the last
        const OnsetRecord record{time_s_, k, m_eff, points, approach, st.restitution};
        auto same = log_.rbegin();
        while (same != log_.rend() && same->time_s == time_s_ && same->pair != k) ++same;
        if (same != log_.rend() && same->time_s == time_s_) {
          *same = record;
        } else if (log_.size() < log_.capacity()) {
          log_.push_back(record);
        } else {
          ++unlogged_;
        }
      }
    }
  }
  // the same restitution on every touching contact of the pair
  for (b2ContactEdge* e = listed.GetContactList(); e != nullptr; e = e->next) {
    b2Contact* c = e->contact;
    if (e->other != other || (c != contact && !c->IsTouching())) continue;
    c->SetRestitution(static_cast<float>(st.restitution));
    c->SetRestitutionThreshold(static_cast<float>(st.threshold_mps));
    c->SetFriction(st.friction);
  }
}

void PairContactListener::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) {
  // its first PreSolve gave the pair its index
  const int k =
      pairs_.find(body_index(*contact->GetFixtureA()), body_index(*contact->GetFixtureB()));
  if (k < 0) return;
  PairState& st = pairs_.state(k);
  if (st.impulse_step != pairs_.step) {
    st.impulse_step = pairs_.step;
    st.step_impulse_ns = 0.0;
    st.step_tangent_impulse_ns = 0.0;
  }
  double sum = 0.0;
  double tangent = 0.0;
  for (int i = 0; i < impulse->count; ++i) {
    sum += static_cast<double>(impulse->normalImpulses[i]);
    tangent += static_cast<double>(impulse->tangentImpulses[i]);
  }
  st.step_impulse_ns += sum;
  st.step_tangent_impulse_ns -= tangent;
}

}  // namespace pb::internal::box2d
