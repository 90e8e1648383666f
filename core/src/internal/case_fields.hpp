// The fields a case file shares between its tables: shapes, mass
// properties, contact laws and the limits that catch absurd input. Defined in
// case_loader.cpp; the scene tables (scene_loader.cpp) read theirs with them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "toml_reader.hpp"

namespace pb::internal {

// limits that catch absurd input, not physics: sizes and coordinates a
// planar benchmark never needs, and output grids that would not fit in memory
inline constexpr double kMaxDuration_s = 1e4;          // s
inline constexpr double kMaxOutputSamples = 1e7;       // duration / output_interval
inline constexpr int kMaxOutlinePoints = 100000;
inline constexpr int kMaxPolygonPoints = 10000;        // the self-intersection check is O(n^2)
inline constexpr double kMaxSize_m = 1e4;              // m, radius, semi-axis, extent
// m, the smallest radius or semi-axis: a positive size far smaller (a
// denormal 1e-310 m) gives the body an area and an inertia that underflow to
// 0, which would be blamed on the inertia; 1 nm is 10 times the default
// contact threshold of 1e-10 m and leaves every area property a normal double
inline constexpr double kMinSize_m = 1e-9;
inline constexpr double kMaxCoordinate_m = 1e6;        // m, positions, anchors, polygon points
inline constexpr double kMaxThreshold_m = 1e-3;        // m, contact distance threshold
// Coulomb coefficient: measured pairs lie in [0, ~1.5] (rubber on concrete
// ~1, clean metals up to ~1.5); 10 keeps room for tests and rejects a slipped
// digit (friction = 50 meant 0.5)
inline constexpr double kMaxFriction = 10.0;
// bytes of a case file: ten 10000-point polygons at ~45 bytes a point are 4.5 MB
inline constexpr std::uintmax_t kMaxCaseFileBytes = 8u << 20;  // 8 MiB

// at most this many bodies in a case, generated ones included: 1e5 leaves a
// decade above the 1e4 a scene is meant to reach (a body is ~1 KB of case
// model; the results file holds one group per moving body)
inline constexpr int kMaxBodies = 100000;
// a body name fits the results file's name cells (results_layout.hpp)
inline constexpr std::size_t kMaxBodyNameChars = 32;

// a shape table: circle, ellipse, polygon, halfplane
[[nodiscard]] Shape read_shape(const TableReader& s);
// mass (mass | density) and inertia (a number, "shape", "outline") of a moving body
void read_mass_properties(const TableReader& t, Body& b);
// the law of a contact pair or group (law, its fields, threshold, friction);
// `keys` are the table's own keys besides the law's, `what` names the table
// in messages ("contact", "contact group")
void read_contact_law(const TableReader& t, const std::vector<std::string>& keys,
                      const std::string& what, ContactLaw& law, double& threshold_m,
                      double& friction);
// a body name: an identifier that fits the results file (kMaxBodyNameChars)
[[nodiscard]] std::string body_name(const TableReader& t, std::string_view key);

}  // namespace pb::internal
