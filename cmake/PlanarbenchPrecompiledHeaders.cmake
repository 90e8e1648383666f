# pb_precompile_common(target [header ...]): the third-party headers nearly
# every source of a multi-source target parses (Eigen, nlohmann/json, fmt and
# the standard containers; plus the given ones) compiled once per target
# instead of once per source (CI time: the sanitizer build is compile-bound,
# ~1600 CPU-seconds, and these headers are most of every translation unit).
# Only for targets that link pb_core (Eigen and json) and fmt. The tests, one
# source each, reuse one header compiled for them all (pb_test_pch,
# tests/CMakeLists.txt): together the two save ~25 % of the sanitizer build.
option(PB_PRECOMPILE_HEADERS "Precompile the common third-party headers of the multi-source targets" ON)

function(pb_precompile_common target)
  if(NOT PB_PRECOMPILE_HEADERS)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE
    <algorithm> <cmath> <map> <memory> <optional> <string> <variant> <vector>
    <Eigen/Core> <fmt/format.h> <nlohmann/json.hpp> ${ARGN})
endfunction()
