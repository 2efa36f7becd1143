# Precompiled headers for the targets of many files that all include the same heavy third-party
# headers (the standard library, Eigen, Abseil, gtest, gRPC and the generated messages): each
# target parses them once instead of once per file, which roughly halves those files' compile
# time. Only third-party headers, so editing the project's own headers rebuilds no header.
option(SWARMPLAN_PRECOMPILED_HEADERS "Precompile the heavy third-party headers (faster builds)" ON)

set(SWARMPLAN_PCH_COMMON
  <algorithm> <cmath> <cstdint> <filesystem> <functional> <limits> <map> <memory> <optional>
  <string> <utility> <vector> <Eigen/Core> <absl/status/status.h> <absl/status/statusor.h>
  <absl/strings/str_cat.h> <absl/strings/str_format.h> <absl/time/time.h>)
set(SWARMPLAN_PCH_TESTS <gmock/gmock.h> <gtest/gtest.h>)
set(SWARMPLAN_PCH_SERVICE
  <grpcpp/grpcpp.h> <swarmplan/v1/algorithms.grpc.pb.h> <swarmplan/v1/jobs.grpc.pb.h>
  <swarmplan/v1/maps.grpc.pb.h>)

# swarmplan_precompile_headers(TARGET [TESTS] [SERVICE]): the common set, plus gtest/gmock with
# TESTS and gRPC with the service's messages and stubs with SERVICE.
function(swarmplan_precompile_headers target)
  if(NOT SWARMPLAN_PRECOMPILED_HEADERS)
    return()
  endif()
  set(headers ${SWARMPLAN_PCH_COMMON})
  if("TESTS" IN_LIST ARGN)
    list(APPEND headers ${SWARMPLAN_PCH_TESTS})
  endif()
  if("SERVICE" IN_LIST ARGN)
    list(APPEND headers ${SWARMPLAN_PCH_SERVICE})
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
  # From a precompiled header GCC 12 no longer treats the standard headers' code as system code,
  # so the false bounds warnings of that family (GCC bug 105329) on `"text" + std::string` reach
  # these targets; core, which holds the array code, keeps these warnings, and the sanitizer run
  # checks bounds at run time.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-stringop-overflow
                                              -Wno-stringop-overread)
  endif()
endfunction()
