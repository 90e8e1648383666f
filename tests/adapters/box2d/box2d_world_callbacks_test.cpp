// Tests for adapters/box2d/box2d_world_callbacks.cpp
#include "box2d_world_callbacks.hpp"

#include <box2d/b2_contact.h>
#include <box2d/b2_world.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "box2d_frame.hpp"
#include "box2d_geometry.hpp"
#include "box2d_test_cases.hpp"
#include "planarbench/adapters/box2d_engine.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/runner.hpp"

namespace pb::internal::box2d {
namespace {

// A world of a ground and two disks dropped side by side, with one case
// contact pair (ground, disk 1) of restitution law Kelvin-Voigt (e = 0.8588
// for 1 kg, zeta = 0.05). The filter lets only that pair collide: disk 2
// falls through the ground. The listener gives the pair's contact its
// restitution as it begins (disk 1 leaves at e times its approach speed)
// and sums the solver's impulses: m (1 + e) v over the bounce. Tolerances:
// gravity acts during the impulse step, (1 + e) g dt relative to v (4e-4),
// and float rounding (1e-6).
// A world with the adapter's filter and listener: case pair 0 joins bodies 0
// and 1 with `state`; every moving body is a 1 kg disk with I = 0.02 kg m^2
// (its mass data set after the fixtures, as the adapter does)
struct CallbackWorld {
  CallbackWorld(int body_count, PairState state) {
    Case c;
    c.bodies.resize(static_cast<std::size_t>(body_count));
    c.bodies[0].fixed = true;
    c.contacts = {box2d_test::kv_pair(0, 1)};
    pairs.reset(c, {state}, {});
    inertia.assign(static_cast<std::size_t>(body_count),
                   BodyInertia{false, 1.0, 0.02, Vec2::Zero(), false, Vec2::Zero()});
    inertia[0].fixed = true;
    world.SetContactFilter(&filter);
    world.SetContactListener(&listener);
  }
  // adds b (the next body index) and returns Box2D's body
  b2Body* add(const Body& b) {
    const b2BodyDef def = body_def(b);
    b2Body* body = world.CreateBody(&def);
    FixtureOptions opt;
    opt.body_index = static_cast<int>(bodies.size());
    opt.half_plane_half_length_m = 5.0;
    add_fixtures(*body, b, opt);
    if (!b.fixed) {
      b2MassData md{1.0f, b2Vec2(0.0f, 0.0f), 0.02f};
      body->SetMassData(&md);
    }
    bodies.push_back(body);
    return body;
  }
  b2World world{b2Vec2(0.0f, -9.8066f)};
  PairBook pairs;
  bool enabled = true;
  PairContactFilter filter{pairs, enabled};
  std::vector<BodyInertia> inertia;
  double time_s = 0.0;
  PairContactListener listener{pairs, inertia, time_s};
  std::vector<b2Body*> bodies;
};

TEST(Box2dWorldCallbacks, OnlyCasePairsCollideAndBounceWithTheLawsRestitution) {
  const double dt = 1e-4;
  PairState state;
  state.law = KelvinVoigt{1e4, 10.0, 0.0};
  state.per_onset = true;
  state.threshold_mps = 0.02;
  CallbackWorld w(3, state);
  w.listener.reserve_log(4);
  w.add(box2d_test::ground_body());
  w.add(box2d_test::disk_body("d1", 0.2, 1.0, Vec2(-1.0, 0.5)));
  w.add(box2d_test::disk_body("d2", 0.2, 1.0, Vec2(1.0, 0.5)));
  b2World& world = w.world;
  std::vector<b2Body*>& bodies = w.bodies;
  PairBook& book = w.pairs;
  double& time_s = w.time_s;
  const PairContactListener& listener = w.listener;
  double approach = 0.0;
  double separation = 0.0;
  double impulse = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const double vy_before = static_cast<double>(bodies[1]->GetLinearVelocity().y);
    book.step = i + 1;  // the step's stamp: PostSolve's sums start from 0
    world.Step(static_cast<float>(dt), 8, 3);
    time_s += dt;
    impulse += book.state(0).impulse_ns(i + 1);
    const double vy_after = static_cast<double>(bodies[1]->GetLinearVelocity().y);
    if (vy_before < 0.0 && vy_after > 0.0 && approach == 0.0) {
      approach = -vy_before;
      separation = vy_after;
    }
  }
  ASSERT_GT(approach, 0.0);
  const double e = box2d_test::clamped_kv_restitution(1e4, 10.0, 1.0);
  const double tol = (1.0 + e) * 9.8066 * dt / approach + 1e-6;
  EXPECT_NEAR(separation / approach, e, tol);
  // the impulse of the bounce (the disk flies for the rest of the run)
  EXPECT_NEAR(impulse / (approach * (1.0 + e)), 1.0, tol);
  // the onset was logged with m_eff = m (normal through the centre)
  ASSERT_EQ(listener.log().size(), 1u);
  // 1e-6 kg: from Box2D's float contact normal and mass data
  EXPECT_NEAR(listener.log()[0].m_eff_kg, 1.0, 1e-6);
  // 1e-12: flat ground gives the normal (0, 1) exactly and the mass is 1.0,
  // so this is the same closed form on the same inputs (evaluation order)
  EXPECT_NEAR(listener.log()[0].restitution, e, 1e-12);
  // disk 2 had no pair: it fell through the ground freely (0.5 s of free
  // fall from y = 0.5 m ends at -0.73 m; stopped at the ground it stays at 0.2)
  EXPECT_LT(bodies[2]->GetPosition().y, -0.5f);
}

// with collisions disabled (injection mode) nothing collides
TEST(Box2dWorldCallbacks, DisabledFilterRejectsEverything) {
  b2World world(b2Vec2(0.0f, -9.8066f));
  Case c;
  c.bodies.resize(2);
  c.bodies[0].fixed = true;
  c.contacts = {box2d_test::kv_pair(0, 1)};
  PairBook pairs;
  pairs.reset(c, {PairState{}}, {});
  const bool enabled = false;
  PairContactFilter filter(pairs, enabled);
  world.SetContactFilter(&filter);
  const Body ground = box2d_test::ground_body();
  const Body d1 = box2d_test::disk_body("d1", 0.2, 1.0, Vec2(0.0, 0.3));
  int index = 0;
  b2Body* disk = nullptr;
  for (const Body* b : {&ground, &d1}) {
    const b2BodyDef def = body_def(*b);
    b2Body* body = world.CreateBody(&def);
    FixtureOptions opt;
    opt.body_index = index++;
    add_fixtures(*body, *b, opt);
    disk = body;
  }
  // a dynamic body without mass does not fall in Box2D 2.4: give it the case's
  b2MassData md{1.0f, b2Vec2(0.0f, 0.0f), 0.02f};
  disk->SetMassData(&md);
  for (int i = 0; i < 1000; ++i) world.Step(1e-3f, 8, 3);
  // 1 s of free fall from 0.3 m ends at -4.6 m; stopped it would stay at 0.2
  EXPECT_LT(disk->GetPosition().y, -1.0f);
}

// The pair's friction goes to each of its contacts as it begins (PreSolve,
// b2Contact::SetFriction), whatever the fixtures' friction (0: the sqrt(f1 f2)
// mix would give 0). A uniform disk thrown at 2 m/s without spin on flat
// ground with mu = 0.5 slips until t* = v0 / (3 mu g) = 0.136 s and then rolls
// at (2/3) v0 (SPEC §7): at 0.2 s it rolls at 4/3 m/s. Tolerance: the float
// rounding of the velocity over 2000 steps, 2000 x 6e-8 x 2 m/s = 2.4e-4, and
// the contact point in the middle of the overlap (depth <= g dt^2 ~ 1e-7 m
// here): 2.4e-4
TEST(Box2dWorldCallbacks, PairFrictionIsSetOnItsContacts) {
  const double dt = 1e-4;
  PairState state;
  state.law = KelvinVoigt{1e5, 600.0, 0.0};
  state.threshold_mps = 0.02;
  state.friction = 0.5f;
  CallbackWorld w(2, state);
  w.add(box2d_test::ground_body());
  // resting on the ground (its centre 0.2 m above the surface)
  w.add(box2d_test::disk_body("d", 0.2, 1.0, Vec2(0.0, 0.2)))->SetLinearVelocity(b2Vec2(2.0f, 0.0f));
  b2World& world = w.world;
  const std::vector<b2Body*>& bodies = w.bodies;
  double& time_s = w.time_s;
  for (int i = 0; i < 2000; ++i) {
    world.Step(static_cast<float>(dt), 8, 3);
    time_s += dt;
  }
  ASSERT_NE(world.GetContactList(), nullptr);
  EXPECT_EQ(world.GetContactList()->GetFriction(), 0.5f);
  EXPECT_NEAR(static_cast<double>(bodies[1]->GetLinearVelocity().x), 4.0 / 3.0, 2.4e-4);
  // and it rolls: omega R = -v
  EXPECT_NEAR(static_cast<double>(bodies[1]->GetAngularVelocity()) * 0.2, -4.0 / 3.0, 2.4e-4);
}

// The mechanism behind Box2D's cone bands (cases/thresholds.toml; README,
// Per-step physical validity), row by row on the shipped sliding cases: the
// friction the listener sums is clamped by friction x the normal impulses of
// the velocity iteration before the last, so |F_t| - mu F_n is the float
// friction's rounding plus mu times the normal impulse's last change, which
// only the rounding of the body's normal velocity moves: at most
// 6 P u V / (g_n h) with V = |v_x| + |v_y| + |w| r_max at that row (not the
// run's largest, as the gate takes it), P the points. A clamp taken from a
// stale impulse or a friction mixed off mu would leave this by orders.
TEST(Box2dFrictionClamp, ConeResidualIsTheNormalVelocitysRounding) {
  constexpr double u = 5.960464477539063e-08;  // float32 unit roundoff 2^-24
  constexpr double h = 1e-4;                   // s, Box2D's default step here
  struct Slide {
    const char* file;
    double r_max;  // m, the body's farthest point from its centre
    int points;    // P: contact points at most (a face over a chain vertex 4, a circle 2)
  };
  for (const Slide& sl : {Slide{"disk_slip", 0.25, 2}, Slide{"block_slide", std::hypot(0.2, 0.02), 4},
                          Slide{"block_stop", std::hypot(0.2, 0.02), 4}}) {
    const Case c = load_case(std::string(PB_CASES_DIR) + "/" + sl.file + ".toml");
    // the case's mu, and gravity along its ground's normal
    const double mu = c.contacts.at(0).friction;
    const Body& ground = c.bodies.at(static_cast<std::size_t>(c.contacts.at(0).body_a));
    const double g_n = c.gravity_mps2.norm() * std::cos(ground.angle_rad);
    auto e = make_box2d_engine();
    const RunResult r = run_engine(*e, c, {});
    ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
    const BodyTrajectory& b = r.bodies.front();
    int rows = 0, over_float = 0;
    double worst = 0.0;  // residual in units of u V / (g_n h)
    for (const ContactRow& row : r.contacts) {
      const ContactSample& s = row.sample;
      if (!(s.force_n > 0.0)) continue;
      const auto k = static_cast<std::size_t>(std::lround(row.time_s / h));
      if (k >= b.time_s.size()) continue;
      const double v = std::abs(b.velocity_mps[k].x()) + std::abs(b.velocity_mps[k].y()) +
                       std::abs(b.angular_velocity_radps[k]) * sl.r_max;
      const double excess = (std::abs(s.tangential_force_n) - mu * s.force_n) / (mu * s.force_n);
      ++rows;
      if (excess > 2 * u) ++over_float;
      if (v > 0.0) worst = std::max(worst, (excess - 2 * u) / (u * v / (g_n * h)));
    }
    EXPECT_GT(rows, 1000) << sl.file;
    EXPECT_GT(over_float, 0) << sl.file << ": the clamp's lag is seen";
    EXPECT_LE(worst, 6.0 * sl.points) << sl.file;
  }
}

}  // namespace
}  // namespace pb::internal::box2d
