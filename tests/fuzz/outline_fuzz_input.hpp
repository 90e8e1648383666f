// Decodes the bytes of the outline fuzz target into two shapes with their
// outline point counts and poses, a rigid motion and a probe point. The
// format is written out in tests/fuzz/README.md; make_outline_corpus.py
// encodes the seed corpus with it. Missing bytes read as zero, so every byte
// string decodes.
//
// Numbers stay inside what the case loader accepts (case_loader.cpp): sizes
// in (0, 8192] m (loader: <= 1e4 m), coordinates |x| <= 524288 m (loader:
// <= 1e6 m). Polygons are checked like the loader checks them
// (polygon_problem); a polygon it would reject makes the input unusable.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include "../../core/src/internal/polygon_checks.hpp"
#include "planarbench/case.hpp"
#include "planarbench/outline.hpp"
#include "planarbench/reference/contact_geometry.hpp"

namespace pb::fuzz {

// largest binary exponents of the decoded numbers
constexpr int kSizeExponent = 13;        // 2^13 = 8192 m
constexpr int kCoordinateExponent = 19;  // 2^19 = 524288 m
constexpr int kAngleExponent = 4;        // 2^4 = 16 rad
// most outline points of a circle, ellipse or half-plane: the paper's 180
// cost 2x the executions per second and reach no branch that 128 do not
constexpr int kMaxOutlinePoints = 128;

// the bytes, read front to back; zero once they run out
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t u8() {
    if (size_ == 0) return 0;
    --size_;
    return *data_++;
  }
  // little-endian signed 16-bit
  std::int16_t i16() {
    const auto lo = static_cast<std::uint16_t>(u8());
    const auto hi = static_cast<std::uint16_t>(u8());
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8)));
  }
  // 3 bytes: m / 32768 * 2^e, m = i16, e = (u8 mod (max_exponent + 33)) - 32;
  // |value| < 2^max_exponent, nonzero values >= 2^-47
  double scalar(int max_exponent) {
    const double m = static_cast<double>(i16()) / 32768.0;
    const int e = static_cast<int>(u8() % static_cast<unsigned>(max_exponent + 33)) - 32;
    return std::ldexp(m, e);
  }
  // a size > 0: |scalar|, or `fallback` for 0
  double size(double fallback) {
    const double s = std::abs(scalar(kSizeExponent));
    return s > 0.0 ? s : fallback;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
};

// one body: its shape, the outline point count make_outline gets, its pose
struct FuzzBody {
  Shape shape;
  int outline_points = 3;
  Pose pose;
};

// what one input decodes to
struct FuzzInput {
  FuzzBody a;
  FuzzBody b;
  Vec2 shift_m = Vec2::Zero();  // m, rigid motion of both bodies: translation
  double turn_rad = 0.0;        // rad, and rotation about the world origin
  Vec2 probe_m = Vec2::Zero();  // m, world point for nearest_boundary_point
};

// the polygon moved so that its centroid is the origin, or nothing when the
// loader would reject it
inline std::optional<Polygon> centred_polygon(std::vector<Vec2> points) {
  const AreaProperties props = polygon_area_properties(points);
  if (!std::isfinite(props.centroid_m.x()) || !std::isfinite(props.centroid_m.y())) {
    return std::nullopt;
  }
  for (auto& p : points) p -= props.centroid_m;
  if (internal::polygon_problem(points)) return std::nullopt;
  return Polygon{std::move(points)};
}

// kind (u8 mod 5), count (u8), shape numbers, then the pose
inline std::optional<Shape> read_shape(ByteReader& r, int& outline_points) {
  const int kind = r.u8() % 5;
  const int count = r.u8();
  switch (kind) {
    case 0:  // circle: radius
      outline_points = 3 + count % (kMaxOutlinePoints - 2);
      return Circle{r.size(1.0)};
    case 1: {  // ellipse: semi-axes a, b
      outline_points = 3 + count % (kMaxOutlinePoints - 2);
      const double a = r.size(1.0);
      return Ellipse{a, r.size(0.5)};
    }
    case 2: {  // star polygon: (angle step u8, radius) per point, angles increasing
      const int n = 3 + count % 62;
      std::vector<double> steps;
      std::vector<double> radii;
      double total = 0.0;
      for (int i = 0; i < n; ++i) {
        steps.push_back(1.0 + r.u8());
        radii.push_back(r.size(1.0));
        total += steps.back();
      }
      std::vector<Vec2> pts;
      double angle = 0.0;
      for (int i = 0; i < n; ++i) {
        pts.emplace_back(radii[i] * std::cos(angle), radii[i] * std::sin(angle));
        angle += 2.0 * std::numbers::pi * steps[i] / total;
      }
      outline_points = n;
      auto p = centred_polygon(std::move(pts));
      if (!p) return std::nullopt;
      return *p;
    }
    case 3:  // half-plane: extent
      outline_points = 2 + count % (kMaxOutlinePoints - 1);
      return HalfPlane{r.size(20.0)};
    default: {  // any polygon: (x, y) per point
      const int n = 3 + count % 62;
      std::vector<Vec2> pts;
      for (int i = 0; i < n; ++i) {
        const double x = r.scalar(kCoordinateExponent);
        pts.emplace_back(x, r.scalar(kCoordinateExponent));
      }
      outline_points = n;
      auto p = centred_polygon(std::move(pts));
      if (!p) return std::nullopt;
      return *p;
    }
  }
}

inline std::optional<FuzzBody> read_body(ByteReader& r, const Pose* relative_to) {
  FuzzBody b;
  auto shape = read_shape(r, b.outline_points);
  if (!shape) return std::nullopt;
  b.shape = *shape;
  // body b sits within 8192 m of body a, so that overlap is common
  const int e = relative_to == nullptr ? kCoordinateExponent : kSizeExponent;
  const double x = r.scalar(e);
  const double y = r.scalar(e);
  b.pose.position_m = Vec2(x, y);
  if (relative_to != nullptr) b.pose.position_m += relative_to->position_m;
  b.pose.angle_rad = r.scalar(kAngleExponent);
  return b;
}

// body a, body b (pose relative to a), rigid motion, probe (relative to a)
inline std::optional<FuzzInput> decode(const std::uint8_t* data, std::size_t size) {
  ByteReader r(data, size);
  FuzzInput in;
  auto a = read_body(r, nullptr);
  if (!a) return std::nullopt;
  in.a = *a;
  auto b = read_body(r, &in.a.pose);
  if (!b) return std::nullopt;
  in.b = *b;
  const double sx = r.scalar(kCoordinateExponent);
  in.shift_m = Vec2(sx, r.scalar(kCoordinateExponent));
  in.turn_rad = r.scalar(kAngleExponent);
  const double px = r.scalar(kSizeExponent);
  in.probe_m = in.a.pose.position_m + Vec2(px, r.scalar(kSizeExponent));
  return in;
}

}  // namespace pb::fuzz
