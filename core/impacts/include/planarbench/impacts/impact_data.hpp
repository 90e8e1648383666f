// A file of measured planar impacts (SPEC §8): the MCube ellipse drops
// (../shared/data/mcube/README.md), MAT v5, read and written with Debian's
// libmatio. The layout:
//   data.states_i  N x 6  state before the impact: x, y (m), theta (rad), x', y' (m/s), theta' (rad/s)
//   data.states_f  N x 6  state after it, same columns
//   data.n, data.d N x 3  the dataset's contact Jacobian rows (read, not used)
//   data.drop      N      the impact's row in the original file
//   v_models       N x 18 optional: post-impact (x', y', theta') of the dataset's six
//                         fitted models (kStoredModelNames, in that order)
// As stored: angles clockwise-positive, y twice the centre's height (the README
// measured both; impact_convention.hpp checks the first in code).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace pb {

struct ImpactSet {
  std::string path;    // as given
  std::string sha256;  // of the file's bytes
  std::vector<std::array<double, 6>> pre;   // data.states_i
  std::vector<std::array<double, 6>> post;  // data.states_f
  std::vector<double> drop;                 // data.drop
  std::vector<std::array<double, 18>> models;  // v_models, empty when absent
  [[nodiscard]] std::size_t size() const { return pre.size(); }
};

// the dataset's six models, in v_models' column order
inline constexpr std::array<const char*, 6> kStoredModelNames = {
    "drumwright_shell", "anitescu_potra_poisson", "anitescu_potra_newton",
    "mirtich",          "wang_mason",             "whittaker"};

// Reads a MAT v5 file of impacts. InputError naming the file, the variable
// and what was expected (its class and shape) for anything else; a file that
// is no MAT file at all is blamed on `option`, the command's option that
// named it (--data, or score's --training-data).
[[nodiscard]] ImpactSet read_impacts(const std::filesystem::path& path,
                                     const std::string& option = "--data");

// Writes `set` in the same layout (zlib-compressed MAT v5): tests make their
// own files with it. Throws std::runtime_error when libmatio fails.
void write_impacts(const std::filesystem::path& path, const ImpactSet& set);

}  // namespace pb
