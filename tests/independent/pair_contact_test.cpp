// Tests for core/independent/pair_contact.cpp
#include "pair_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "planarbench/errors.hpp"

namespace pb::independent {
namespace {

BodyMotion at(Vec2 c, double angle, Vec2 v = Vec2::Zero(), double w = 0.0) {
  return BodyMotion{Pose{c, angle}, v, w};
}

// the pair's motion advanced by h along constant velocities (first order in h)
BodyMotion moved(const BodyMotion& m, double h) {
  return at(m.pose.centre_m + h * m.velocity_mps, m.pose.angle_rad + h * m.angular_velocity_radps,
            m.velocity_mps, m.angular_velocity_radps);
}

// A disk on a line through p0 declining at 30 deg (outward normal
// n = (sin30, cos30)): depth = R - n . (c - p0) in closed form; the normal
// from the line (body a) to the disk is n; the contact point is the midpoint
// of the disk's lowest point c - R n and its projection on the line.
TEST(PairContact, DiskOnTiltedLine) {
  const double th = -std::numbers::pi / 6.0;
  const Vec2 n(-std::sin(th), std::cos(th));
  const Vec2 c(1.0, 0.45);
  const BodyMotion line = at(Vec2(0.2, 0.1), th);
  const BodyMotion disk = at(c, 0.7, Vec2(0.3, -2.0), 5.0);
  const PairContact pc = pair_contact(HalfPlane{}, line, Circle{0.5}, disk);
  const double depth = 0.5 - n.dot(c - Vec2(0.2, 0.1));
  EXPECT_NEAR(pc.depth_m, depth, 1e-15);  // a few roundings of O(1) terms
  EXPECT_NEAR((pc.normal - n).norm(), 0.0, 1e-15);
  EXPECT_NEAR((pc.point_b_m - (c - 0.5 * n)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(n.dot(pc.point_a_m - Vec2(0.2, 0.1)), 0.0, 1e-15);  // on the line
  // rate: -n . v (the spin moves the lowest point along the line only)
  EXPECT_NEAR(pc.depth_rate_mps, -n.dot(Vec2(0.3, -2.0)), 1e-15);
  // the same pair named the other way round: normal and points swap
  const PairContact flip = pair_contact(Circle{0.5}, disk, HalfPlane{}, line);
  EXPECT_EQ(flip.depth_m, pc.depth_m);
  EXPECT_EQ(flip.depth_rate_mps, pc.depth_rate_mps);
  EXPECT_EQ(flip.normal, -pc.normal);
  EXPECT_EQ(flip.point_a_m, pc.point_b_m);
}

// The rate of the depth is the derivative of the depth along the motion (the
// envelope theorem drops the support / nearest point's own motion): checked
// against the central difference (d(t + h) - d(t - h)) / 2h of the depth with
// the bodies moved rigidly. At h = 1e-6 s the difference errs by h^2 d''' / 6
// (~1e-12 x O(10) m/s^3 here) plus the rounding 1e-16 / 1e-6 = 1e-10 m/s:
// tolerance 1e-9 m/s.
TEST(PairContact, RateIsTheDerivativeOfTheDepth) {
  const double h = 1e-6;  // s
  const auto check = [&](const Shape& sa, BodyMotion ma, const Shape& sb, BodyMotion mb) {
    const PairContact now = pair_contact(sa, ma, sb, mb);
    const double ahead = pair_contact(sa, moved(ma, h), sb, moved(mb, h)).depth_m;
    const double behind = pair_contact(sa, moved(ma, -h), sb, moved(mb, -h)).depth_m;
    EXPECT_NEAR(now.depth_rate_mps, (ahead - behind) / (2.0 * h), 1e-9);
  };
  // an ellipse spinning on an incline (ellipse_incline's shapes)
  check(HalfPlane{}, at(Vec2::Zero(), -0.2618), Ellipse{0.3, 0.15},
        at(Vec2(0.1, 0.2), 0.3, Vec2(0.5, -2.4), 4.0));
  // a disk and an ellipse, both moving and spinning (dual_pendulum's shapes)
  check(Ellipse{0.7071, 0.25}, at(Vec2(0.0, -0.7), 1.5, Vec2(1.7, 0.1), -2.5), Circle{0.5},
        at(Vec2(0.76, -0.69), 0.2, Vec2(-0.3, 0.05), 0.8));
  // a polygon's vertex on a line
  check(HalfPlane{}, at(Vec2::Zero(), 0.0),
        Polygon{{Vec2(-0.3, -0.2), Vec2(0.3, -0.2), Vec2(0.3, 0.2), Vec2(-0.3, 0.2)}},
        at(Vec2(0.0, 0.3), 0.35, Vec2(0.2, -1.0), 3.0));
}

// A disk on the ellipse's major axis, beyond its vertex: nearest point the
// vertex (a, 0), depth R - (x - a), normal along the axis; the ellipse turned
// by 90 deg puts the axis along world y.
TEST(PairContact, DiskOffTheEllipsesVertex) {
  const double a = 0.7071;
  const double b = 0.25;
  const double r = 0.5;
  const BodyMotion ell = at(Vec2(0.0, 0.0), std::numbers::pi / 2.0);
  const BodyMotion disk = at(Vec2(0.0, a + 0.4999), 0.0);
  const PairContact pc = pair_contact(Ellipse{a, b}, ell, Circle{r}, disk);
  EXPECT_NEAR(pc.depth_m, r - 0.4999, 1e-15);
  EXPECT_NEAR((pc.normal - Vec2(0.0, 1.0)).norm(), 0.0, 1e-15);  // cos(pi/2) ~ 6e-17
  EXPECT_NEAR((pc.point_a_m - Vec2(0.0, a)).norm(), 0.0, 1e-15);
}

TEST(PairContact, DiskCentreInsideTheEllipseIsAnError) {
  EXPECT_THROW((void)pair_contact(Ellipse{0.7, 0.25}, at(Vec2::Zero(), 0.0), Circle{0.5},
                                  at(Vec2(0.1, 0.0), 0.0)),
               EngineError);
}

TEST(PairContact, WhichPairsAreCovered) {
  Body line{.name = "ground", .shape = HalfPlane{}, .fixed = true};
  Body disk{.name = "disk", .shape = Circle{0.5}};
  Body ell{.name = "ellipse", .shape = Ellipse{0.3, 0.1}};
  Body poly{.name = "poly", .shape = Polygon{{Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}}};
  EXPECT_EQ(pair_contact_unsupported(line, disk), "");
  EXPECT_EQ(pair_contact_unsupported(ell, line), "");
  EXPECT_EQ(pair_contact_unsupported(line, poly), "");
  EXPECT_EQ(pair_contact_unsupported(ell, disk), "");
  EXPECT_NE(pair_contact_unsupported(disk, disk), "");
  EXPECT_NE(pair_contact_unsupported(poly, ell), "");
  Body moving_line = line;
  moving_line.fixed = false;
  EXPECT_NE(pair_contact_unsupported(moving_line, disk).find("moves"), std::string::npos);
}

}  // namespace
}  // namespace pb::independent
