// Requirement: an external code runs with the contact_suite package that goes with this program
// on its PYTHONPATH. A build tree's <bin>/python (our package alone) leads the caller's
// PYTHONPATH; an installed <prefix>/lib/python3/dist-packages (every Debian package with it)
// follows it, so that a code's own Python packages (a venv, a newer NumPy) keep their place.
// Fails if the installed directory is put first, or the build tree's last.

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "adapters/protocol/code_environment.hpp"
#include "support/temp_dir.hpp"

namespace cs::adapters::protocol {
namespace {

namespace fs = std::filesystem;

/// A contact_suite package in `dir`.
void make_package(const fs::path& dir) {
  fs::create_directories(dir / "contact_suite");
  std::ofstream(dir / "contact_suite" / "__init__.py") << "\n";
}

std::map<std::string, std::string> environment(const fs::path& exe, const std::string& inherited) {
  std::map<std::string, std::string> out;
  for (const auto& [name, value] : code_environment_of(exe, inherited))
    out[name] = value;
  return out;
}

TEST(CodeEnvironment, BuildTreePackageLeadsAnInstalledOneFollows) {
  cs::testing::TempDir tmp;
  const fs::path build = tmp.path() / "build", prefix = tmp.path() / "usr";
  make_package(build / "python");
  const fs::path installed = prefix / "lib" / "python3" / "dist-packages";
  make_package(installed);

  auto env = environment(build / "contact-suite", "/venv/site");
  EXPECT_EQ(env.at("PYTHONPATH"), (build / "python").string() + ":/venv/site");
  env = environment(prefix / "bin" / "contact-suite", "/venv/site");
  EXPECT_EQ(env.at("PYTHONPATH"), "/venv/site:" + installed.string());
  env = environment(prefix / "bin" / "contact-suite", "");
  EXPECT_EQ(env.at("PYTHONPATH"), installed.string());
  EXPECT_EQ(env.at("OMP_NUM_THREADS"), "1");

  env = environment(tmp.path() / "elsewhere" / "contact-suite", "/venv/site");
  EXPECT_FALSE(env.contains("PYTHONPATH"));  // no package found: left as inherited
}

}  // namespace
}  // namespace cs::adapters::protocol
