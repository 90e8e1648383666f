// Tests for adapters/mujoco/mujoco_geometry.cpp
#include "mujoco_geometry.hpp"

#include <gtest/gtest.h>

namespace pb::internal::mujoco {
namespace {

TEST(MujocoGeometry, ShapesBecomeOneGeomEach) {
  EXPECT_EQ(geom_type(Circle{0.5}), GeomType::sphere);
  EXPECT_EQ(geom_type(Ellipse{0.7, 0.25}), GeomType::ellipsoid);
  EXPECT_EQ(geom_type(Polygon{}), GeomType::mesh);
  EXPECT_EQ(geom_type(HalfPlane{}), GeomType::plane);
}

TEST(MujocoGeometry, EllipsoidKeepsTheEllipseInPlane) {
  // MuJoCo local (x, y, z) = (case x, out of plane, case y)
  const auto s = ellipsoid_size_m(Ellipse{0.7071, 0.25});
  EXPECT_EQ(s[0], 0.7071);
  EXPECT_EQ(s[2], 0.25);
  EXPECT_EQ(s[1], 0.25);  // min(a, b)
}

TEST(MujocoGeometry, BipyramidHasThePolygonInItsMidPlane) {
  const Polygon square{{Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1), Vec2(-1, -1)}};
  const auto v = bipyramid_vertices(square);
  ASSERT_EQ(v.size(), 6u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(v[i][0], square.points_m[i].x());
    EXPECT_EQ(v[i][1], 0.0);
    EXPECT_EQ(v[i][2], square.points_m[i].y());
  }
  // apexes over the centroid, off the plane: never extreme in x-z
  EXPECT_EQ(v[4][0], 0.0);
  EXPECT_EQ(v[4][2], 0.0);
  EXPECT_GT(v[4][1], 0.0);
  EXPECT_EQ(v[5][1], -v[4][1]);
}

TEST(MujocoGeometry, ConvexityOfCounterClockwisePolygons) {
  EXPECT_TRUE(is_convex(Polygon{{Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}}));
  // an L shape has one reflex corner
  EXPECT_FALSE(
      is_convex(Polygon{{Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)}}));
  EXPECT_FALSE(is_convex(Polygon{{Vec2(0, 0), Vec2(1, 0)}}));
}

TEST(MujocoGeometry, CollidersOfMujoco222) {
  EXPECT_EQ(collider(GeomType::sphere, GeomType::plane), Collider::exact);
  EXPECT_EQ(collider(GeomType::plane, GeomType::ellipsoid), Collider::exact);
  EXPECT_EQ(collider(GeomType::mesh, GeomType::plane), Collider::exact);
  EXPECT_EQ(collider(GeomType::sphere, GeomType::sphere), Collider::exact);
  EXPECT_EQ(collider(GeomType::ellipsoid, GeomType::sphere), Collider::mpr);
  EXPECT_EQ(collider(GeomType::sphere, GeomType::mesh), Collider::mpr);
  EXPECT_EQ(collider(GeomType::plane, GeomType::plane), Collider::none);
  EXPECT_EQ(collider_description(GeomType::ellipsoid, GeomType::sphere),
            "ellipsoid-sphere (libccd MPR, approximate depth)");
}

}  // namespace
}  // namespace pb::internal::mujoco
