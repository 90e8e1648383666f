// Contact detection on outlines, closed form: a strictly convex outline
// against a half-plane's surface, in O(1) per evaluation along a trajectory
// (O(log N) for a cold start). The engine's default (`detection = fast`) for
// such a pair; every other pair, and every pose this one cannot decide for
// certain, goes to the tree search (fast_outline_contact.hpp). Its oracle is
// the brute force (outline_contact.hpp, whose header says what is computed
// and why): the same gap, normal and contact points to a stated tolerance
// (tests/reference/convex_line_contact_test.cpp), not to the bit.
//
// Why it can be closed form. Let the convex outline C have body-frame
// vertices q_i and the half-plane's surface the world normal n through the
// point x_L. With m = R_C^T n and s = n . (x_C - x_L), the height of vertex i
// above the line is h_i = m . q_i + s: affine in the pose. Along a strictly
// convex outline h_i has one minimum and one maximum and is monotone between
// them (two chains). Hence:
// * The deepest vertex k (least h) is a local minimum: found by walking
//   downhill from the last evaluation's (O(1) while the pose moves little),
//   or cold by a binary search of the edge normals' angles (they increase
//   along a convex counter-clockwise outline).
// * Apart (h_k >= 0) the outlines' distance is h_k: no vertex of C is nearer
//   the line, and no surface vertex is nearer C than C's lowest vertex is to
//   the line (C lies above it). The closest points are vertex k and its foot.
// * Overlapping, the vertices of C inside the half-plane are one run
//   lo .. hi around k (h < 0), whose ends are found on the two monotone chains
//   by walking from the last ends or by binary search. Their depths d_i = -h_i
//   are the brute force's depths (the nearest boundary feature of a point
//   below the surface is the surface, as checked below), so
//     sum d_i     = -(m . S1 + count s),
//     sum d_i q_i = -(S2 m + s S1),
//   S1 = sum q_i and S2 = sum q_i q_i^T over the run, from prefix sums of the
//   body-frame vertices and their second moments (long double: the
//   difference of two prefix sums then carries ~1e-19 relative error of the
//   whole outline's sums). Runs of up to kDirectSumPoints points are summed
//   directly instead, where a small depth sum would magnify that error.
// * The surface vertices inside C lie on the chord between the two crossings
//   of C's boundary with the line; they are counted by a binary search of
//   the surface vertices' positions (sorted). None is deeper than vertex k
//   (its distance to C's boundary is at most its vertical distance to the
//   boundary, less than C's depth unless C's lowest edge is level with the
//   line: level faces, below). The brute force's line of action is the
//   depth-weighted centroid of C's run when C has more points inside, and
//   that of the surface's points inside C when those are more (a polygon
//   lying on a finely sampled surface): then C must be a polygon of at most
//   kSurfaceSidePolygonVertices vertices and the surface points at most
//   kDirectSumPoints, each one's depth the least distance to the lines of
//   C's edges (C convex), summed point by point.
// Level faces. When a neighbour j of k is as deep as k to within the
// rounding of a depth (1e-13 of the scene's size + 1e-15 m), C has a face
// level with the surface (a polygon lying flat; the 180-point
// disk of sliding, whose lowest edge is parallel to its incline). Every
// point of that face, and every surface vertex above it, is then a deepest
// or closest point within rounding, and the brute force picks one by its
// rounding and sweep order. The closed form answers with vertex k (apart)
// or the same centroid (overlapping) when the face is level to within
// kLevelTilt = 1e-10 rad: the brute force's normal is then the surface's or
// the face's, which differ by at most that angle, and its gap is the same
// to rounding. Its closest points apart may be any point of the face
// (tested as such). The same ill-conditioning reaches a little past the
// level band: a surface vertex within ~1e-14 m / tilt of vertex k along the
// line is as deep as k to rounding, and the brute force may then report the
// face's normal, tilted from the surface's by the face's tilt.
// What is refused (nullopt: the caller asks the tree search), so that the
// answer is never a guess:
// * a face nearly level: tied in depth but tilted by more than kLevelTilt
//   (a band of 1e-10 .. ~1e-10 rad for the cases' outlines);
// * C not wholly over the surface segment, or so deep that the closing edges
//   of the half-plane's outline (contact_outline: the point extent/2 below the
//   middle, edges at 45 deg) could be nearer than the surface: the whole of C
//   (its bounding circle about the body origin) must lie along the line within
//   extent/2 - (1 + sqrt 2) delta of the middle;
// * an overlap where neither side has more points inside the other for
//   certain (every point within the margin of the boundary counted on the
//   side that could flip the decision), or where the surface's side has more
//   than the bounds above allow.
// The margin, for counting points near the boundary, is that of the tree
// search: 1e-10 times the scene's coordinate size plus 1e-12 m.
// Hot path: no allocation, no throw.
#pragma once

#include <optional>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reference/contact_geometry.hpp"

namespace pb {

// what one evaluation did, to check the cost without a clock
struct LineSearchWork {
  int heights = 0;       // vertex heights computed by walks and searches
  int summed_points = 0; // points summed one by one (runs of up to kDirectSumPoints)
  int surface_probes = 0;  // surface vertices looked at by the count's binary search
};

class ConvexLineContact {
 public:
  // runs of at most this many points are summed point by point
  static constexpr int kDirectSumPoints = 32;
  // the surface's points inside C are summed (up to kDirectSumPoints of them)
  // when C is a polygon of at most this many vertices
  static constexpr int kSurfaceSidePolygonVertices = 16;

  // The closed form for the pair (a, b) with outline point counts n_a, n_b,
  // or nullopt when it does not apply: not exactly one half-plane, or the
  // other shape's outline (contact_outline) not strictly convex.
  [[nodiscard]] static std::optional<ConvexLineContact> make(const Shape& a, int n_a, const Shape& b,
                                                             int n_b);

  // The pair's contact geometry (a, b in the order given to make), or
  // nullopt when the pose is one of those refused above.
  [[nodiscard]] std::optional<ContactGeometry> evaluate(const Pose& pose_a, const Pose& pose_b);

  // the next evaluation starts cold (binary searches)
  void forget_history() { has_history_ = false; }
  [[nodiscard]] const LineSearchWork& last_work() const { return work_; }

 private:
  ConvexLineContact(std::vector<Vec2> convex_m, std::vector<double> surface_x_m, double extent_m,
                    bool line_is_a);
  [[nodiscard]] double height(int i, const Vec2& m) {
    ++work_.heights;
    const Vec2& q = q_[static_cast<std::size_t>(i)];
    return m.x() * q.x() + m.y() * q.y();
  }
  [[nodiscard]] int next(int i) const { return i + 1 == n_ ? 0 : i + 1; }
  [[nodiscard]] int prev(int i) const { return i == 0 ? n_ - 1 : i - 1; }
  [[nodiscard]] int support(const Vec2& direction) const;  // vertex of largest direction . q
  int walk_down(int k, const Vec2& m);
  int walk_up(int k, const Vec2& m);
  int run_end(int k, int top, int step, int guess, const Vec2& m, double s);
  [[nodiscard]] int surface_count_between(double u0, double u1, double margin, int& ambiguous,
                                          int& first);
  Vec2 body_centroid(int lo, int hi, int count, const Vec2& m, double s, const Eigen::Matrix2d& r_body,
                     const Vec2& x_body, const Vec2& fallback);
  std::optional<Vec2> surface_centroid(int first, int count, const Eigen::Matrix2d& r_line,
                                       const Vec2& x_line, const Eigen::Matrix2d& r_body,
                                       const Vec2& x_body);

  std::vector<Vec2> q_;                   // m, convex outline, body frame, counter-clockwise
  std::vector<double> normal_angle_;      // rad, outward normal angle of edge i, increasing
  std::vector<long double> s1x_, s1y_;    // prefix sums of q (entry i: vertices 0 .. i-1)
  std::vector<long double> s2xx_, s2xy_, s2yy_;  // prefix sums of q q^T
  std::vector<double> surface_x_;         // m, surface vertices along the line, descending
  double radius_m_ = 0.0;                 // m, largest |q|
  double half_extent_m_ = 0.0;            // m
  int n_ = 0;
  bool line_is_a_ = false;
  bool has_history_ = false;
  int deepest_ = 0, highest_ = 0, lo_ = 0, hi_ = 0;  // last evaluation's vertices
  LineSearchWork work_;
};

}  // namespace pb
