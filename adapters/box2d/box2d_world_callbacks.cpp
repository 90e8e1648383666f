#include "box2d_world_callbacks.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>

#include "box2d_frame.hpp"

namespace pb::internal::box2d {

void PairTable::reset(int bodies) {
  bodies_ = bodies;
  table_.assign(static_cast<std::size_t>(bodies) * static_cast<std::size_t>(bodies), -1);
}

void PairTable::set(int body_a, int body_b, int pair) {
  table_[index(body_a, body_b)] = pair;
  table_[index(body_b, body_a)] = pair;
}

std::size_t PairTable::index(int body_a, int body_b) const {
  return static_cast<std::size_t>(body_a) * static_cast<std::size_t>(bodies_) +
         static_cast<std::size_t>(body_b);
}

int PairTable::pair(int body_a, int body_b) const {
  if (body_a < 0 || body_b < 0 || body_a >= bodies_ || body_b >= bodies_) return -1;
  return table_[index(body_a, body_b)];
}

int body_index(b2Fixture& fixture) {
  return static_cast<int>(fixture.GetUserData().pointer) - 1;
}

bool PairContactFilter::ShouldCollide(b2Fixture* fixture_a, b2Fixture* fixture_b) {
  return enabled_ && pairs_.pair(body_index(*fixture_a), body_index(*fixture_b)) >= 0;
}

void PairContactListener::BeginContact(b2Contact* contact) {
  const int ia = body_index(*contact->GetFixtureA());
  const int ib = body_index(*contact->GetFixtureB());
  const int k = pairs_.pair(ia, ib);
  if (k < 0) return;
  PairState& st = states_[static_cast<std::size_t>(k)];
  if (st.per_onset) {
    // the manifold is fresh (b2Contact::Update): its normal points from
    // fixture A to fixture B, its points lie midway between the surfaces
    b2WorldManifold wm;
    contact->GetWorldManifold(&wm);
    const int count = contact->GetManifold()->pointCount;
    Vec2 p = Vec2::Zero();
    for (int i = 0; i < count; ++i) p += from_b2(wm.points[i]);
    p /= static_cast<double>(count);
    const Vec2 n = from_b2(wm.normal);
    const b2Body& body_a = *contact->GetFixtureA()->GetBody();
    const b2Body& body_b = *contact->GetFixtureB()->GetBody();
    BodyInertia a = inertia_[static_cast<std::size_t>(ia)];
    BodyInertia b = inertia_[static_cast<std::size_t>(ib)];
    a.centre_m = from_b2(body_a.GetWorldCenter());
    b.centre_m = from_b2(body_b.GetWorldCenter());
    const double m_eff = effective_mass_kg(a, b, p, n);
    const Vec2 v_rel =
        point_velocity(body_state(body_b), p) - point_velocity(body_state(body_a), p);
    const double approach = -n.dot(v_rel);
    st.restitution = law_restitution(st.law, m_eff, approach);
    if (log_.size() < log_.capacity()) {
      log_.push_back(OnsetRecord{time_s_, k, m_eff, approach, st.restitution});
    } else {
      ++unlogged_;
    }
  }
  contact->SetRestitution(static_cast<float>(st.restitution));
  contact->SetRestitutionThreshold(static_cast<float>(st.threshold_mps));
  contact->SetFriction(0.0f);
}

void PairContactListener::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) {
  const int k =
      pairs_.pair(body_index(*contact->GetFixtureA()), body_index(*contact->GetFixtureB()));
  if (k < 0) return;
  double sum = 0.0;
  for (int i = 0; i < impulse->count; ++i) sum += static_cast<double>(impulse->normalImpulses[i]);
  states_[static_cast<std::size_t>(k)].step_impulse_ns += sum;
}

}  // namespace pb::internal::box2d
