#include "adapters/protocol/solver_registry.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <system_error>

#include <fmt/format.h>

#ifndef CONTACT_SUITE_ADAPTERS_DIR
#define CONTACT_SUITE_ADAPTERS_DIR ""
#endif

namespace cs::adapters::protocol {
namespace {

namespace fs = std::filesystem;

/// The folders of `dir` that hold a manifest (or `dir` itself if it holds one), sorted.
std::vector<fs::path> manifest_folders(const fs::path& dir) {
  std::error_code ec;
  if (fs::is_regular_file(dir / "manifest.json", ec))
    return {dir};
  std::vector<fs::path> out;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_directory(ec) && fs::is_regular_file(it->path() / "manifest.json", ec))
      out.push_back(it->path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The project's adapters: PREFIX/share/contact-suite/adapters next to an installed (or
/// unpacked) program PREFIX/bin/contact-suite, else the source tree's adapters/.
fs::path project_adapters() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed =
        exe.parent_path().parent_path() / "share" / "contact-suite" / "adapters";
    if (fs::is_directory(installed, ec))
      return installed;
  }
  return CONTACT_SUITE_ADAPTERS_DIR;
}

}  // namespace

std::vector<fs::path> solver_directories(const std::vector<fs::path>& extra) {
  std::vector<fs::path> out;
  if (const fs::path built_in = project_adapters(); !built_in.empty())
    out.push_back(built_in);
  if (const char* env = std::getenv("CONTACT_SUITE_SOLVER_DIRS")) {
    std::string list = env;
    for (std::size_t start = 0; start <= list.size();) {
      const auto colon = std::min(list.find(':', start), list.size());
      if (colon > start)  // absolute: a code runs inside its case directory, not here
        out.push_back(fs::absolute(list.substr(start, colon - start)));
      start = colon + 1;
    }
  }
  for (const auto& dir : extra)
    out.push_back(fs::absolute(dir));
  return out;
}

std::vector<SolverManifest> discover_solvers(const std::vector<fs::path>& directories) {
  std::vector<SolverManifest> out;
  for (const auto& dir : directories) {
    for (const auto& folder : manifest_folders(dir)) {
      SolverManifest m = read_manifest(folder);
      for (const auto& other : out)
        if (other.name == m.name &&
            fs::weakly_canonical(other.folder) != fs::weakly_canonical(m.folder))
          throw ManifestError(fmt::format("two codes are called '{}': {} and {}", m.name,
                                          other.folder.string(), m.folder.string()));
      const bool seen = std::any_of(out.begin(), out.end(),
                                    [&](const SolverManifest& o) { return o.name == m.name; });
      if (!seen)
        out.push_back(std::move(m));
    }
  }
  std::sort(out.begin(), out.end(),
            [](const SolverManifest& a, const SolverManifest& b) { return a.name < b.name; });
  return out;
}

std::vector<std::string> readable_solver_names(const std::vector<fs::path>& directories) {
  std::vector<std::string> out;
  for (const auto& dir : directories) {
    for (const auto& folder : manifest_folders(dir)) {
      try {
        out.push_back(read_manifest(folder).name);
      } catch (const ManifestError&) {  // passed over: the caller only checks a name
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

SolverManifest find_solver(std::string_view name, const std::vector<fs::path>& directories) {
  const auto all = discover_solvers(directories);
  for (const auto& m : all)
    if (m.name == name)
      return m;
  std::string known;
  for (const auto& m : all)
    known += (known.empty() ? "" : ", ") + m.name;
  throw ManifestError(
      fmt::format("no solver '{}' (builtin, calculix{}{}; add a folder with a "
                  "manifest.json by --solver-dir or CONTACT_SUITE_SOLVER_DIRS)",
                  name, known.empty() ? "" : ", ", known));
}

}  // namespace cs::adapters::protocol
