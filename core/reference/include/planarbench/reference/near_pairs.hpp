// The reference's broad phase for contact groups (SPEC §11): the group pairs
// near enough that they may touch before the list is built again. A Verlet
// list over bounding boxes (Verlet 1967, the neighbour list of molecular
// dynamics; Ericson, "Real-Time Collision Detection", §7.5, for the sort
// and sweep): each group body's box is fattened by its margin, and the
// pairs whose fattened boxes overlap (a body and a half-plane: whose box
// comes within the margin of the surface) are listed. A pair not listed is
// apart by more than the two margins, so it cannot touch while each body has
// moved (|dx| + reach |d theta|, the farthest any of its material points has
// gone) less than its margin since the build. The solver rebuilds the list
// at a step's start once a body has moved half its margin, and rejects a
// trial step that would move one past its whole margin: no contact of a
// group is ever missed, and the narrow phase runs on near pairs only.
// Declared pairs are not listed here: they are always evaluated.
#pragma once

#include <vector>

#include "planarbench/broad_phase.hpp"
#include "planarbench/case.hpp"
#include "planarbench/contact_pairs.hpp"
#include "planarbench/reference/planar_model.hpp"

namespace pb {

// the margin a body's box is fattened by, as a fraction of its reach (the
// farthest material point from its centre): a quarter keeps a body's
// neighbour list to the bodies about touching it, and a body moving at 1 m/s
// with a reach of 5 cm rebuilds it every ~6 ms of simulated time, each
// rebuild O(n log n)
inline constexpr double kNearMarginFraction = 0.25;

class NearPairs {
 public:
  NearPairs(const Case& c, const PlanarModel& model);

  [[nodiscard]] bool empty() const { return members_.empty(); }
  // rebuilds the list at q when due (first call, or a body moved past half
  // its margin); the group pairs found are registered in `pairs` and their
  // indices written to `near` (ascending). Returns whether it rebuilt.
  bool update(ConstVectorRef q, ContactPairs& pairs, std::vector<int>& near);
  // the largest fraction of its margin any group body has moved at q since
  // the last build (>= 1: a contact could be missed)
  [[nodiscard]] double excursion(ConstVectorRef q) const;
  [[nodiscard]] long rebuilds() const { return rebuilds_; }

 private:
  struct Member {
    int body = -1;
    bool plane = false;     // a half-plane (fixed; tested against boxes)
    double reach_m = 0.0;   // m, farthest material point from the centre
    double margin_m = 0.0;  // m
  };
  const PlanarModel* model_;
  const std::vector<Body>* bodies_;
  std::vector<Member> members_;
  std::vector<Pose> built_at_;  // per member, its pose at the last build
  bool built_ = false;
  long rebuilds_ = 0;
  // scratch
  std::vector<Aabb> boxes_;
  std::vector<int> ids_, order_;
  std::vector<std::pair<int, int>> candidates_;
};

}  // namespace pb
