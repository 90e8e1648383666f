// The contact geometry of one contact pair, as the setting `geometry` asks:
// outline points (the paper, outline_contact.hpp) or the exact shapes
// (exact_contact.hpp). Two polygons are exact as outlines in both modes.
// Outline points are searched as the setting `detection` asks: fast (the
// default, fast_outline_contact.hpp) or brute (the brute-force oracle); both
// give the same result.
#pragma once

#include <optional>
#include <string>

#include "planarbench/case.hpp"
#include "planarbench/reference/contact_geometry.hpp"
#include "planarbench/reference/exact_contact.hpp"
#include "planarbench/reference/fast_outline_contact.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace pb {

enum class GeometryMode { outline, exact };
// how outline points are searched (same result, different cost)
enum class DetectionMode { fast, brute };

class PairGeometry {
 public:
  // throws std::invalid_argument when the pair is not supported (see supported)
  PairGeometry(const Body& a, const Body& b, GeometryMode mode,
               DetectionMode detection = DetectionMode::fast);

  // whether the pair can be evaluated in this mode; `reason` says why not
  [[nodiscard]] static bool supported(const Body& a, const Body& b, GeometryMode mode,
                                      std::string* reason);

  [[nodiscard]] ContactGeometry evaluate(const Pose& pose_a, const Pose& pose_b);

 private:
  std::optional<OutlineContactSearch> outline_;
  std::optional<FastOutlineContactSearch> fast_;
  std::optional<ExactContact> exact_;
};

}  // namespace pb
