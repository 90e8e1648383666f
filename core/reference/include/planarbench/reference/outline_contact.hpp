// Contact detection on outlines, brute force (paper §2.1.1, Fig. 1). This is
// the faithful O(N M) search and the oracle: the engine's default search,
// FastOutlineContactSearch (fast_outline_contact.hpp, setting detection =
// fast), returns the same result and is tested against this one; this one
// stays selectable with detection = brute. Both share their arithmetic
// (src/outline_kernels.hpp).
//
// What the paper does. Every body is a closed list of outline points. First
// the pair of points (one on each body) with the least distance is found;
// then the neighbouring points of that pair are used (projection onto the
// adjacent edges) to find the true closest points of the two polylines, which
// may lie between the given points. Contact is declared when that distance
// reaches "zero" (1e-10 m in the paper; ContactPair::threshold_m here).
//
// What this file computes, and why it is a superset of the paper's two stages:
// * Apart. The closest points of two disjoint polylines are always an outline
//   point of one and a point on an edge of the other. Projecting every outline
//   point onto every edge of the other outline (both ways) therefore gives the
//   exact polyline distance. The paper's refinement, which projects only onto
//   the edges next to the closest point pair, reaches the same answer when the
//   closest edges are next to that pair - true for dense outlines of smooth
//   shapes, false e.g. for a coarse square against a circle (see
//   paper_two_stage_distance below and its test). Same O(N M) cost as the
//   paper's first stage.
// * Overlapping. An outline point of one body lies inside the other (crossing
//   number test). Its depth is its distance to the other body's boundary
//   polyline. The penetration delta is the largest depth over every outline
//   point of either body inside the other; the normal is that of the deepest
//   point's nearest boundary feature (below).
// * Contact points when overlapping. The force acts at the depth-weighted
//   centroid p = sum(d_i p_i) / sum(d_i) of the outline points of one body
//   inside the other (d_i their depths), and at p -/+ delta n on the other
//   body, so that the pair lies on one line of action along n (SPEC §1, one
//   force per pair). The body is the one with more points inside the other
//   (ties: the body of the deepest point overall); with a single point inside,
//   p is the deepest point itself. The sum runs first over the run of
//   consecutive inside points around that body's deepest point, then over its
//   other inside points in index order (other overlap regions of a concave
//   body), so a single region's sum is always taken in the same order. Why not
//   the deepest point always: when two neighbouring outline points are equally
//   deep (a polygon edge flat on a line, e.g. the 180-point disk of the
//   sliding case, whose contact normal falls between two points), the force
//   jumps from one to the other, each jump turns the polygon so that the other
//   gets deeper, and the switching accelerates without bound (Zeno chatter;
//   rk45 steps fell to 1e-9 s). The same happens between the regions of a
//   concave body pressed in at several places (an arch on both feet) when only
//   one region carries the force. The weighted centroid moves continuously
//   (points enter and leave with zero weight), and the body with more points
//   inside is the better sampled side of the overlap (a sparse ground
//   outline's single point under a flat chord ties in depth with the disk's
//   points and would otherwise steal the line of action).
// * Several overlapping regions (concave bodies): one contact per pair; delta
//   and the normal are those of the deepest point over all regions, the point
//   of action the weighted centroid over all of them (above). delta is
//   continuous in time; the normal jumps when another region becomes the
//   deepest.
// * Limits. Every overlap region bounded by two edge crossings holds an outline
//   point of one body inside the other, so shallow contact is always seen. A
//   deep crossing without any outline point inside (two thin bars crossed like
//   "+") is not seen. A point deep inside a concave body is pushed to its
//   nearest boundary, which may be the far side (as in every penetration-based
//   method).
// The half-plane's outline is its surface segment (make_outline), closed into a
// simple polygon by one extra point extent/2 below its middle; it is valid for
// contacts within the extent of the segment.
#pragma once

#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reference/contact_geometry.hpp"

namespace pb {

// Outline of a shape as a closed simple polygon in its body frame,
// counter-clockwise: make_outline(shape, n), plus the closing point of a
// half-plane (see above).
[[nodiscard]] std::vector<Vec2> contact_outline(const Shape& shape, int n);

// An outline placed in the world, structure of arrays for the O(N M) sweep.
struct WorldOutline {
  std::vector<double> x, y;          // m, vertex i; n + 1 entries (vertex 0 repeated last)
  std::vector<double> ex, ey;        // m, edge i: vertex i -> vertex i+1
  std::vector<double> inv_len2;      // 1/m^2, 1 / |edge i|^2 (0 for a degenerate edge)
  std::vector<double> nx, ny;        // unit outward normal of edge i
  std::vector<double> x_per_y;       // -, ex / ey of edge i (0 for a horizontal edge)
  double min_x = 0.0, max_x = 0.0;   // m, bounding box
  double min_y = 0.0, max_y = 0.0;   // m
  [[nodiscard]] int size() const { return static_cast<int>(ex.size()); }  // n
};

// Places body-frame points in the world (no allocation once sized).
void place_outline(const std::vector<Vec2>& local_m, const Pose& pose, WorldOutline& out);

// Nearest point of a polygon's boundary to a point, and whether the point is inside.
struct BoundaryHit {
  double distance_m = 0.0;  // m, to the boundary polyline
  int edge = -1;            // edge holding the nearest point
  double t = 0.0;           // position on that edge, [0, 1]
  bool inside = false;      // crossing-number test
};
[[nodiscard]] BoundaryHit nearest_boundary_point(double px, double py, const WorldOutline& poly);

// The brute-force search of one pair, with its scratch space (no allocation
// per evaluation).
// Whose inside points place the line of action of two overlapping outlines
// (their depth-weighted centroid, SPEC §1): the body with more of them (the
// paper's rule, `more`), or always body a's / body b's (a pair with friction
// on a half-plane: the half-plane's points sample a straight line at a spacing
// set by its extent, the body's outline is its shape; pair_geometry.hpp), or
// body a's / b's when that body (a polygon, its points its vertices) has
// exactly one point inside and the other's points sample a line or curve
// (vertex_a / vertex_b: a vertex contact acts at the vertex; else `more`), or
// every inside point of both bodies (`both`: continuous as points come and
// go; outline_kernels.hpp, place_line_of_action)
enum class ActionPoints { more, a, b, vertex_a, vertex_b, both };

class OutlineContactSearch {
 public:
  // outlines in their body frames, closed, counter-clockwise
  OutlineContactSearch(std::vector<Vec2> outline_a_m, std::vector<Vec2> outline_b_m);
  void set_action_points(ActionPoints rule) { action_points_ = rule; }

  [[nodiscard]] ContactGeometry evaluate(const Pose& pose_a, const Pose& pose_b);
  // the same on outlines already placed in the world
  [[nodiscard]] ContactGeometry evaluate_placed(const WorldOutline& a, const WorldOutline& b);

 private:
  std::vector<Vec2> local_a_;
  std::vector<Vec2> local_b_;
  WorldOutline world_a_;
  WorldOutline world_b_;
  std::vector<BoundaryHit> hits_a_;  // outline point i of a against b's boundary
  std::vector<BoundaryHit> hits_b_;
  std::vector<int> inside_ids_;  // scratch: inside point indices of one body
  ActionPoints action_points_ = ActionPoints::more;
};

// The paper's two stages taken literally, for comparison only: the closest
// pair of outline points, then projection onto the edges adjacent to that
// pair. Returns the distance it finds (>= the polyline distance). Valid for
// disjoint outlines.
[[nodiscard]] double paper_two_stage_distance(const WorldOutline& a, const WorldOutline& b);

}  // namespace pb
