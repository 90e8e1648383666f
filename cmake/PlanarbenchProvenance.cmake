# Build provenance compiled into the binary and written to every results file.
find_package(Git QUIET)
set(PB_BUILD_REVISION "unknown")
if(GIT_FOUND AND EXISTS "${CMAKE_SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}"
                  OUTPUT_VARIABLE PB_BUILD_REVISION OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET RESULT_VARIABLE _pb_git_rc)
  if(NOT _pb_git_rc EQUAL 0 OR PB_BUILD_REVISION STREQUAL "")
    set(PB_BUILD_REVISION "unknown")
  endif()
endif()
string(TOUPPER "${CMAKE_BUILD_TYPE}" _pb_bt)
set(PB_BUILD_COMPILER "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}")
set(PB_BUILD_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_pb_bt}}")
string(STRIP "${PB_BUILD_FLAGS}" PB_BUILD_FLAGS)
set(PB_BUILD_TYPE "${CMAKE_BUILD_TYPE}")
configure_file("${CMAKE_SOURCE_DIR}/cmake/build_info.hpp.in"
               "${CMAKE_BINARY_DIR}/generated/planarbench/build_info.hpp" @ONLY)
