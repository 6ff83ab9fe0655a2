# Installs the build's oracles package into a fresh prefix, then configures, builds and runs the
# consumer project against it, with CMake (find_package) and with pkg-config (the compiler
# called with `pkg-config --cflags --libs contact_suite_oracles`, as a Makefile would).
# Run by ctest (test `oracles_install_consumer`):
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DCXX_COMPILER=...
#         [-DCONSUMER_LINK_FLAGS=...] [-DPREFIX=...] -P check.cmake
# PREFIX: an installed tree to use instead of installing the build (ci/deb-package.sh passes the
# unpacked .deb's usr/).
# CONSUMER_LINK_FLAGS: what the consumer links with besides the package (the sanitizers'
# runtimes when the build is sanitized).
file(REMOVE_RECURSE ${WORK_DIR})
if(NOT PREFIX)
  set(PREFIX ${WORK_DIR}/prefix)
  execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                          --component Unspecified RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "cmake --install failed (${rc})")
  endif()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer
                        -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${PREFIX}
                        -DCMAKE_BUILD_TYPE=Release
                        "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_LINK_FLAGS}" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer does not configure against the installed package (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer does not build against the installed package (${rc})")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer's check of the installed oracles failed (${rc})")
endif()

# The same program through pkg-config alone: the .pc file in PREFIX's library directory.
file(GLOB_RECURSE pc_files ${PREFIX}/*/contact_suite_oracles.pc)
if(NOT pc_files)
  message(FATAL_ERROR "no contact_suite_oracles.pc under ${PREFIX}")
endif()
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
execute_process(COMMAND pkg-config --cflags --libs contact_suite_oracles OUTPUT_VARIABLE pc_flags
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "pkg-config does not find contact_suite_oracles in ${pc_dir} (${rc})")
endif()
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
separate_arguments(link_flags UNIX_COMMAND "${CONSUMER_LINK_FLAGS}")
execute_process(COMMAND ${CXX_COMPILER} -std=c++20 -O2 ${SOURCE_DIR}/tests/install/consumer/main.cpp
                        ${pc_flags} ${link_flags} -o ${WORK_DIR}/pkg-config-consumer
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer does not build with pkg-config's flags: ${pc_flags} (${rc})")
endif()
execute_process(COMMAND ${WORK_DIR}/pkg-config-consumer RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the pkg-config consumer's check of the installed oracles failed (${rc})")
endif()
