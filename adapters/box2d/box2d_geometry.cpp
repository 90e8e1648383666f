#include "box2d_geometry.hpp"

#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_common.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "box2d_frame.hpp"
#include "planarbench/convex_pieces.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/outline.hpp"
#include "planarbench/overloaded.hpp"

namespace pb::internal::box2d {

namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// outward unit normal of the edge a -> b of a counter-clockwise outline
Vec2 outward_normal(const Vec2& a, const Vec2& b) {
  const Vec2 e = (b - a).normalized();
  return Vec2(e.y(), -e.x());
}

// the turn a -> b -> c counts as a left turn only when clearly so: sin(turn)
// above 1e-6, so that Box2D's float hull (b2PolygonShape::Set) keeps b
bool left_turn(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 e1 = b - a;
  const Vec2 e2 = c - b;
  return cross(e1, e2) > 1e-6 * e1.norm() * e2.norm();
}

b2FixtureDef base_fixture_def(const FixtureOptions& o) {
  b2FixtureDef def;
  // frictionless (SPEC §2): Box2D mixes friction as sqrt(f1 f2), 0 on every fixture
  def.friction = 0.0f;
  // the restitution is set on each contact when it begins (box2d_world_callbacks)
  def.restitution = 0.0f;
  def.restitutionThreshold = static_cast<float>(o.restitution_threshold_mps);
  // mass data is set explicitly from the case (b2Body::SetMassData)
  def.density = 0.0f;
  def.isSensor = false;
  def.userData.pointer = static_cast<uintptr_t>(o.body_index) + 1;
  return def;
}

// one convex b2PolygonShape per fan piece. Box2D must keep every vertex, and
// Debian's libbox2d keeps its asserts: a piece it would weld or find
// degenerate aborts inside b2PolygonShape::Set, so it is checked first.
// why Box2D cannot take fan piece k of a body as a b2PolygonShape, or ""
std::string piece_error(const std::vector<Vec2>& piece, std::size_t k, const std::string& body_name) {
  const double weld_m = 0.5 * static_cast<double>(b2_linearSlop);  // b2PolygonShape::Set
  const int n = static_cast<int>(piece.size());
  double closest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      closest = std::min(
          closest, (piece[static_cast<std::size_t>(i)] - piece[static_cast<std::size_t>(j)]).norm());
    }
  }
  double twice_area = 0.0;  // m^2
  for (int i = 0; i < n; ++i) {
    twice_area +=
        cross(piece[static_cast<std::size_t>(i)], piece[static_cast<std::size_t>((i + 1) % n)]);
  }
  if (n > b2_maxPolygonVertices || !(closest > 1.01 * weld_m) || !is_convex_ccw(piece)) {
    return fmt::format(
        "body '{}': fan piece {} has vertices {:.3g} m apart; Box2D welds vertices closer than "
        "0.5 b2_linearSlop = {} m (b2PolygonShape::Set): use fewer outline_points, or a body "
        "thicker than Box2D's skin (2 x b2_polygonRadius = {} m), which its pieces are inset by",
        body_name, k, closest, weld_m, 2.0 * skin_m());
  }
  // b2PolygonShape's centroid asserts an area above b2_epsilon (float epsilon)
  if (!(0.5 * twice_area > 10.0 * static_cast<double>(b2_epsilon))) {
    return fmt::format("body '{}': fan piece {} has an area of {:.3g} m^2, below what "
                       "Box2D accepts (b2_epsilon); the body is too small for Box2D",
                       body_name, k, 0.5 * twice_area);
  }
  return {};
}

int add_polygon_pieces(b2Body& body, const std::vector<std::vector<Vec2>>& pieces,
                       const FixtureOptions& o, const std::string& body_name) {
  b2FixtureDef def = base_fixture_def(o);
  b2Vec2 vertices[b2_maxPolygonVertices];
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto& piece = pieces[k];
    const int n = static_cast<int>(piece.size());
    if (const std::string why = piece_error(piece, k, body_name); !why.empty()) {
      throw EngineError(why);
    }
    for (int i = 0; i < n; ++i) vertices[i] = to_b2(piece[static_cast<std::size_t>(i)]);
    b2PolygonShape shape;
    shape.Set(vertices, n);
    if (shape.m_count != n) {
      throw EngineError(fmt::format("body '{}': Box2D changed fan piece {} ({} vertices became {})",
                                    body_name, k, n, shape.m_count));
    }
    def.shape = &shape;
    body.CreateFixture(&def);
  }
  return static_cast<int>(pieces.size());
}

}  // namespace

double skin_m() {
  return static_cast<double>(b2_polygonRadius);
}

double linear_slop_m() {
  return static_cast<double>(b2_linearSlop);
}

std::vector<Vec2> inset_outline(const std::vector<Vec2>& outline, double r_m) {
  const std::size_t n = outline.size();
  std::vector<Vec2> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& prev = outline[(i + n - 1) % n];
    const Vec2& p = outline[i];
    const Vec2& next = outline[(i + 1) % n];
    const Vec2 n1 = outward_normal(prev, p);
    const Vec2 n2 = outward_normal(p, next);
    // intersection of the lines n1.x = n1.p - r and n2.x = n2.p - r
    const double denom = 1.0 + n1.dot(n2);
    out[i] = denom > 1e-9 ? Vec2(p - r_m * (n1 + n2) / denom) : Vec2(p - r_m * n1);
  }
  return out;
}

namespace {

// m, distance from p to the segment a-b
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// whether p lies inside the closed counter-clockwise polygon (even-odd rule)
bool inside(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool in = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      in = !in;
    }
  }
  return in;
}

// m, the least distance from the segment a-b to the polygon's outline, 0 when
// the segment leaves the polygon
double clearance_m(const std::vector<Vec2>& polygon, const Vec2& a, const Vec2& b) {
  if (!inside(polygon, a) || !inside(polygon, b)) return 0.0;
  double least = std::numeric_limits<double>::infinity();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = polygon[i];
    const Vec2& q = polygon[(i + 1) % n];
    // two segments inside one another's clearance: the least of the four
    // end-to-segment distances (they cannot cross: both ends lie inside)
    least = std::min({least, point_segment_distance(a, p, q), point_segment_distance(b, p, q),
                      point_segment_distance(p, a, b), point_segment_distance(q, a, b)});
  }
  return least;
}

}  // namespace

std::optional<std::vector<Vec2>> inset_piece(const std::vector<Vec2>& piece,
                                             const std::vector<Vec2>& polygon, double r_m) {
  const std::size_t np = polygon.size();
  // the half-planes n . x <= n . p - r of the polygon's edges that bound the
  // piece: the piece's own outline edges, and at each convex polygon corner
  // of the piece where a seam ends, the polygon's edges on both sides of it
  // (the one of the neighbouring piece too: the corner is the body's)
  std::vector<std::size_t> edges;  // polygon edge k: polygon[k] -> polygon[k + 1]
  for (const Vec2& p : piece) {
    // the partition's points are the polygon's own doubles (convex_pieces.hpp)
    const auto at = std::find(polygon.begin(), polygon.end(), p);
    if (at == polygon.end()) return std::nullopt;
    const auto k = static_cast<std::size_t>(at - polygon.begin());
    const std::size_t before = (k + np - 1) % np;
    if (left_turn(polygon[before], polygon[k], polygon[(k + 1) % np])) {
      edges.push_back(before);
      edges.push_back(k);
    } else {
      // a reflex corner: only the piece's own outline edges there
      const Vec2& next = piece[(static_cast<std::size_t>(&p - piece.data()) + 1) % piece.size()];
      const Vec2& prev =
          piece[(static_cast<std::size_t>(&p - piece.data()) + piece.size() - 1) % piece.size()];
      if (next == polygon[(k + 1) % np]) edges.push_back(k);
      if (prev == polygon[before]) edges.push_back(before);
    }
  }
  // the piece clipped by each half-plane (Sutherland-Hodgman on a convex
  // polygon: the result is their intersection, convex); its seams need no
  // clipping, the piece lies on its side of them
  double size = 0.0;  // m
  for (const Vec2& p : polygon) size = std::max(size, p.norm());
  // m: a point this close to a clipping line lies on it (two lines through
  // one corner, as at a corner the seam bisects, must give one vertex, not
  // two a rounding apart): 1e-12 of the body, far above the rounding of its
  // coordinates (1e-16 relative), far below Box2D's weld distance
  const double on_line = 1e-12 * size;
  std::vector<Vec2> core = piece;
  for (const std::size_t k : edges) {
    const Vec2 n = outward_normal(polygon[k], polygon[(k + 1) % np]);
    const double c = n.dot(polygon[k]) - r_m;
    std::vector<Vec2> kept;
    for (std::size_t i = 0; i < core.size(); ++i) {
      const Vec2& a = core[i];
      const Vec2& b = core[(i + 1) % core.size()];
      const double da = n.dot(a) - c;  // > 0: outside
      const double db = n.dot(b) - c;
      if (da <= on_line) kept.push_back(a);
      if ((da < -on_line && db > on_line) || (da > on_line && db < -on_line)) {
        kept.push_back(a + (da / (da - db)) * (b - a));
      }
    }
    core = std::move(kept);
    if (core.size() < 3) return std::nullopt;
  }
  // the skinned core must stay inside the outline: every core edge at least r
  // from it (1e-9 relative: the offset edges lie at r exactly, up to rounding)
  for (std::size_t i = 0; i < core.size(); ++i) {
    if (clearance_m(polygon, core[i], core[(i + 1) % core.size()]) < r_m * (1.0 - 1e-9)) {
      return std::nullopt;
    }
  }
  return core;
}

bool is_convex_ccw(const std::vector<Vec2>& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!left_turn(polygon[i], polygon[(i + 1) % n], polygon[(i + 2) % n])) return false;
  }
  return true;
}

Fan convex_fan(const std::vector<Vec2>& outline, const Vec2& centre, int max_outline_vertices) {
  Fan fan;
  const std::size_t n = outline.size();
  if (n < 3) {
    fan.error = "an outline needs at least 3 points";
    return fan;
  }
  // a small convex outline is one polygon as it stands
  if (static_cast<int>(n) <= max_outline_vertices + 1 && is_convex_ccw(outline)) {
    fan.pieces.push_back(outline);
    return fan;
  }
  // star-shaped from the centre: every triangle (centre, P_i, P_i+1) turns left
  for (std::size_t i = 0; i < n; ++i) {
    if (!left_turn(centre, outline[i], outline[(i + 1) % n])) {
      fan.error = fmt::format(
          "the outline is not star-shaped from its centre (edge {} -> {} is not seen from "
          "({:.6g}, {:.6g})): a fan of convex Box2D polygons cannot represent it",
          i, (i + 1) % n, centre.x(), centre.y());
      return fan;
    }
  }
  // greedy pieces: centre + consecutive outline vertices while convex
  std::size_t start = 0;
  std::size_t covered = 0;  // outline edges covered so far
  while (covered < n) {
    std::vector<Vec2> piece = {centre, outline[start], outline[(start + 1) % n]};
    std::size_t edges = 1;
    while (static_cast<int>(edges) < max_outline_vertices - 1 && covered + edges < n) {
      std::vector<Vec2> candidate = piece;
      candidate.push_back(outline[(start + edges + 1) % n]);
      if (!is_convex_ccw(candidate)) break;
      piece = std::move(candidate);
      ++edges;
    }
    fan.pieces.push_back(std::move(piece));
    covered += edges;
    start = (start + edges) % n;
  }
  return fan;
}

namespace {

// The convex Box2D polygons of an ellipse or a polygon, before any fixture
// is made: a convex outline inset by the skin and cut into a fan around the
// body origin (centre + up to kFanOutlineVertices outline points per piece);
// a non-convex polygon cut by CGAL into convex pieces of at most
// b2_maxPolygonVertices points (planarbench/convex_pieces.hpp), each clipped
// by the polygon's edges moved in by the skin (inset_piece). `error` says why Box2D cannot take it.
struct BodyPieces {
  std::vector<std::vector<Vec2>> pieces;
  std::string how;
  std::string error;
};

BodyPieces body_pieces(const Body& body) {
  BodyPieces out;
  const double skin = skin_m();
  const std::vector<Vec2> outline = make_outline(body.shape, body.outline_points);
  const auto* polygon = std::get_if<Polygon>(&body.shape);
  if (polygon == nullptr || pb::is_convex_ccw(polygon->points_m, 1e-12)) {
    const std::vector<Vec2> inset = inset_outline(outline, skin);
    Fan fan = convex_fan(inset, Vec2::Zero(), kFanOutlineVertices);
    if (!fan.error.empty()) {
      out.error = fmt::format("body '{}': {}", body.name, fan.error);
      return out;
    }
    out.pieces = std::move(fan.pieces);
    // a body thinner than two skins leaves degenerate pieces: refused before the run
    for (std::size_t k = 0; k < out.pieces.size(); ++k) {
      if (std::string why = piece_error(out.pieces[k], k, body.name); !why.empty()) {
        out.error = std::move(why);
        out.pieces.clear();
        return out;
      }
    }
    out.how = fmt::format(
        "{} convex b2PolygonShape pieces (the centre and up to {} consecutive outline points "
        "each, at most b2_maxPolygonVertices = {}) of the {}-point outline inset by the skin "
        "{} m, so that the skinned pieces' union has the outline's edges",
        out.pieces.size(), kFanOutlineVertices, b2_maxPolygonVertices, outline.size(), skin);
    return out;
  }
  const ConvexDecomposition parts = convex_pieces(polygon->points_m, b2_maxPolygonVertices);
  int whole = 0;  // pieces inset on every edge (their seams too)
  for (std::size_t k = 0; k < parts.pieces.size(); ++k) {
    // the piece clipped by the outline's edges moved in by the skin
    // (inset_piece); where that fails, the piece inset on its own
    std::optional<std::vector<Vec2>> core = inset_piece(parts.pieces[k], polygon->points_m, skin);
    if (!core || !is_convex_ccw(*core) ||
        static_cast<int>(core->size()) > b2_maxPolygonVertices) {
      core = inset_outline(parts.pieces[k], skin);
      ++whole;
    }
    std::vector<Vec2> inset = std::move(*core);
    if (!is_convex_ccw(inset)) {
      out.error = fmt::format(
          "body '{}': convex piece {} of the non-convex polygon is thinner than Box2D's skin "
          "(2 x b2_polygonRadius = {} m): its skinned polygon cannot have the piece's edges",
          body.name, k, 2.0 * skin);
      out.pieces.clear();
      return out;
    }
    out.pieces.push_back(std::move(inset));
  }
  out.how = fmt::format(
      "{} convex b2PolygonShape pieces of the non-convex {}-point polygon ({}; at most "
      "b2_maxPolygonVertices = {} points each), each piece clipped by the polygon's edges "
      "moved in by the skin {} m (its own, and both edges at a convex corner it shares), its "
      "seams kept, so that the skinned pieces have the polygon's edges, its reflex corners sharp "
      "and a corner two pieces share rounded as a convex corner is, by r (1/cos(phi/2) - 1) (phi its turning angle), not as each piece's sharper corner; "
      "{} of the pieces inset on their own instead (a seam's skin would leave the outline)",
      out.pieces.size(), polygon->points_m.size(), parts.method, b2_maxPolygonVertices, skin,
      whole);
  return out;
}

}  // namespace

std::string unsupported_shape_reason(const Body& body) {
  if (std::holds_alternative<HalfPlane>(body.shape)) {
    return body.fixed ? "" : "a moving half-plane has no Box2D counterpart (infinite surface)";
  }
  if (std::holds_alternative<Circle>(body.shape)) return "";
  return body_pieces(body).error;
}

double bounding_radius_m(const Shape& shape) {
  return std::visit(
      overloaded{[](const Circle& c) { return c.radius_m; },
                 [](const Ellipse& e) { return std::max(e.semi_axis_a_m, e.semi_axis_b_m); },
                 [](const Polygon& p) {
                   double r = 0.0;
                   for (const auto& q : p.points_m) r = std::max(r, q.norm());
                   return r;
                 },
                 [](const HalfPlane&) { return std::numeric_limits<double>::infinity(); }},
      shape);
}

nlohmann::json add_fixtures(b2Body& body, const Body& case_body, const FixtureOptions& options) {
  nlohmann::json j;
  j["shape"] = shape_type_name(case_body.shape);
  const double skin = skin_m();

  if (const auto* circle = std::get_if<Circle>(&case_body.shape)) {
    // a circle is exact in Box2D and has no skin
    b2CircleShape shape;
    shape.m_radius = static_cast<float>(circle->radius_m);
    shape.m_p.SetZero();
    b2FixtureDef def = base_fixture_def(options);
    def.shape = &shape;
    body.CreateFixture(&def);
    j["box2d"] = "b2CircleShape, exact radius, no skin";
    j["fixtures"] = 1;
    return j;
  }

  if (std::holds_alternative<HalfPlane>(case_body.shape)) {
    // a one-sided chain along the surface, its core one skin below it; the
    // chain runs from +x to -x so that its normal (to the right of the
    // direction of travel, b2_edge_shape.h) is the body's +y
    const double half = options.half_plane_half_length_m;
    const int segments = std::max(1, static_cast<int>(std::ceil(2.0 * half / kMaxSegment_m)));
    const double step = 2.0 * half / segments;
    std::vector<b2Vec2> vertices;
    for (int k = 0; k <= segments; ++k) {
      vertices.push_back(to_b2(Vec2(half - step * k, -skin)));
    }
    vertices.back() = to_b2(Vec2(-half, -skin));
    b2ChainShape chain;
    chain.CreateChain(vertices.data(), static_cast<int32>(vertices.size()),
                      to_b2(Vec2(half + step, -skin)), to_b2(Vec2(-half - step, -skin)));
    b2FixtureDef def = base_fixture_def(options);
    def.shape = &chain;
    body.CreateFixture(&def);
    j["box2d"] = fmt::format(
        "one-sided b2ChainShape of {} segments (<= {} m each, ghost vertices at both ends) "
        "from x = +{:.6g} m to -{:.6g} m of the body frame, its core moved {} m (the skin) "
        "below the surface so that the skinned edge is the surface",
        segments, kMaxSegment_m, half, half, skin);
    j["fixtures"] = 1;
    j["half_length_m"] = half;
    j["skin_offset_m"] = -skin;
    return j;
  }

  // ellipse, polygon: convex pieces, each inset by the skin
  const BodyPieces bp = body_pieces(case_body);
  if (!bp.error.empty()) throw EngineError(bp.error);
  const int pieces = add_polygon_pieces(body, bp.pieces, options, case_body.name);
  j["box2d"] = bp.how;
  j["fixtures"] = pieces;
  j["outline_points"] = make_outline(case_body.shape, case_body.outline_points).size();
  j["inset_m"] = skin;
  return j;
}

}  // namespace pb::internal::box2d
