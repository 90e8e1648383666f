// The one assertion of the fuzz targets: a broken invariant prints itself and
// traps, which libFuzzer (and the corpus replay driver) records as a crash.
// Not assert(): it must also fire in builds with NDEBUG.
#pragma once

#include <cstdio>

#define PB_FUZZ_CHECK(cond)                                                              \
  do {                                                                                   \
    if (!(cond)) {                                                                       \
      std::fprintf(stderr, "fuzz invariant broken: %s (%s:%d)\n", #cond, __FILE__, __LINE__); \
      __builtin_trap();                                                                  \
    }                                                                                    \
  } while (false)
