#include "adapters/protocol/code_environment.hpp"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace cs::adapters::protocol {
namespace {

namespace fs = std::filesystem;

bool holds_package(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "contact_suite" / "__init__.py", ec);
}

/// <prefix>/lib/python3.*/dist-packages, sorted (the newest Python last).
std::vector<fs::path> versioned_dist_packages(const fs::path& lib) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(lib, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind("python3.", 0) == 0)
      out.push_back(it->path() / "dist-packages");
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

fs::path python_package_dir(const fs::path& executable) {
  const fs::path bin = executable.parent_path();
  std::vector<fs::path> candidates = {bin / "python",
                                      bin.parent_path() / "lib" / "python3" / "dist-packages"};
  for (const auto& dir : versioned_dist_packages(bin.parent_path() / "lib"))
    candidates.push_back(dir);
  for (const auto& dir : candidates)
    if (holds_package(dir))
      return dir;
  return {};
}

std::vector<std::pair<std::string, std::string>> code_environment() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const char* inherited = std::getenv("PYTHONPATH");
  return code_environment_of(ec ? fs::path() : exe, inherited ? inherited : "");
}

std::vector<std::pair<std::string, std::string>> code_environment_of(const fs::path& exe,
                                                                     const std::string& inherited) {
  std::vector<std::pair<std::string, std::string>> out = {{"OMP_NUM_THREADS", "1"},
                                                          {"PYTHONDONTWRITEBYTECODE", "1"}};
  const fs::path package = exe.empty() ? fs::path() : python_package_dir(exe);
  if (!package.empty()) {
    // A build tree's python/ holds our package alone and leads; an installed dist-packages
    // holds every Debian package too, so it follows the caller's own PYTHONPATH (a code's venv
    // or newer NumPy keeps its place), where python3 would look for it anyway.
    const bool build_tree = package == exe.parent_path() / "python";
    std::string path = package.string();
    if (!inherited.empty())
      path = build_tree ? path + ":" + inherited : inherited + ":" + path;
    out.emplace_back("PYTHONPATH", path);
  }
  return out;
}

}  // namespace cs::adapters::protocol
