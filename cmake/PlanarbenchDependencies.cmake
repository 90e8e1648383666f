# Every dependency comes from a Debian 12 package (scripts/setup.sh installs them).
# Nothing is downloaded at build time.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(tomlplusplus 3 REQUIRED)
find_package(CLI11 2 REQUIRED)
find_package(HDF5 1.10 REQUIRED COMPONENTS C)
# zlib: results-file chunks are deflated by us, in parallel (core/src/internal/hdf5_chunks.hpp)
find_package(ZLIB REQUIRED)
find_package(Threads REQUIRED)
# CGAL 5 (header-only): 2-D polygon partitioning, the convex pieces of concave
# bodies (core/src/convex_pieces.cpp)
find_package(CGAL 5 REQUIRED)
# Boost (header-only parts, libboost-dev): Boost.Odeint and Boost.Math's
# minimiser for the independent truth (core/independent)
find_package(Boost 1.74 REQUIRED)
find_package(mujoco 2.2 REQUIRED)
find_package(box2d 2.4 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode>=0.16)
# measured impacts (core/impacts): MAT v5 files through libmatio, fits through NLopt
pkg_check_modules(MATIO REQUIRED IMPORTED_TARGET matio>=1.5)
# NLopt: the C library (libnlopt-dev); nlopt.hpp (libnlopt-cxx-dev) is a header-only wrapper of it
find_package(NLopt 2.7 REQUIRED CONFIG)
if(PB_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(PB_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# HDF5's FindHDF5 gives variables, not always a target: wrap them once.
if(NOT TARGET pb_hdf5)
  add_library(pb_hdf5 INTERFACE)
  if(TARGET hdf5::hdf5)
    target_link_libraries(pb_hdf5 INTERFACE hdf5::hdf5)
  else()
    target_include_directories(pb_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
    target_link_libraries(pb_hdf5 INTERFACE ${HDF5_C_LIBRARIES} ${HDF5_LIBRARIES})
    target_compile_definitions(pb_hdf5 INTERFACE ${HDF5_DEFINITIONS} ${HDF5_C_DEFINITIONS})
  endif()
endif()
