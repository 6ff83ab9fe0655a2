# Every dependency is a Debian package installed by ci/install-deps.sh.
# Each lookup fails early, naming the package that provides it.

macro(cs_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR "contact-suite: ${what} not found. Install the Debian package "
                        "'${package}' (or run: sudo bash ci/install-deps.sh).")
  endif()
endmacro()

find_package(Eigen3 3.4 QUIET NO_MODULE)
cs_require(Eigen3_FOUND "Eigen 3.4" libeigen3-dev)

find_package(GSL QUIET)
cs_require(GSL_FOUND "GSL" libgsl-dev)

find_package(fmt QUIET)
cs_require(fmt_FOUND "fmt" libfmt-dev)

find_package(CLI11 QUIET)
cs_require(CLI11_FOUND "CLI11" libcli11-dev)

find_package(nlohmann_json 3.10 QUIET)
cs_require(nlohmann_json_FOUND "nlohmann-json" nlohmann-json3-dev)

find_package(pugixml QUIET)
cs_require(pugixml_FOUND "pugixml" libpugixml-dev)

find_package(Threads REQUIRED)

# kainjow's Mustache (header-only): the report's prose templates.
find_path(KAINJOW_MUSTACHE_INCLUDE_DIR kainjow/mustache.hpp)
cs_require(KAINJOW_MUSTACHE_INCLUDE_DIR "kainjow Mustache" libkainjow-mustache-dev)

# SuiteSparse 5.x ships no CMake package: find CHOLMOD and its companions by hand.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig)
find_library(METIS_LIBRARY metis)
if(CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY AND SUITESPARSECONFIG_LIBRARY)
  set(CHOLMOD_FOUND TRUE)
endif()
cs_require(CHOLMOD_FOUND "SuiteSparse CHOLMOD" libsuitesparse-dev)
cs_require(METIS_LIBRARY "METIS" libmetis-dev)
find_package(BLAS QUIET)
find_package(LAPACK QUIET)
cs_require(BLAS_FOUND "BLAS (OpenBLAS)" libopenblas-dev)
cs_require(LAPACK_FOUND "LAPACK (OpenBLAS)" libopenblas-dev)

add_library(cs_cholmod INTERFACE)
target_include_directories(cs_cholmod SYSTEM INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(cs_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY}
                                           ${METIS_LIBRARY} ${LAPACK_LIBRARIES} ${BLAS_LIBRARIES})

if(CONTACT_SUITE_BUILD_PYTHON)
  # Debian's python3: the one the .deb depends on and the one with Debian's NumPy and pytest. A
  # python3 of pyenv or a virtualenv first on PATH has neither; pass -DPython3_EXECUTABLE to
  # choose another.
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python3 3.9 QUIET COMPONENTS Interpreter Development.Module)
  cs_require(Python3_FOUND "Python 3 headers" python3-dev)
  find_package(pybind11 2.6 QUIET CONFIG)
  cs_require(pybind11_FOUND "pybind11" pybind11-dev)
endif()

if(CONTACT_SUITE_BUILD_TESTS)
  find_package(GTest QUIET)
  cs_require(GTest_FOUND "GoogleTest" libgtest-dev)
endif()
if(CONTACT_SUITE_BUILD_BENCH)
  find_package(benchmark QUIET)
  cs_require(benchmark_FOUND "Google Benchmark" libbenchmark-dev)
endif()

# cs_add_layer(<target> <folder> [deps...]): one static library per layer, made of every
# .cpp under the folder (an INTERFACE library while the folder holds none). Headers are
# included by their path from the project root: #include "oracles/hertz.hpp".
function(cs_add_layer target folder)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.cpp)
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${target} PUBLIC ${ARGN})
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${target} INTERFACE ${ARGN})
  endif()
endfunction()
