// Bare Box2D loop (issue 22): Box2D 2.4.1 used directly, as a user would, on
// exactly the scene and settings the "box2d" adapter (native mode) builds for
// falling_ball and disk_roll, so that callgrind's instructions per step of this
// program against the adapter's measure only the adapter's overhead.
//
// Mirrors:
//   adapters/box2d/box2d_engine.cpp   b2World with the case's gravity, sleeping
//       off, warm starting and continuous physics on, sub-stepping off, a
//       contact listener; the restitution threshold max(0.02, 2 |g| dt) m/s
//       (box2d_settings.hpp, automatic); the disk's b2MassData (m, centre 0, I);
//       Step(1e-4, 8, 3); the half-plane's chain long enough for the run:
//       half length max(extent / 2, reach) + 1 m, reach = |x0| + |v0| T +
//       |g| T^2 / 2 + R with T = steps x dt (the duration of the adapter run
//       this loop is compared with);
//   adapters/box2d/box2d_frame.cpp    body defs: static ground at its position
//       and angle, dynamic disk, allowSleep false, awake, no bullet;
//   adapters/box2d/box2d_geometry.cpp the half-plane as a one-sided b2ChainShape
//       of segments <= 10 m from +half to -half along the body's x axis, its core
//       one skin (b2_polygonRadius) below the surface so that the skinned edge is
//       the case's surface, ghost vertices one segment beyond each end; the disk a
//       b2CircleShape; fixtures with friction 0, restitution 0, density 0 and
//       the restitution threshold;
//   adapters/box2d/box2d_world_callbacks.cpp   PreSolve on a contact that
//       begins (old manifold without points): SetRestitution, SetRestitution-
//       Threshold, SetFriction (the pair's Coulomb coefficient, 0 when
//       frictionless). The adapter computes the restitution from the law at the
//       effective mass and approach speed then (box2d_restitution.cpp,
//       kelvin_voigt_response); for a free disk on fixed ground m_eff = m, and the
//       clamped Kelvin-Voigt restitution does not depend on the speed, so this loop
//       uses the constant e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)),
//       zeta = c / (2 sqrt(K m)).
// Leaves out, deliberately (that is the adapter's overhead being measured):
//   the contact filter restricting collisions to the case's pairs, the
//   listener's manifold walk and effective mass at each onset, PostSolve's
//   impulse sums, the per-step state checks (finite, velocity clamp), the
//   per-step contact probe and sampling (penetration, normal, point, speed),
//   the episode tracker.
//
// Usage: box2d_bare <falling_ball|disk_roll> <steps>
// Build: g++ -O3 -DNDEBUG -std=c++20 box2d_bare.cpp -o box2d_bare -lbox2d
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "bare_scene.hpp"

using namespace bare;

namespace {

constexpr double kMaxSegment = 10.0;  // m, longest chain segment

// the restitution, threshold and friction every contact of the pair takes as it begins
class Listener final : public b2ContactListener {
 public:
  Listener(float restitution, float threshold, float friction)
      : restitution_(restitution), threshold_(threshold), friction_(friction) {}
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override {
    if (old_manifold->pointCount > 0) return;
    contact->SetRestitution(restitution_);
    contact->SetRestitutionThreshold(threshold_);
    contact->SetFriction(friction_);
  }

 private:
  float restitution_, threshold_, friction_;
};

}  // namespace

int main(int argc, char** argv) {
  long steps = 0;
  const Scene* s = parse_command_line(argc, argv, steps);
  if (s == nullptr) return 2;

  // the law's restitution at m_eff = m (clamped Kelvin-Voigt, zeta < 1 in both scenes)
  const double zeta = s->damping_ns_per_m / (2.0 * std::sqrt(s->stiffness_n_per_m * s->mass_kg));
  const double e = std::exp(-zeta * (std::numbers::pi - 2.0 * std::asin(zeta)) / std::sqrt(1.0 - zeta * zeta));
  const double threshold = std::max(0.02, 2.0 * kGravity * kDt);  // m/s
  Listener listener(static_cast<float>(e), static_cast<float>(threshold),
                    static_cast<float>(s->friction));

  b2World world(b2Vec2(0.0f, static_cast<float>(-kGravity)));
  world.SetAllowSleeping(false);
  world.SetWarmStarting(true);
  world.SetContinuousPhysics(true);
  world.SetSubStepping(false);
  world.SetContactListener(&listener);

  b2FixtureDef fixture;
  fixture.friction = 0.0f;
  fixture.restitution = 0.0f;
  fixture.restitutionThreshold = static_cast<float>(threshold);
  fixture.density = 0.0f;

  // ground: a static body at the origin turned to the surface line
  b2BodyDef ground_def;
  ground_def.type = b2_staticBody;
  ground_def.position.Set(0.0f, 0.0f);
  ground_def.angle = static_cast<float>(s->ground_angle_rad);
  ground_def.allowSleep = false;
  ground_def.awake = true;
  b2Body* ground = world.CreateBody(&ground_def);
  {
    const double duration = static_cast<double>(steps) * kDt;
    const double reach = std::hypot(s->x0_m, s->y0_m) + 0.5 * kGravity * duration * duration + s->radius_m;
    const double half = std::max(0.5 * s->extent_m, reach) + 1.0;
    const int segments = std::max(1, static_cast<int>(std::ceil(2.0 * half / kMaxSegment)));
    const double step = 2.0 * half / segments;
    const float skin = b2_polygonRadius;
    std::vector<b2Vec2> vertices;
    for (int k = 0; k <= segments; ++k) vertices.emplace_back(static_cast<float>(half - step * k), -skin);
    vertices.back() = b2Vec2(static_cast<float>(-half), -skin);
    b2ChainShape chain;
    // from +x to -x: the one-sided normal is the body's +y
    chain.CreateChain(vertices.data(), static_cast<int32>(vertices.size()),
                      b2Vec2(static_cast<float>(half + step), -skin),
                      b2Vec2(static_cast<float>(-half - step), -skin));
    fixture.shape = &chain;
    ground->CreateFixture(&fixture);
  }

  // the disk
  b2BodyDef disk_def;
  disk_def.type = b2_dynamicBody;
  disk_def.position.Set(static_cast<float>(s->x0_m), static_cast<float>(s->y0_m));
  disk_def.angle = 0.0f;
  disk_def.allowSleep = false;
  disk_def.awake = true;
  disk_def.bullet = false;
  b2Body* disk = world.CreateBody(&disk_def);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(s->radius_m);
  circle.m_p.SetZero();
  fixture.shape = &circle;
  disk->CreateFixture(&fixture);
  b2MassData md;
  md.mass = static_cast<float>(s->mass_kg);
  md.center.SetZero();
  md.I = static_cast<float>(s->inertia_kgm2);
  disk->SetMassData(&md);

  const float dt = static_cast<float>(kDt);
  for (long n = 0; n < steps; ++n) {
    world.Step(dt, 8, 3);
    const b2Vec2 p = disk->GetWorldCenter();
    const b2Vec2 v = disk->GetLinearVelocity();
    Sample& o = g_samples[n & 63];
    o.x = p.x;
    o.y = p.y;
    o.angle = disk->GetAngle();
    o.vx = v.x;
    o.vy = v.y;
    o.omega = disk->GetAngularVelocity();
  }
  const Sample last = steps > 0 ? g_samples[(steps - 1) & 63] : Sample{s->x0_m, s->y0_m, 0, 0, 0, 0};
  std::printf("box2d %s steps=%ld x=%.17g y=%.17g\n", s->name, steps, last.x, last.y);
  return 0;
}
