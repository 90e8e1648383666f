// Fuzz target for the outline geometry: core/src/outline.cpp (make_outline)
// and core/reference/src/outline_contact.cpp (contact_outline, place_outline,
// nearest_boundary_point, OutlineContactSearch, paper_two_stage_distance),
// fast_outline_contact.cpp (FastOutlineContactSearch).
// The bytes decode to two shapes with poses (outline_fuzz_input.hpp).
//
// Checked, for the finite inputs the case loader accepts:
// * outlines: the promised point count, finite points, circle points on the
//   circle, the half-plane segment from +extent/2 to -extent/2, closed
//   outlines counter-clockwise (positive area);
// * the search: finite outputs, a unit normal, |point_a - point_b| = |gap|
//   and gap = normal . (point_b - point_a) (contact_geometry.hpp; for
//   |gap| above kDirectionFloor), the gap
//   unchanged when the bodies are swapped or both moved rigidly, the paper's
//   two-stage distance >= the gap when apart, and the gap equal to that of a
//   naive search written here apart from outline_contact.cpp (every outline
//   point against every edge of the other outline, winding-number inside test);
// * nearest_boundary_point against the same naive distance and inside test;
// * the fast search (fast_outline_contact.hpp) against the brute force, fresh,
//   after a motion (with its history) and with the bodies swapped;
// * the closed form for a convex outline on a half-plane
//   (convex_line_contact.hpp), wherever it answers, fresh and after the
//   motion: a consistent geometry with the brute force's gap. Its points are
//   not compared: where the brute force's deepest or closest point is picked
//   by rounding (level faces) they may differ by design, as its test states.
// Only geometry that doubles resolve is checked: every outline's feature size
// (shortest edge, least distance of a point to another edge) at least
// kResolvable times the largest coordinate of the input. Below that (a
// 1e-13 m triangle, or a 4016 m x 3e-13 m ellipse, 5e4 m from the origin) the
// placed outline collapses onto rounded points, is no longer simple, and
// nothing above holds; no case is near that.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <typeinfo>
#include <utility>
#include <variant>
#include <vector>

#include "fuzz_check.hpp"
#include "outline_fuzz_input.hpp"
#include "planarbench/outline.hpp"
#include "planarbench/reference/contact_geometry.hpp"
#include "planarbench/reference/convex_line_contact.hpp"
#include "planarbench/reference/fast_outline_contact.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace {

using pb::Vec2;
using pb::WorldOutline;

// Tolerances, as multiples of the largest world coordinate magnitude S of the
// pair: the search and the naive search below compute the same distances by
// different roundings of coordinates of size S, each off by a few ulp of S
// (2.2e-16 S); 1e-12 S is ~4500 ulp, far above that and far below any
// geometric feature checked (kResolvable below).
constexpr double kRelativeTolerance = 1e-12;
// moving both bodies rigidly re-rounds every coordinate (up to ~1e6 m after
// the move): the gap may change by a few ulp of the larger scale
constexpr double kMotionTolerance = 1e-10;
// |normal| - 1: the normal is normalised once, a few ulp
constexpr double kUnitTolerance = 1e-12;
// feature size / largest coordinate: features of ~4.5e9 ulp, so that a
// placed outline keeps its shape to ~1e-10 of its features
constexpr double kResolvable = 1e-6;
// below |gap| = 1e-12 (1 + |p|) m the search takes a vertex's normal as the
// mean of its edges' normals, not the direction between the two points
// (outline_kernels.hpp, hit_geometry): gap = normal . (point_b - point_a)
// then holds only to that distance
constexpr double kDirectionFloor = 1e-12;  // m, and relative to |p|
// the fast search against the brute force: the same numbers bit for bit by
// design (fast_outline_contact.hpp); 1e-9 m, or 1e-9 of the scene when it is
// smaller than 1 m, leaves room only for a different choice among exact ties
constexpr double kFastTolerance = 1e-9;

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

// largest |coordinate| of the outlines, m (never 0)
double coordinate_scale(const WorldOutline& a, const WorldOutline& b) {
  double s = std::numeric_limits<double>::min();
  for (const WorldOutline* w : {&a, &b}) {
    for (std::size_t i = 0; i < w->x.size(); ++i) {
      s = std::max({s, std::abs(w->x[i]), std::abs(w->y[i])});
    }
  }
  return s;
}

// ---- the naive search, written apart from outline_contact.cpp --------------
// (plain doubles: Eigen's expression templates, not inlined under the
// sanitizers, made this the target's hot spot)

Vec2 vertex(const WorldOutline& w, int i) {
  return Vec2(w.x[static_cast<std::size_t>(i)], w.y[static_cast<std::size_t>(i)]);
}

// distance from (px, py) to the segment (sx, sy) -> (ex, ey)
double segment_distance(double px, double py, double sx, double sy, double ex, double ey) {
  const double dx = ex - sx;
  const double dy = ey - sy;
  const double len2 = dx * dx + dy * dy;
  double t = 0.0;
  if (len2 > 0.0) t = std::min(1.0, std::max(0.0, ((px - sx) * dx + (py - sy) * dy) / len2));
  const double rx = px - (sx + t * dx);
  const double ry = py - (sy + t * dy);
  return std::sqrt(rx * rx + ry * ry);
}

// distance from p to the closed polyline of w
double boundary_distance(const Vec2& p, const WorldOutline& w) {
  const double* x = w.x.data();
  const double* y = w.y.data();
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < w.size(); ++j) {
    best = std::min(best, segment_distance(p.x(), p.y(), x[j], y[j], x[j + 1], y[j + 1]));
  }
  return best;
}

// winding number of the closed polyline around p, nonzero = inside
// (D. Sunday, "Inclusion of a point in a polygon", 2001)
bool winding_inside(const Vec2& p, const WorldOutline& w) {
  const double* x = w.x.data();
  const double* y = w.y.data();
  int wn = 0;
  for (int j = 0; j < w.size(); ++j) {
    const double side = (x[j + 1] - x[j]) * (p.y() - y[j]) - (p.x() - x[j]) * (y[j + 1] - y[j]);
    if (y[j] <= p.y()) {
      if (y[j + 1] > p.y() && side > 0.0) ++wn;
    } else if (y[j + 1] <= p.y() && side < 0.0) {
      --wn;
    }
  }
  return wn != 0;
}

// what the gap must be: -(largest depth) when some outline point lies inside
// the other outline by more than `tol`, else the least distance; `unsure`
// when the answer hangs on a point within `tol` of the other boundary
struct NaiveGap {
  double gap_m = 0.0;
  bool unsure = false;
};

NaiveGap naive_gap(const WorldOutline& a, const WorldOutline& b, double tol) {
  double deepest = -1.0;
  double closest = std::numeric_limits<double>::infinity();
  bool borderline = false;
  for (const auto& [own, other] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    for (int i = 0; i < own->size(); ++i) {
      const Vec2 p = vertex(*own, i);
      const double d = boundary_distance(p, *other);
      closest = std::min(closest, d);
      if (d <= tol) {
        borderline = true;
      } else if (winding_inside(p, *other)) {
        deepest = std::max(deepest, d);
      }
    }
  }
  if (deepest > 0.0) return {-deepest, false};
  return {closest, borderline};
}

// ---- the checks --------------------------------------------------------------

void check_outline(const pb::Shape& shape, int n) {
  const std::vector<Vec2> pts = pb::make_outline(shape, n);
  const std::vector<Vec2> closed = pb::contact_outline(shape, n);
  for (const auto& p : pts) PB_FUZZ_CHECK(finite(p));
  if (const auto* c = std::get_if<pb::Circle>(&shape)) {
    PB_FUZZ_CHECK(pts.size() == static_cast<std::size_t>(n));
    // on the circle: cos^2 + sin^2 = 1 to a few ulp
    for (const auto& p : pts) PB_FUZZ_CHECK(std::abs(p.norm() - c->radius_m) <= 8e-16 * c->radius_m);
  } else if (const auto* h = std::get_if<pb::HalfPlane>(&shape)) {
    PB_FUZZ_CHECK(pts.size() == static_cast<std::size_t>(n));
    PB_FUZZ_CHECK(pts.front() == Vec2(0.5 * h->extent_m, 0.0));
    PB_FUZZ_CHECK(pts.back() == Vec2(-0.5 * h->extent_m, 0.0));
    for (std::size_t k = 1; k < pts.size(); ++k) {
      PB_FUZZ_CHECK(pts[k].y() == 0.0 && pts[k].x() < pts[k - 1].x());
    }
    PB_FUZZ_CHECK(closed.size() == pts.size() + 1);
    PB_FUZZ_CHECK(closed.back() == Vec2(0.0, -0.5 * h->extent_m));
  } else if (std::holds_alternative<pb::Ellipse>(shape)) {
    PB_FUZZ_CHECK(pts.size() == static_cast<std::size_t>(n));
  }
  if (!std::holds_alternative<pb::HalfPlane>(shape)) PB_FUZZ_CHECK(closed == pts);
  // counter-clockwise: positive shoelace area
  double twice_area = 0.0;
  for (std::size_t i = 0; i < closed.size(); ++i) {
    const Vec2 u = closed[i] - closed[0];
    const Vec2 v = closed[(i + 1) % closed.size()] - closed[0];
    twice_area += u.x() * v.y() - v.x() * u.y();
  }
  PB_FUZZ_CHECK(twice_area > 0.0);
}

void check_placed(const std::vector<Vec2>& local, const WorldOutline& w) {
  const std::size_t n = local.size();
  PB_FUZZ_CHECK(w.size() == static_cast<int>(n) && w.x.size() == n + 1 && w.y.size() == n + 1);
  PB_FUZZ_CHECK(w.x[n] == w.x[0] && w.y[n] == w.y[0]);
  for (std::size_t i = 0; i <= n; ++i) {
    PB_FUZZ_CHECK(std::isfinite(w.x[i]) && std::isfinite(w.y[i]));
    PB_FUZZ_CHECK(w.min_x <= w.x[i] && w.x[i] <= w.max_x && w.min_y <= w.y[i] && w.y[i] <= w.max_y);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double len = std::hypot(w.nx[i], w.ny[i]);
    // a unit normal, or none for an edge of zero length
    PB_FUZZ_CHECK(std::abs(len - 1.0) <= kUnitTolerance || (len == 0.0 && w.inv_len2[i] == 0.0));
  }
}

void check_geometry(const pb::ContactGeometry& g, double tol) {
  PB_FUZZ_CHECK(std::isfinite(g.gap_m) && finite(g.normal) && finite(g.point_a_m) &&
                finite(g.point_b_m));
  PB_FUZZ_CHECK(std::abs(g.normal.norm() - 1.0) <= kUnitTolerance);
  PB_FUZZ_CHECK(std::abs((g.point_a_m - g.point_b_m).norm() - std::abs(g.gap_m)) <= tol);
  const double floor_m =
      kDirectionFloor * (1.0 + std::max(g.point_a_m.norm(), g.point_b_m.norm()));
  if (std::abs(g.gap_m) > floor_m) {
    PB_FUZZ_CHECK(std::abs(g.gap_m - g.normal.dot(g.point_b_m - g.point_a_m)) <= tol);
  }
}

// the fast search's answer is the brute force's
void check_same(const pb::ContactGeometry& fast, const pb::ContactGeometry& brute, double scale) {
  const double tol = kFastTolerance * std::min(1.0, scale);
  PB_FUZZ_CHECK(std::abs(fast.gap_m - brute.gap_m) <= tol);
  PB_FUZZ_CHECK((fast.normal - brute.normal).norm() <= kFastTolerance);
  PB_FUZZ_CHECK((fast.point_a_m - brute.point_a_m).norm() <= tol);
  PB_FUZZ_CHECK((fast.point_b_m - brute.point_b_m).norm() <= tol);
}

void check_probe(const Vec2& p, const WorldOutline& w, double tol) {
  const pb::BoundaryHit hit = pb::nearest_boundary_point(p.x(), p.y(), w);
  PB_FUZZ_CHECK(hit.edge >= 0 && hit.edge < w.size() && hit.t >= 0.0 && hit.t <= 1.0);
  const double naive = boundary_distance(p, w);
  PB_FUZZ_CHECK(std::abs(hit.distance_m - naive) <= tol);
  // the point it names is at that distance
  const Vec2 s = vertex(w, hit.edge);
  const Vec2 q = s + hit.t * (vertex(w, hit.edge + 1) - s);
  PB_FUZZ_CHECK(std::abs((q - p).norm() - hit.distance_m) <= tol);
  if (naive > tol) PB_FUZZ_CHECK(hit.inside == winding_inside(p, w));
}

// with PB_FUZZ_VERBOSE set: the decoded input and the search's answer, for
// triage of a crash input (replay it through the fuzz target)
bool verbose() { return std::getenv("PB_FUZZ_VERBOSE") != nullptr; }

void print_body(const char* label, const pb::fuzz::FuzzBody& b) {
  std::fprintf(stderr, "%s: %s n=%d pose=(%.17g, %.17g, %.17g rad)\n", label,
               pb::shape_type_name(b.shape), b.outline_points, b.pose.position_m.x(),
               b.pose.position_m.y(), b.pose.angle_rad);
  for (const auto& p : pb::contact_outline(b.shape, b.outline_points)) {
    std::fprintf(stderr, "  %.17g %.17g\n", p.x(), p.y());
  }
}

void print_geometry(const char* label, const pb::ContactGeometry& g) {
  std::fprintf(stderr, "%s: gap=%.17g normal=(%.17g, %.17g) a=(%.17g, %.17g) b=(%.17g, %.17g)\n",
               label, g.gap_m, g.normal.x(), g.normal.y(), g.point_a_m.x(), g.point_a_m.y(),
               g.point_b_m.x(), g.point_b_m.y());
}

// the feature size of a closed outline, m: its shortest edge and the least
// distance of a point to an edge not its own (the width of a spike, the
// thickness of a sliver)
double feature_size(const std::vector<Vec2>& pts) {
  const std::size_t n = pts.size();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    best = std::min(best, (pts[(i + 1) % n] - pts[i]).norm());
    for (std::size_t j = 0; j < n; ++j) {
      // edge j runs from point j to point j + 1
      if (j == i || (j + 1) % n == i) continue;
      const Vec2& s = pts[j];
      const Vec2& e = pts[(j + 1) % n];
      best = std::min(best, segment_distance(pts[i].x(), pts[i].y(), s.x(), s.y(), e.x(), e.y()));
    }
  }
  return best;
}

void run(const pb::fuzz::FuzzInput& in) {
  if (verbose()) {
    print_body("a", in.a);
    print_body("b", in.b);
  }
  check_outline(in.a.shape, in.a.outline_points);
  check_outline(in.b.shape, in.b.outline_points);
  const std::vector<Vec2> la = pb::contact_outline(in.a.shape, in.a.outline_points);
  const std::vector<Vec2> lb = pb::contact_outline(in.b.shape, in.b.outline_points);

  WorldOutline wa;
  WorldOutline wb;
  pb::place_outline(la, in.a.pose, wa);
  pb::place_outline(lb, in.b.pose, wb);
  check_placed(la, wa);
  check_placed(lb, wb);
  const double scale = std::max(coordinate_scale(wa, wb), in.probe_m.cwiseAbs().maxCoeff());
  const double tol = kRelativeTolerance * scale;

  // both bodies moved by one rigid motion: rotation about the origin, then shift
  const Eigen::Matrix2d turn = pb::Pose{Vec2::Zero(), in.turn_rad}.rotation();
  const pb::Pose ma{turn * in.a.pose.position_m + in.shift_m, in.a.pose.angle_rad + in.turn_rad};
  const pb::Pose mb{turn * in.b.pose.position_m + in.shift_m, in.b.pose.angle_rad + in.turn_rad};
  WorldOutline wma;
  WorldOutline wmb;
  pb::place_outline(la, ma, wma);
  pb::place_outline(lb, mb, wmb);
  const double moved_scale = std::max(scale, coordinate_scale(wma, wmb));

  // geometry below the resolution of doubles at this scale: not checked
  if (std::min(feature_size(la), feature_size(lb)) < kResolvable * moved_scale) return;

  // the search, and the same pair seen from b
  pb::OutlineContactSearch ab(la, lb);
  const pb::ContactGeometry g = ab.evaluate(in.a.pose, in.b.pose);
  if (verbose()) print_geometry("a-b", g);
  check_geometry(g, tol);
  pb::OutlineContactSearch ba(lb, la);
  const pb::ContactGeometry h = ba.evaluate(in.b.pose, in.a.pose);
  if (verbose()) print_geometry("b-a", h);
  check_geometry(h, tol);
  PB_FUZZ_CHECK(std::abs(g.gap_m - h.gap_m) <= tol);

  // against the naive search
  const NaiveGap naive = naive_gap(wa, wb, tol);
  if (naive.unsure) {
    PB_FUZZ_CHECK(std::abs(g.gap_m) <= 2.0 * tol);
  } else {
    PB_FUZZ_CHECK(std::abs(g.gap_m - naive.gap_m) <= tol);
  }
  if (g.gap_m > 0.0) PB_FUZZ_CHECK(pb::paper_two_stage_distance(wa, wb) >= g.gap_m - tol);

  // the same pair after the rigid motion
  const pb::ContactGeometry m = ab.evaluate(ma, mb);
  if (verbose()) print_geometry("moved", m);
  check_geometry(m, kRelativeTolerance * moved_scale);
  PB_FUZZ_CHECK(std::abs(m.gap_m - g.gap_m) <= kMotionTolerance * moved_scale);

  // the fast search: fresh, then after the motion (its history is the first
  // pose), then with the bodies swapped
  pb::FastOutlineContactSearch fast_ab(la, lb);
  const pb::ContactGeometry fg = fast_ab.evaluate(in.a.pose, in.b.pose);
  if (verbose()) print_geometry("fast a-b", fg);
  check_same(fg, g, scale);
  const pb::ContactGeometry fm = fast_ab.evaluate(ma, mb);
  if (verbose()) print_geometry("fast moved", fm);
  check_same(fm, m, moved_scale);
  pb::FastOutlineContactSearch fast_ba(lb, la);
  const pb::ContactGeometry fh = fast_ba.evaluate(in.b.pose, in.a.pose);
  if (verbose()) print_geometry("fast b-a", fh);
  check_same(fh, h, scale);

  // the closed form, where it applies and answers
  if (auto closed = pb::ConvexLineContact::make(in.a.shape, in.a.outline_points, in.b.shape,
                                                in.b.outline_points)) {
    if (const auto cg = closed->evaluate(in.a.pose, in.b.pose)) {
      if (verbose()) print_geometry("closed a-b", *cg);
      check_geometry(*cg, tol);
      PB_FUZZ_CHECK(std::abs(cg->gap_m - g.gap_m) <= tol);
    }
    if (const auto cm = closed->evaluate(ma, mb)) {
      if (verbose()) print_geometry("closed moved", *cm);
      check_geometry(*cm, kRelativeTolerance * moved_scale);
      PB_FUZZ_CHECK(std::abs(cm->gap_m - m.gap_m) <= kRelativeTolerance * moved_scale);
    }
  }

  // one point against b's boundary
  check_probe(in.probe_m, wb, tol);
  check_probe(in.probe_m, wa, tol);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto in = pb::fuzz::decode(data, size);
    if (in) run(*in);
  } catch (const std::exception& e) {
    // nothing here may throw for inputs the loader accepts
    std::fprintf(stderr, "unexpected exception %s: %s\n", typeid(e).name(), e.what());
    __builtin_trap();
  }
  return 0;
}
