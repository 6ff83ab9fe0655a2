# What `cmake --install` puts beside the command, the oracles library and the Python module
# (installed by apps/, oracles/ and python/), and the Debian package `cpack -G DEB` makes of it
# all: contact-suite_<version>_<arch>.deb, installed under /usr. ci/deb-package.sh builds it
# and runs it from an unpacked root.
include(GNUInstallDirs)

# The study's tables, which `report` compares with (reports/results/study_reference.hpp finds
# them at PREFIX/share/contact-suite/data/study), and the documentation.
# Components: command (the program and its data), python (python/), docs, and Unspecified (the
# oracles' library, headers, CMake and pkg-config files; tests/install/ installs only these).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/study
        DESTINATION ${CMAKE_INSTALL_DATADIR}/contact-suite/data COMPONENT command
        FILES_MATCHING PATTERN "*.csv" PATTERN "README.md")
# The external codes' adapters that run through the solver protocol (a manifest and a script
# each; adapters/protocol/solver_registry.hpp finds them at PREFIX/share/contact-suite/adapters).
install(FILES ${PROJECT_SOURCE_DIR}/adapters/getfem/manifest.json
              ${PROJECT_SOURCE_DIR}/adapters/getfem/getfem_case.py
        DESTINATION ${CMAKE_INSTALL_DATADIR}/contact-suite/adapters/getfem COMPONENT command)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/contact-suite COMPONENT docs)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/contact-suite/docs
        COMPONENT docs FILES_MATCHING PATTERN "*.md")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME contact-suite)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "verification test suite for finite-element contact mechanics, with exact solutions")
# One string (set() joins several with ';', which would end up in the control file).
string(CONCAT CPACK_PACKAGE_DESCRIPTION
       "The contact-suite command (run the study's battery, grade imported results, gate CI on a "
       "baseline with JUnit output), the exact-solution oracles as a C++ library (CMake package "
       "and pkg-config file), the Python package contact_suite (oracles, results reader, grading, "
       "the solver protocol's case reader and results writer), the GetFEM adapter and the "
       "documentation.")
set(CPACK_PACKAGE_CONTACT "contact-suite developers")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The shared libraries the command and the module link (GSL, CHOLMOD, OpenBLAS, fmt, pugixml,
# libstdc++ ...) as dpkg-shlibdeps finds them; then what is not a linked library: the Python the
# module was built for, and NumPy, which its field functions return.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(CONTACT_SUITE_BUILD_PYTHON)
  math(EXPR cs_python_next_minor "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${cs_python_next_minor}), python3-numpy")
endif()
# The oracles' headers and static library need GSL's headers to build against; figures need
# gnuplot; `run --solver calculix` needs ccx, `run --solver getfem` python3-getfem.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgsl-dev, pkg-config, gnuplot-nox")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "calculix-ccx, python3-getfem, cmake")
include(CPack)
