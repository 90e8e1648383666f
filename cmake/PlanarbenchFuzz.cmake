# PB_BUILD_FUZZERS: the libFuzzer targets of tests/fuzz (scripts/fuzz.sh,
# preset "fuzz"). Clang only. Every project target gets libFuzzer's coverage
# instrumentation, AddressSanitizer and UBSan through pb_sanitizers
# (-fsanitize=fuzzer-no-link,address,undefined); the fuzz executables add
# libFuzzer's main (-fsanitize=fuzzer, tests/fuzz/CMakeLists.txt).
# Include after PlanarbenchWarnings (it extends pb_sanitizers).
if(NOT PB_BUILD_FUZZERS)
  return()
endif()

if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR
    "PB_BUILD_FUZZERS=ON needs Clang (libFuzzer is part of Clang), but the C++ compiler is "
    "${CMAKE_CXX_COMPILER_ID} (${CMAKE_CXX_COMPILER}). Configure with the preset: "
    "cmake --preset fuzz (clang/clang++), or -DCMAKE_CXX_COMPILER=clang++ in a fresh build folder.")
endif()
if(PB_SANITIZE)
  message(FATAL_ERROR
    "PB_BUILD_FUZZERS=ON brings its own sanitizers (address,undefined): leave PB_SANITIZE empty "
    "(it is '${PB_SANITIZE}').")
endif()

# libFuzzer's runtime ships apart from the compiler on Debian (libclang-rt-14-dev)
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer")
set(CMAKE_REQUIRED_LINK_OPTIONS "-fsanitize=fuzzer")
check_cxx_source_compiles([=[
#include <cstddef>
#include <cstdint>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }
]=] PB_HAVE_LIBFUZZER)
unset(CMAKE_REQUIRED_FLAGS)
unset(CMAKE_REQUIRED_LINK_OPTIONS)
if(NOT PB_HAVE_LIBFUZZER)
  message(FATAL_ERROR
    "PB_BUILD_FUZZERS=ON: ${CMAKE_CXX_COMPILER} cannot link -fsanitize=fuzzer. Install "
    "libFuzzer's runtime (Debian 12: apt-get install libclang-rt-14-dev; scripts/setup.sh).")
endif()

# known defects outside planarbench, each with its reference, in the ignorelist
target_compile_options(pb_sanitizers INTERFACE
  -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
  "-fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/tests/fuzz/ubsan_ignorelist.txt")
target_link_options(pb_sanitizers INTERFACE -fsanitize=address,undefined)

# toml++ compiled into the fuzzed code instead of called in Debian's shared
# library (whose package config adds -DTOML_HEADER_ONLY=0 -DTOML_SHARED_LIB=1),
# so that libFuzzer sees its branches and ASan checks its memory accesses.
# These options come after the package's on every target that links
# tomlplusplus before pb_set_warnings (pb_core does).
target_compile_options(pb_sanitizers INTERFACE
  -UTOML_HEADER_ONLY -DTOML_HEADER_ONLY=1 -UTOML_SHARED_LIB)
