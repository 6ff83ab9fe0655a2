# Build speed (issue 27): precompiled headers for the heavy third-party includes, unity builds,
# and test programs compiled at -O1.
#
# Each target precompiles the third-party headers that most of its translation units include
# anyway (measured with `ninja -t deps`): parsing Eigen, nlohmann-json or GoogleTest once per
# target instead of once per file. Headers a target's files rarely include stay out of its
# precompiled header, since every file of the target pays for what the header holds.
option(CONTACT_SUITE_PCH "Precompile the heavy third-party headers of each target" ON)

# Unity builds: each target compiles its files as one translation unit, so the headers every
# file includes (ours, the standard library's, what the precompiled header leaves out) are parsed
# once, and the inline code they instantiate (CLI11's parser, nlohmann-json, fmt, GoogleTest) is
# compiled once per target instead of once per batch. Measured unit by unit on one core against
# batches of 8: the command line 72 -> 32 s, the report writer 90 -> 68 s, the suites 77 -> 52 s.
# The solver keeps batches of 8 (cs_unity_batches): its optimized code dominates its time, and
# one unit of it would be the build's longest step. Test files whose file-local names (an
# anonymous namespace's helpers and constants) would clash keep them in a namespace named after
# the file (test_solver: 91 -> 63 s); a library file that cannot is compiled on its own:
# cs_unity_exclude, next to the target.
option(CONTACT_SUITE_UNITY "Compile each target's files as one unit (unity build)" ON)
if(CONTACT_SUITE_UNITY)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 0)
endif()

# cs_unity_batches(<target> <n>): compile <target>'s files in batches of n instead.
function(cs_unity_batches target n)
  set_target_properties(${target} PROPERTIES UNITY_BUILD_BATCH_SIZE ${n})
endfunction()

# cs_unity_exclude(<file>...): compile these files of the current directory on their own.
function(cs_unity_exclude)
  set_source_files_properties(${ARGN} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()

set(cs_pch_eigen <Eigen/Core> <Eigen/SparseCore>)
set(cs_pch_json <nlohmann/json.hpp>)
set(cs_pch_fmt <fmt/format.h>)
set(cs_pch_gtest <gtest/gtest.h>)
set(cs_pch_cli11 <CLI/CLI.hpp>)

# cs_precompile(<target> <header-set>...): precompile the named sets (eigen, json, fmt, gtest,
# cli11) for <target>'s own files.
function(cs_precompile target)
  if(NOT CONTACT_SUITE_PCH)
    return()
  endif()
  set(headers "")
  foreach(set_name ${ARGN})
    if(NOT DEFINED cs_pch_${set_name})
      message(FATAL_ERROR "cs_precompile: unknown header set '${set_name}'")
    endif()
    list(APPEND headers ${cs_pch_${set_name}})
  endforeach()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

# Code that does no numerical work of its own compiles at -O1 (after the build type's -O3, so
# it wins): the test programs (assertions and set-up around the layers they test, which are
# built optimized; about a quarter faster to compile) and the report writer (formatting and
# templates; its files compile in about half the time, and writing the committed report from
# its 4,838 cases stays a matter of seconds). Floating-point results do not depend on it: ISO
# C++ mode keeps -ffp-contract=off at every level.
function(cs_light_optimization target)
  if(CMAKE_BUILD_TYPE STREQUAL "Release")
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()
