// Tests for adapters/ode/ode_pair_contact.cpp
#include "ode_pair_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ode_test_cases.hpp"
#include "planarbench/outline.hpp"

namespace pb::internal::ode {
namespace {

using ode_test::disk_body;
using ode_test::ellipse_body;
using ode_test::ground_body;
using ode_test::pair;

constexpr double kPi = std::numbers::pi;
const ContactLaw kKv = KelvinVoigt{1e4, 10.0, 0.0};

// A disk R = 0.5 m with its centre 0.45 m above the horizontal ground
// penetrates 0.05 m. The case's normal points from body_a to body_b: up when
// the ground is body_a, down when the pair lists the ball first. The contact
// point is midway between the ball's lowest point (y = -0.05) and the
// ground's surface (y = 0). A ball falling at 2 m/s approaches at +2 m/s
// either way. Tolerances: 1e-12 m on lengths built from 0.45 and 0.5
// (rounding of sums), 1e-15 on unit normals and on 0.3 (copied, at most one
// rounding).
TEST(OdePairContact, NormalFollowsThePairOrder) {
  for (const bool ground_first : {true, false}) {
    Case c;
    c.bodies = {ground_body(), disk_body("ball", 0.5, 1.0, Vec2(0.3, 0.45))};
    c.bodies[1].velocity_mps = Vec2(0.0, -2.0);
    c.contacts = {ground_first ? pair(0, 1, kKv) : pair(1, 0, kKv)};
    OdeWorld world(c);
    PairCollider collider(c, world);
    StepContacts out;
    collider.collide(out);
    ASSERT_EQ(out.pairs.size(), 1u);
    const PairContact& pc = out.pairs[0];
    EXPECT_NEAR(pc.depth_m, 0.05, 1e-12);
    const Vec2 up(0.0, 1.0);
    EXPECT_NEAR((pc.normal_ab - (ground_first ? up : Vec2(-up))).norm(), 0.0, 1e-15);
    EXPECT_NEAR(pc.point_m.x(), 0.3, 1e-15);
    EXPECT_NEAR(pc.point_m.y(), -0.025, 1e-12);
    EXPECT_NEAR(pc.approach_speed_mps, 2.0, 1e-12);
    // the ODE contact: g1 has a body and the normal points into it
    EXPECT_EQ(dGeomGetBody(out.geom(pc, 0).g1), world.body(1));
    EXPECT_NEAR(out.geom(pc, 0).normal[1], 1.0, 1e-15);
  }
}

// Only the case's pairs collide: a second ball overlapping the ground and the
// first ball, but in no pair, is never reported.
TEST(OdePairContact, OnlyTheCasePairsCollide) {
  Case c;
  c.bodies = {ground_body(), disk_body("ball", 0.5, 1.0, Vec2(0.0, 0.45)),
              disk_body("ghost", 0.5, 1.0, Vec2(0.2, 0.4))};
  c.contacts = {pair(0, 1, kKv)};
  OdeWorld world(c);
  PairCollider collider(c, world);
  StepContacts out;
  collider.collide(out);
  ASSERT_EQ(out.pairs.size(), 1u);
  EXPECT_EQ(out.pairs[0].pair, 0);
  EXPECT_EQ(out.pairs[0].contacts_reported, 1);
}

// exact distance from p to the polygon's edges (independent of ODE)
double polygon_distance(const std::vector<Vec2>& poly, const Vec2& p) {
  double best = 1e300;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec2 a = poly[k];
    const Vec2 ab = poly[(k + 1) % poly.size()] - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - a - t * ab).norm());
  }
  return best;
}

// The dual pendulum's contact: the 180-point ellipse (a = 0.7071, b = 0.25)
// hanging vertically (angle -90 deg) against the disk R = 0.5 on its right.
// ODE's sphere-convex collider reports one contact; its depth is compared
// with R minus the exact distance from the disk's centre to the polygon,
// swept along the side and over the pendulum's penetrations (up to ~0.14 mm).
// Measured worst difference 5.3e-7 m (ODE returns the first face or vertex
// it meets); 1e-6 m bounds it, below 1 % of the peak penetration.
TEST(OdePairContact, SphereConvexDepthMatchesThePolygon) {
  const double a = 0.7071;
  const double b = 0.25;
  const auto local = make_outline(Ellipse{a, b}, 180);
  std::vector<Vec2> world_outline;
  for (const Vec2& q : local) world_outline.emplace_back(q.y(), -q.x());  // turned -90 deg
  int checked = 0;
  for (double y = -0.02; y <= 0.02; y += 0.0007) {
    for (const double pen : {1e-5, 5e-5, 1.4e-4}) {
      const Vec2 centre(b + 0.5 - pen, y);
      const double exact = 0.5 - polygon_distance(world_outline, centre);
      if (exact <= 1e-9) continue;
      Case c;
      c.bodies = {ellipse_body("ellipse", a, b, 1.0, Vec2::Zero(), -kPi / 2.0),
                  disk_body("disk", 0.5, 1.0, centre)};
      c.contacts = {pair(0, 1, LankaraniNikravesh{1.0242e10, 1.5, 0.7, std::nullopt, {}})};
      OdeWorld world(c);
      PairCollider collider(c, world);
      StepContacts out;
      collider.collide(out);
      ASSERT_EQ(out.pairs.size(), 1u) << y << " " << pen;
      EXPECT_NEAR(out.pairs[0].depth_m, exact, 1e-6) << y << " " << pen;
      // from the ellipse to the disk: the outline's faces near the minor
      // axis turn by at most 2 deg (180 points), cos 2 deg = 0.9994
      EXPECT_GT(out.pairs[0].normal_ab.x(), 0.999);
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

// An ellipse turned 30 deg, centre 0.4 m above the ground: several of its
// outline vertices are below the ground (found here from the outline
// itself). The prism reports each on both of its faces (z = -w and +w), and
// the collider keeps one contact per in-plane point; the pair's contact
// (SPEC §1) has the deepest vertex's depth, the normal up, and the
// depth-weighted centroid of the contacts' points, each midway between a
// vertex and the ground surface above it. A
// rotation error would move the vertices to the other side of the centre.
// 1e-12 m: rounding of the rotated vertices (computed here and by ODE from the
// same outline); 1e-15 on the plane's unit normal.
TEST(OdePairContact, RotatedEllipseOnGroundActsAtItsDepthWeightedVertices) {
  const double angle = kPi / 6.0;
  const Vec2 centre(1.0, 0.4);
  const auto local = make_outline(Ellipse{0.7071, 0.25}, 180);
  Vec2 lowest(0.0, 1e300);
  double weight = 0.0;
  Vec2 moment = Vec2::Zero();
  int below = 0;
  for (const Vec2& q : local) {
    const Vec2 w(centre.x() + std::cos(angle) * q.x() - std::sin(angle) * q.y(),
                 centre.y() + std::sin(angle) * q.x() + std::cos(angle) * q.y());
    if (w.y() < lowest.y()) lowest = w;
    if (w.y() < 0.0) {
      weight -= w.y();
      moment -= w.y() * Vec2(w.x(), 0.5 * w.y());
      ++below;
    }
  }
  ASSERT_LT(lowest.y(), 0.0);
  ASSERT_LT(lowest.x(), centre.x());  // a CCW turn puts the low end on the left
  ASSERT_GE(below, 2);                // several vertices: the centroid is not the deepest
  Case c;
  c.bodies = {ground_body(), ellipse_body("ellipse", 0.7071, 0.25, 1.0, centre, angle)};
  c.contacts = {pair(0, 1, kKv)};
  OdeWorld world(c);
  PairCollider collider(c, world);
  StepContacts out;
  collider.collide(out);
  ASSERT_EQ(out.pairs.size(), 1u);
  EXPECT_EQ(out.pairs[0].contacts_reported, 2 * below);  // each vertex on both faces of the prism
  EXPECT_EQ(out.pairs[0].count, below);                  // one kept per in-plane point
  EXPECT_NEAR(out.pairs[0].depth_m, -lowest.y(), 1e-12);
  EXPECT_NEAR(out.pairs[0].depth_sum_m, weight, 1e-12);
  EXPECT_NEAR(out.pairs[0].point_m.x(), moment.x() / weight, 1e-12);
  EXPECT_NEAR(out.pairs[0].point_m.y(), moment.y() / weight, 1e-12);
  EXPECT_NEAR(out.pairs[0].normal_ab.y(), 1.0, 1e-15);
}

// The boot of concave_seam_face.toml 2 mm into the ground on its sole: two
// convex prisms, the heel a vertex of both, the toe of one. dCollide reports
// the heel four times (two prisms, two faces each) and the toe twice; one
// contact is kept per in-plane point, so the law spreads alike over heel and
// toe and the pair acts at the sole's middle, under the centre of mass (x = 0).
// Counting the heel twice put the point 0.4 / 6 m toward it and turned the
// boot. 1e-12 m: rounding of 0.2 m coordinates.
TEST(OdePairContact, VertexSharedByTwoPiecesIsOneContact) {
  Case c;
  Body boot;
  boot.name = "boot";
  boot.shape = Polygon{{Vec2(-0.2, -0.09982758620689655), Vec2(0.2, -0.09982758620689655),
                        Vec2(0.2, 0.14017241379310344), Vec2(-0.12, -0.039827586206896554),
                        Vec2(-0.12, 0.17017241379310344), Vec2(-0.2, 0.17017241379310344)}};
  boot.mass_kg = 1.0;
  boot.inertia_kgm2 = 0.0214747;
  boot.position_m = Vec2(0.0, 0.09982758620689655 - 0.002);
  c.bodies = {ground_body(), boot};
  c.contacts = {pair(0, 1, kKv)};
  OdeWorld world(c);
  PairCollider collider(c, world);
  StepContacts out;
  collider.collide(out);
  ASSERT_EQ(out.pairs.size(), 1u);
  EXPECT_EQ(out.pairs[0].contacts_reported, 6);
  EXPECT_EQ(out.pairs[0].count, 2);
  EXPECT_NEAR(out.pairs[0].depth_sum_m, 2 * 0.002, 1e-12);
  EXPECT_NEAR(out.pairs[0].point_m.x(), 0.0, 1e-12);
}

// Disk against disk (sphere-sphere): ODE's pos is the midpoint already.
// 1e-12 m: rounding of sums of O(1) m lengths; 1e-15 on the unit normal.
TEST(OdePairContact, SphereSphereMidpoint) {
  Case c;
  c.bodies = {disk_body("left", 0.5, 1.0, Vec2(0.0, 0.0)),
              disk_body("right", 0.25, 1.0, Vec2(0.7, 0.0))};
  c.contacts = {pair(0, 1, kKv)};
  OdeWorld world(c);
  PairCollider collider(c, world);
  StepContacts out;
  collider.collide(out);
  ASSERT_EQ(out.pairs.size(), 1u);
  EXPECT_NEAR(out.pairs[0].depth_m, 0.05, 1e-12);
  // left's rightmost point 0.5, right's leftmost 0.45: midpoint 0.475
  EXPECT_NEAR(out.pairs[0].point_m.x(), 0.475, 1e-12);
  EXPECT_NEAR(out.pairs[0].normal_ab.x(), 1.0, 1e-15);
}

}  // namespace
}  // namespace pb::internal::ode
