// A MAT v5 file's structure walked before libmatio reads it (issue 35: libmatio
// allocates what a header claims - a struct whose field-name element claimed
// 4.7e8 names made Mat_VarReadInfo allocate 7.5 GB, found by
// tests/fuzz/fuzz_impact_data.cpp). Every data element's size is checked
// against what contains it, compressed variables are inflated (streamed, at
// most kMaxInflatedBytes each) and walked the same way, and each matrix's
// header against what a file of impacts can hold: at most kMaxMatElements
// values, kMaxStructFields fields, kMaxStructCells struct or cell entries,
// kMaxMatDepth levels of nesting. Files that are not MAT v5 never reach
// libmatio: its MAT v4 reader allocated a header's name length (a 20-byte
// file took 2 GB), and MAT v7.3 goes through HDF5, whose failed calls printed
// a 26-line error stack (issue 35 item 15); a file of impacts is MAT v5.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pb {

// 1e5 impacts x 18 values (impact_data.cpp's largest claim)
inline constexpr std::size_t kMaxMatElements = 1800000;
inline constexpr std::size_t kMaxStructFields = 64;
inline constexpr std::size_t kMaxStructCells = 4096;   // struct elements x fields, or cells
inline constexpr int kMaxMatDepth = 8;
// 64 MB: two variables of kMaxMatElements doubles (29 MB) and their headers
inline constexpr std::size_t kMaxInflatedBytes = std::size_t{64} << 20;
// 256 MB: more than four times what the largest file of impacts needs
inline constexpr std::size_t kMaxMatFileBytes = std::size_t{256} << 20;

// What is wrong with a MAT v5 file's structure: the variable ("data",
// "data.states_i"; empty when the file's elements themselves are broken) and
// what, where (the byte offset of the element, in the file or in the inflated
// variable) and what is allowed. `what` is empty when all is well.
struct MatProblem {
  std::string variable;
  std::string what;
};

// `bytes`: a whole file.
[[nodiscard]] MatProblem mat_v5_problem(std::string_view bytes);

}  // namespace pb
