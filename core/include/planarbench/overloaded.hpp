// The overload set of lambdas for std::visit over the shape and law variants
// (cppreference, std::visit, example "overloaded").
#pragma once

namespace pb {

template <class... Ts>
struct overloaded : Ts... {
  using Ts::operator()...;
};
// clang 14 lacks C++20 aggregate deduction (P1816): spell the guide out
template <class... Ts>
overloaded(Ts...) -> overloaded<Ts...>;

}  // namespace pb
