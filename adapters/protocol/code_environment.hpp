#pragma once
// The environment an external code runs in (docs/solver-protocol.md, section 2), beside ours:
//   OMP_NUM_THREADS=1          one thread, so that cases running side by side are timed alike;
//   PYTHONDONTWRITEBYTECODE=1  a Python adapter leaves no __pycache__ in its own folder;
//   PYTHONPATH                 the directory of the Python package contact_suite that goes with
//                              this program, so that an adapter script can `import
//                              contact_suite` (read_case, write_results) from a build tree or an
//                              unpacked package: a build tree's <bin>/python before the inherited
//                              PYTHONPATH, an installed dist-packages (which holds every Debian
//                              package) after it, so that a code's own Python packages come first.
// The package is looked for next to the running program: <bin>/python (a build tree), then
// <bin>/../lib/python3/dist-packages and <bin>/../lib/python3.*/dist-packages (an installed or
// unpacked tree); none found: PYTHONPATH is left as it is (Debian's python3 finds a package
// installed under /usr by itself).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace cs::adapters::protocol {

/// The directory holding contact_suite/__init__.py next to the program `executable` (see the
/// file comment), or empty.
std::filesystem::path python_package_dir(const std::filesystem::path& executable);

/// The variables to set for an external code run by this program (see the file comment).
std::vector<std::pair<std::string, std::string>> code_environment();

/// code_environment() for the program `executable` (empty: not known) and the inherited
/// PYTHONPATH `inherited` (empty: none).
std::vector<std::pair<std::string, std::string>> code_environment_of(
    const std::filesystem::path& executable, const std::string& inherited);

}  // namespace cs::adapters::protocol
