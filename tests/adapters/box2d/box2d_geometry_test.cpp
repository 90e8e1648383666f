// Tests for adapters/box2d/box2d_geometry.cpp
#include "box2d_geometry.hpp"

#include <box2d/b2_chain_shape.h>
#include <box2d/b2_common.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "box2d_frame.hpp"
#include "box2d_test_cases.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::box2d {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEpsF = 1.1920928955078125e-07;  // float32 epsilon

// signed distance of world point q from the skinned surface of a body's
// fixtures (> 0 outside): b2Distance between the point and each core, minus
// the core's radius; inside every core the point counts as -skin or deeper,
// which the tests below never need
double skinned_distance(const b2Body& body, const Vec2& q) {
  double best = std::numeric_limits<double>::infinity();
  b2Vec2 point = to_b2(q);
  for (const b2Fixture* f = body.GetFixtureList(); f != nullptr; f = f->GetNext()) {
    for (int child = 0; child < f->GetShape()->GetChildCount(); ++child) {
      b2DistanceInput in;
      in.proxyA.Set(f->GetShape(), child);
      in.proxyB.Set(&point, 1, 0.0f);
      in.transformA = body.GetTransform();
      in.transformB.SetIdentity();
      in.useRadii = false;
      b2SimplexCache cache;
      cache.count = 0;
      b2DistanceOutput out;
      b2Distance(&out, &cache, &in);
      best = std::min(best, static_cast<double>(out.distance) - f->GetShape()->m_radius);
    }
  }
  return best;
}

// The inset of a counter-clockwise square of side 2 by r is the square of
// side 2 - 2r: every edge moves inward by r, corners stay on the diagonals.
TEST(Box2dGeometry, InsetOfASquareIsTheSmallerSquare) {
  const std::vector<Vec2> square = {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
  const auto inset = inset_outline(square, 0.1);
  ASSERT_EQ(inset.size(), 4u);
  // 1e-15 m: 0.9 and the inset coordinates are rounded doubles of size 1
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(inset[i].x(), 0.9 * square[i].x(), 1e-15);
    EXPECT_NEAR(inset[i].y(), 0.9 * square[i].y(), 1e-15);
  }
}

// A 180-point ellipse fans into 30 convex pieces of the centre and 7 outline
// points (6 edges each, 180 / 6 = 30), each within Box2D's 8 vertices, and the
// pieces' areas add up to the outline's (the fan covers it once).
TEST(Box2dGeometry, EllipseFanHasConvexPiecesCoveringTheOutline) {
  const double a = 0.7071;
  const double b = 0.25;
  std::vector<Vec2> outline;
  for (int k = 0; k < 180; ++k) {
    const double t = 2 * kPi * k / 180;
    outline.emplace_back(a * std::cos(t), b * std::sin(t));
  }
  const Fan fan = convex_fan(outline, Vec2::Zero(), kFanOutlineVertices);
  ASSERT_TRUE(fan.error.empty()) << fan.error;
  EXPECT_EQ(fan.pieces.size(), 30u);
  double area_pieces = 0.0;
  for (const auto& piece : fan.pieces) {
    EXPECT_LE(static_cast<int>(piece.size()), b2_maxPolygonVertices);
    EXPECT_TRUE(is_convex_ccw(piece));
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const Vec2& p = piece[i];
      const Vec2& q = piece[(i + 1) % piece.size()];
      area_pieces += 0.5 * (p.x() * q.y() - q.x() * p.y());
    }
  }
  double area_outline = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Vec2& p = outline[i];
    const Vec2& q = outline[(i + 1) % outline.size()];
    area_outline += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  // 1e-12 m^2: rounding of the 180 + 30 x 7 cross products of size 0.01
  EXPECT_NEAR(area_pieces, area_outline, 1e-12);
}

// a small convex polygon is one piece; a star (concave but star-shaped from
// its centre) fans; a C shape whose mouth hides edges from the centre is
// refused with a reason
TEST(Box2dGeometry, ConvexStarAndNonStarPolygons) {
  const std::vector<Vec2> box = {{1, -0.5}, {1, 0.5}, {-1, 0.5}, {-1, -0.5}};
  const Fan one = convex_fan(box, Vec2::Zero(), kFanOutlineVertices);
  ASSERT_EQ(one.pieces.size(), 1u);
  EXPECT_EQ(one.pieces[0].size(), 4u);

  std::vector<Vec2> star;
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 == 0 ? 1.0 : 0.4;
    star.emplace_back(r * std::cos(2 * kPi * k / 10), r * std::sin(2 * kPi * k / 10));
  }
  const Fan fan = convex_fan(star, Vec2::Zero(), kFanOutlineVertices);
  ASSERT_TRUE(fan.error.empty());
  for (const auto& piece : fan.pieces) EXPECT_TRUE(is_convex_ccw(piece));

  // C shape around the origin: the inner wall's edges face away from it
  const std::vector<Vec2> c_shape = {{1, -1},  {1, -0.5}, {-0.5, -0.5}, {-0.5, 0.5},
                                     {1, 0.5}, {1, 1},    {-1, 1},      {-1, -1}};
  const Fan refused = convex_fan(c_shape, Vec2(0.6, 0.0), kFanOutlineVertices);
  EXPECT_TRUE(refused.pieces.empty());
  EXPECT_NE(refused.error.find("star-shaped"), std::string::npos);
}

// The surface Box2D collides is the case's: for an ellipse at 30 deg built
// from its 180-point outline, every outline point lies on the skinned
// surface of the fixtures, and every chord midpoint too (the skinned pieces
// keep the outline's edges). Tolerance: the skin rounds each vertex, which
// ends up r (1/cos(phi/2) - 1) inside it (phi the outline's turning angle
// there, largest at the tips: 5.6 deg, 1.2e-5 m), plus float rounding of
// 1 m coordinates (1e-6 m).
TEST(Box2dGeometry, SkinnedEllipseFixturesHaveTheOutlineSurface) {
  b2World world(b2Vec2(0.0f, 0.0f));
  const Vec2 centre(0.4, 1.1);
  const double angle = kPi / 6.0;
  const double a = 0.7071;
  const double b = 0.25;
  const Body e = box2d_test::ellipse_body("e", a, b, 1.0, centre, angle);
  const b2BodyDef def = body_def(e);
  b2Body* body = world.CreateBody(&def);
  const nlohmann::json j = add_fixtures(*body, e, FixtureOptions{});
  EXPECT_EQ(j.at("fixtures").get<int>(), 30);
  std::vector<Vec2> outline;
  for (int k = 0; k < 180; ++k) {
    const double t = 2 * kPi * k / 180;
    outline.emplace_back(a * std::cos(t), b * std::sin(t));
  }
  double phi_max = 0.0;
  for (std::size_t k = 0; k < 180; ++k) {
    const Vec2 e1 = outline[k] - outline[(k + 179) % 180];
    const Vec2 e2 = outline[(k + 1) % 180] - outline[k];
    phi_max = std::max(phi_max, std::acos(e1.dot(e2) / (e1.norm() * e2.norm())));
  }
  const double tol = skin_m() * (1.0 / std::cos(phi_max / 2) - 1.0) + 1e-6;
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  auto to_world = [&](const Vec2& p) {
    return Vec2(centre + Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()));
  };
  for (std::size_t k = 0; k < 180; ++k) {
    const Vec2& p0 = outline[k];
    const Vec2& p1 = outline[(k + 1) % 180];
    EXPECT_NEAR(skinned_distance(*body, to_world(p0)), 0.0, tol) << k;
    EXPECT_NEAR(skinned_distance(*body, to_world(0.5 * (p0 + p1))), 0.0, 1e-6) << k;
  }
  // a point 0.1 m outside the tip along the major axis is 0.1 m away
  EXPECT_NEAR(skinned_distance(*body, to_world(Vec2(a + 0.1, 0.0))), 0.1, tol);
}

// A half-plane at -30 deg becomes a chain whose skinned surface is the line:
// a point at height h along the normal is h away, wherever it is along the
// line within the chain's reach. Tolerance: float rounding of coordinates up
// to 30 m (8 eps_f 30 m = 3e-5 m).
TEST(Box2dGeometry, HalfPlaneChainSurfaceIsTheLine) {
  b2World world(b2Vec2(0.0f, 0.0f));
  const double angle = -kPi / 6.0;
  const Body g = box2d_test::ground_body(angle);
  const b2BodyDef def = body_def(g);
  b2Body* body = world.CreateBody(&def);
  FixtureOptions opt;
  opt.half_plane_half_length_m = 35.0;
  const nlohmann::json j = add_fixtures(*body, g, opt);
  EXPECT_EQ(j.at("skin_offset_m").get<double>(), -skin_m());
  const Vec2 tangent(std::cos(angle), std::sin(angle));
  const Vec2 normal(-std::sin(angle), std::cos(angle));
  for (const double along : {-30.0, -12.3, 0.0, 4.9, 10.0, 29.0}) {
    for (const double h : {0.02, 0.5, 2.0}) {
      const Vec2 q = along * tangent + h * normal;
      EXPECT_NEAR(skinned_distance(*body, q), h, 8 * kEpsF * 30.0) << along << " " << h;
    }
  }
}

// circles carry no skin: a b2CircleShape of the case radius
TEST(Box2dGeometry, CircleIsExact) {
  b2World world(b2Vec2(0.0f, 0.0f));
  const Body d = box2d_test::disk_body("d", 0.5, 1.0, Vec2(1.0, 2.0));
  const b2BodyDef def = body_def(d);
  b2Body* body = world.CreateBody(&def);
  add_fixtures(*body, d, FixtureOptions{});
  EXPECT_NEAR(skinned_distance(*body, Vec2(1.0, 3.0)), 0.5, 4 * kEpsF * 3.0);
  const b2Fixture* f = body->GetFixtureList();
  EXPECT_EQ(f->GetFriction(), 0.0f);
  EXPECT_EQ(f->GetRestitution(), 0.0f);
  EXPECT_EQ(f->GetDensity(), 0.0f);
}

// an outline finer than Box2D's weld distance (0.5 b2_linearSlop = 2.5 mm)
// is refused with a clear error rather than silently welded
TEST(Box2dGeometry, TooFineOutlineIsAnEngineError) {
  b2World world(b2Vec2(0.0f, 0.0f));
  Body d = box2d_test::ellipse_body("fine", 0.1, 0.05, 1.0, Vec2::Zero(), 0.0);
  d.outline_points = 720;  // ~0.6 mm spacing
  const b2BodyDef def = body_def(d);
  b2Body* body = world.CreateBody(&def);
  EXPECT_THROW(add_fixtures(*body, d, FixtureOptions{}), EngineError);
}

// shapes Box2D cannot build are named with a reason; the rest are not
TEST(Box2dGeometry, UnsupportedShapeReasons) {
  Body moving_plane = box2d_test::ground_body();
  moving_plane.fixed = false;
  EXPECT_FALSE(unsupported_shape_reason(moving_plane).empty());
  EXPECT_TRUE(unsupported_shape_reason(box2d_test::ground_body()).empty());
  EXPECT_TRUE(unsupported_shape_reason(box2d_test::disk_body("d", 1, 1, Vec2::Zero())).empty());
  Body c_shape;
  c_shape.name = "c";
  // C shape with its centroid in the mouth: not star-shaped from the centroid
  c_shape.shape = Polygon{{{0.6, -1},
                           {0.6, -0.5},
                           {-0.9, -0.5},
                           {-0.9, 0.5},
                           {0.6, 0.5},
                           {0.6, 1},
                           {-1.4, 1},
                           {-1.4, -1}}};
  // not a fan, but CGAL's convex pieces take it (at most 8 points each)
  EXPECT_TRUE(unsupported_shape_reason(c_shape).empty()) << unsupported_shape_reason(c_shape);
  // a concave polygon with a prong thinner than Box2D's skin cannot keep its
  // edges: refused, naming the skin
  Body thin;
  thin.name = "thin";
  thin.shape = Polygon{{{-1, 0}, {1, 0}, {1, 0.015}, {0.0, 0.015}, {0.0, 1}, {-1, 1}}};
  EXPECT_NE(unsupported_shape_reason(thin).find("skin"), std::string::npos)
      << unsupported_shape_reason(thin);
  EXPECT_EQ(bounding_radius_m(Ellipse{0.3, 0.7}), 0.7);
}

}  // namespace
}  // namespace pb::internal::box2d
