// The contact geometry of one contact pair, as the setting `geometry` asks:
// outline points (the paper, outline_contact.hpp) or the exact shapes
// (exact_contact.hpp). Two polygons are exact as outlines in both modes.
// Outline points are searched as the setting `detection` asks: fast (the
// default) or brute (the brute-force oracle); both give the same result to
// the tolerance their tests state. fast is the closed form of
// convex_line_contact.hpp for a strictly convex outline on a half-plane
// wherever it can decide, and the trees of fast_outline_contact.hpp
// otherwise.
#pragma once

#include <optional>
#include <string>

#include "planarbench/case.hpp"
#include "planarbench/reference/contact_geometry.hpp"
#include "planarbench/reference/convex_line_contact.hpp"
#include "planarbench/reference/exact_contact.hpp"
#include "planarbench/reference/fast_outline_contact.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace pb {

enum class GeometryMode { outline, exact };
// how outline points are searched (same result, different cost)
enum class DetectionMode { fast, brute };

class PairGeometry {
 public:
  // throws std::invalid_argument when the pair is not supported (see supported).
  // with_friction: a pair whose friction can hold a face (a polygon's; see
  // contact_dynamics.cpp) uses ContactGeometry::spread_m2, so fast detection
  // goes to the trees, not to the closed form of convex_line_contact.hpp,
  // which does not compute it; on a half-plane its line of action comes from
  // the body's own points (pair_geometry.cpp)
  PairGeometry(const Body& a, const Body& b, GeometryMode mode,
               DetectionMode detection = DetectionMode::fast, bool with_friction = false);

  // whether the pair can be evaluated in this mode; `reason` says why not
  [[nodiscard]] static bool supported(const Body& a, const Body& b, GeometryMode mode,
                                      std::string* reason);

  [[nodiscard]] ContactGeometry evaluate(const Pose& pose_a, const Pose& pose_b);
  // the next evaluation starts without the last one's history (fast)
  void forget_history();
  // evaluations answered by the closed form (convex_line_contact.hpp) and by
  // the trees, since construction
  [[nodiscard]] long closed_form_evaluations() const { return closed_form_count_; }
  [[nodiscard]] long tree_evaluations() const { return tree_count_; }

 private:
  std::optional<OutlineContactSearch> outline_;
  std::optional<FastOutlineContactSearch> fast_;
  std::optional<ConvexLineContact> convex_line_;
  long closed_form_count_ = 0, tree_count_ = 0;
  std::optional<ExactContact> exact_;
};

}  // namespace pb
