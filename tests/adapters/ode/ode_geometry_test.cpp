// Tests for adapters/ode/ode_geometry.cpp
#include "ode_geometry.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "ode_library.hpp"
#include "ode_test_cases.hpp"
#include "planarbench/outline.hpp"

namespace pb::internal::ode {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Vector3d vertex(const ConvexPrism& p, unsigned int i) {
  return {p.points[3 * i], p.points[3 * i + 1], p.points[3 * i + 2]};
}

// The prism of a 180-point ellipse outline, checked face by face against
// what dCreateConvex expects (ODE manual, "Convex class"): unit outward
// normals, every vertex on or behind every plane, each face's vertices on its
// plane and ordered counter-clockwise seen from outside (Newell's normal of
// the polygon points along the plane normal). 1e-12 m: rounding of sums of
// unit-size coordinates.
TEST(OdeGeometry, EllipsePrismIsAValidConvex) {
  const auto outline = make_outline(Ellipse{0.7071, 0.25}, 180);
  const ConvexPrism p = make_convex_prism(outline, 0.75);
  ASSERT_EQ(p.point_count, 360u);
  ASSERT_EQ(p.plane_count, 182u);
  std::size_t at = 0;
  for (unsigned int f = 0; f < p.plane_count; ++f) {
    const Eigen::Vector3d n(p.planes[4 * f], p.planes[4 * f + 1], p.planes[4 * f + 2]);
    const double d = p.planes[4 * f + 3];
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    for (unsigned int i = 0; i < p.point_count; ++i) EXPECT_LE(n.dot(vertex(p, i)) - d, 1e-12);
    const unsigned int count = p.polygons[at];
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (unsigned int k = 0; k < count; ++k) {
      const Eigen::Vector3d a = vertex(p, p.polygons[at + 1 + k]);
      const Eigen::Vector3d b = vertex(p, p.polygons[at + 1 + (k + 1) % count]);
      EXPECT_NEAR(n.dot(a), d, 1e-12);
      newell += a.cross(b);
    }
    EXPECT_GT(newell.normalized().dot(n), 1.0 - 1e-12) << "face " << f;
    at += count + 1;
  }
  EXPECT_EQ(at, p.polygons.size());
}

TEST(OdeGeometry, ConvexityCheck) {
  EXPECT_TRUE(is_convex_ccw(make_outline(Ellipse{0.7071, 0.25}, 180)));
  const std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(is_convex_ccw(square));
  EXPECT_FALSE(is_convex_ccw({{0, 0}, {0, 1}, {1, 1}, {1, 0}}));            // clockwise
  EXPECT_FALSE(is_convex_ccw({{0, 0}, {2, 0}, {1, 0.2}, {2, 2}, {0, 2}}));  // dent
}

// The falling_ball ground: a half-plane at the origin turned -30 deg has the
// outward normal (sin 30, cos 30) and passes through the origin; shifted to
// (0, 1) it passes through that point. 1e-15: one or two roundings of
// sin/cos of unit-size numbers.
TEST(OdeGeometry, HalfPlaneCoefficients) {
  const PlaneCoefficients p = halfplane_plane(Vec2::Zero(), -kPi / 6.0);
  EXPECT_NEAR(p.a, 0.5, 1e-15);
  EXPECT_NEAR(p.b, std::cos(kPi / 6.0), 1e-15);
  EXPECT_EQ(p.c, 0.0);
  EXPECT_NEAR(p.d, 0.0, 1e-15);
  const PlaneCoefficients q = halfplane_plane(Vec2(0.0, 1.0), -kPi / 6.0);
  EXPECT_NEAR(q.d, std::cos(kPi / 6.0), 1e-15);
}

// ODE's sphere-plane collider on the geoms we build: a sphere R = 0.5 whose
// centre is 0.45 m above the -30 deg line penetrates 0.05 m, along the line's
// normal (ODE's normal points into g1, the sphere). 1e-12 m on the depth:
// rounding of the centre's construction from coordinates of size 3 m; 1e-15
// on the unit normal: ODE copies the plane's normal.
TEST(OdeGeometry, SphereOnInclinedPlaneDepth) {
  ensure_ode_ready_in_this_thread();
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  const Body ball = ode_test::disk_body("ball", 0.5, 1.0, Vec2::Zero());
  ConvexPrism unused;
  dGeomID s = create_shape_geom(space, ball, unused);
  const PlaneCoefficients pc = halfplane_plane(Vec2::Zero(), -kPi / 6.0);
  dGeomID plane = dCreatePlane(space, pc.a, pc.b, pc.c, pc.d);
  const Vec2 n(pc.a, pc.b);
  const Vec2 p0(3.0, -1.0);
  const Vec2 centre = p0 + (0.45 - p0.dot(n)) * n;  // 0.45 m from the line
  dGeomSetPosition(s, centre.x(), centre.y(), 0.0);
  dContactGeom c[4];
  ASSERT_EQ(dCollide(s, plane, 4, c, sizeof(dContactGeom)), 1);
  EXPECT_NEAR(c[0].depth, 0.05, 1e-12);
  EXPECT_NEAR(c[0].normal[0], n.x(), 1e-15);
  EXPECT_NEAR(c[0].normal[1], n.y(), 1e-15);
  dSpaceDestroy(space);
}

// A rectangle centred on its origin with its sides along the body axes is
// recognised in any corner order; a square offset from its origin, a turned
// one, a triangle and a pentagon are not. The half sides are exact copies.
TEST(OdeGeometry, CentredRectangle) {
  const auto half = centred_rectangle_half_sides(
      {Vec2(0.2, 0.05), Vec2(-0.2, 0.05), Vec2(-0.2, -0.05), Vec2(0.2, -0.05)});
  ASSERT_TRUE(half.has_value());
  EXPECT_EQ(half->x(), 0.2);
  EXPECT_EQ(half->y(), 0.05);
  EXPECT_FALSE(centred_rectangle_half_sides(
                   {Vec2(0.0, 0.0), Vec2(0.2, 0.0), Vec2(0.2, 0.1), Vec2(0.0, 0.1)})
                   .has_value());
  const double s = std::sqrt(0.5);
  EXPECT_FALSE(centred_rectangle_half_sides({Vec2(0.0, -s), Vec2(s, 0.0), Vec2(0.0, s), Vec2(-s, 0.0)})
                   .has_value());
  EXPECT_FALSE(centred_rectangle_half_sides({Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.0, 0.1)})
                   .has_value());
  EXPECT_FALSE(centred_rectangle_half_sides({Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1),
                                             Vec2(0.0, 0.15), Vec2(-0.1, 0.1)})
                   .has_value());
}

// Two 0.4 x 0.1 m boxes pressed 9.8 um face to face (a stack's top
// interface). ODE's own convex-convex collider (no libccd in this build)
// takes the face pair for an edge-edge contact and reports one contact, in
// the middle of the face; as dBoxes (rectangles_as_boxes, a scene) ODE
// reports the face's four corners (+-0.2 m, z = +-w), two points in the
// plane. Why scenes build rectangles as boxes: on one contact a stack rocks
// from corner to corner. 1e-12 m: rounding of 0.1 m coordinates.
TEST(OdeGeometry, BoxesOnBoxesTouchAtTheFaceCorners) {
  ensure_ode_ready_in_this_thread();
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  Body box;
  box.name = "box";
  box.shape = Polygon{{Vec2(-0.2, -0.05), Vec2(0.2, -0.05), Vec2(0.2, 0.05), Vec2(-0.2, 0.05)}};
  box.mass_kg = 1.0;
  box.inertia_kgm2 = 1.0 / 12.0 * (0.16 + 0.01);
  const double depth = 9.8066e-6;  // m
  for (const bool as_boxes : {false, true}) {
    std::vector<std::unique_ptr<ConvexPrism>> prisms;
    const ShapeGeoms lower = create_shape_geoms(space, box, prisms, as_boxes);
    const ShapeGeoms upper = create_shape_geoms(space, box, prisms, as_boxes);
    ASSERT_EQ(lower.geoms.size(), 1u);
    EXPECT_EQ(dGeomGetClass(lower.geoms[0]), as_boxes ? dBoxClass : dConvexClass);
    EXPECT_EQ(lower.vertices, 8);
    dGeomSetPosition(lower.geoms[0], 0.0, 0.05, 0.0);
    dGeomSetPosition(upper.geoms[0], 0.0, 0.15 - depth, 0.0);
    dContactGeom c[16];
    const int n = dCollide(lower.geoms[0], upper.geoms[0], 16, c, sizeof(dContactGeom));
    if (!as_boxes) {
      ASSERT_EQ(n, 1);
      EXPECT_NEAR(c[0].pos[0], 0.0, 1e-12);
    } else {
      ASSERT_EQ(n, 4);
      for (int k = 0; k < n; ++k) {
        EXPECT_NEAR(std::abs(c[k].pos[0]), 0.2, 1e-12);
        EXPECT_NEAR(c[k].depth, depth, 1e-12);
      }
    }
    for (int k = 0; k < n; ++k) EXPECT_NEAR(c[k].normal[1], -1.0, 1e-12);
    dGeomDestroy(lower.geoms[0]);
    dGeomDestroy(upper.geoms[0]);
  }
  dSpaceDestroy(space);
}

}  // namespace
}  // namespace pb::internal::ode
