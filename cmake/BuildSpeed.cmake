# Build speed (issue 27): precompiled headers for the heavy third-party includes, unity builds,
# and test programs compiled at -O1.
#
# Each target compiled as several units precompiles the third-party headers that most of its
# translation units include anyway (measured with `ninja -t deps`): parsing Eigen, nlohmann-json
# or GoogleTest once per target instead of once per unit. Headers a target's files rarely
# include stay out of its precompiled header, since every file of the target pays for what the
# header holds.
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
# cli11) for <target>'s own files, when they compile as more than one unit. A target the unity
# build compiles as one unit parses each header once anyway, so its precompiled header would only
# add the time it takes to write it. Measured on two clean builds in turn on 2 cores: writing
# the precompiled headers of the nine test programs, the schema, the suites and the command line
# took 70 CPU-s, and their units compiled about 20 CPU-s faster for them (whole build 698 -> 602
# CPU-s, 351 -> 301 s wall, on a noisy host). The decision waits for the end of the target's
# directory, where its batch size and the files compiled on their own (cs_unity_batches,
# cs_unity_exclude) are known.
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
  # A deferred call's arguments are read when it runs, so they are written into it now.
  list(JOIN headers "]] [[" quoted)
  cmake_language(EVAL CODE
                 "cmake_language(DEFER CALL cs_precompile_if_several_units [[${target}]] [[${quoted}]])")
endfunction()

# The number of units <target> compiles as, into <out>.
function(cs_compile_units target out)
  get_target_property(sources ${target} SOURCES)
  list(FILTER sources INCLUDE REGEX "\\.cpp$")
  if(NOT CONTACT_SUITE_UNITY)
    list(LENGTH sources units)
    set(${out} ${units} PARENT_SCOPE)
    return()
  endif()
  set(together 0)
  set(alone 0)
  foreach(source ${sources})
    get_source_file_property(skip ${source} SKIP_UNITY_BUILD_INCLUSION)
    if(skip)
      math(EXPR alone "${alone} + 1")
    else()
      math(EXPR together "${together} + 1")
    endif()
  endforeach()
  get_target_property(batch ${target} UNITY_BUILD_BATCH_SIZE)
  if(together EQUAL 0)
    set(batches 0)
  elseif(NOT batch OR batch EQUAL 0)
    set(batches 1)
  else()
    math(EXPR batches "(${together} + ${batch} - 1) / ${batch}")
  endif()
  math(EXPR units "${batches} + ${alone}")
  set(${out} ${units} PARENT_SCOPE)
endfunction()

function(cs_precompile_if_several_units target)
  cs_compile_units(${target} units)
  if(units GREATER 1)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
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
