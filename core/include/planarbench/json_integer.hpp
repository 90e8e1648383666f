// An integer read from JSON as it is written. nlohmann's get<int>() converts a
// number of any kind with a static_cast: 5.55556e+102 to int is undefined
// behaviour (fuzz_impact_work found it in a task file's "fold"), -1 to
// std::size_t wraps to 2^64 - 1, 2.5 truncates to 2. json_integer<T> takes
// only an integer literal within T's range and throws std::runtime_error
// naming the field and the range otherwise.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

namespace pb {

template <class T, class Json>
[[nodiscard]] T json_integer(const Json& v, std::string_view what) {
  static_assert(std::is_integral_v<T> && !std::is_same_v<T, bool>);
  constexpr auto lo = std::numeric_limits<T>::min();
  constexpr auto hi = std::numeric_limits<T>::max();
  bool fits = false;
  if (v.is_number_unsigned()) {
    fits = v.template get<std::uint64_t>() <= static_cast<std::uint64_t>(hi);
  } else if (v.is_number_integer()) {
    const auto i = v.template get<std::int64_t>();
    fits = i >= 0 ? static_cast<std::uint64_t>(i) <= static_cast<std::uint64_t>(hi)
                  : std::is_signed_v<T> && i >= static_cast<std::int64_t>(lo);
  }
  if (!fits) {
    throw std::runtime_error(fmt::format("{} is {}: must be an integer in [{}, {}]", what,
                                         v.dump(), lo, hi));
  }
  return v.template get<T>();
}

// each element of an array as json_integer<T>, named what[k]
template <class T, class Json>
[[nodiscard]] std::vector<T> json_integers(const Json& v, std::string_view what) {
  if (!v.is_array()) {
    throw std::runtime_error(
        fmt::format("{} is {}: must be an array of integers", what, v.type_name()));
  }
  std::vector<T> out;
  out.reserve(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    out.push_back(json_integer<T>(v[k], fmt::format("{}[{}]", what, k)));
  }
  return out;
}

}  // namespace pb
