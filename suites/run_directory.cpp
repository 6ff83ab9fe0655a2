#include "suites/run_directory.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "suites/suite_error.hpp"

namespace cs::suites {

void require_temporary_directory() {
  const char* env = std::getenv("TMPDIR");
  const std::string named = env != nullptr ? std::string("TMPDIR=") + env : "/tmp";
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec)
    throw SuiteInputError("the temporary directory (" + named + ") is not usable: " + ec.message());
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw SuiteInputError("the temporary directory " + dir.string() +
                          " is not writable: " + std::strerror(errno));
}

RunDirectory::RunDirectory(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + ".XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw std::system_error(errno, std::generic_category(),
                            "cannot create a run directory from " + pattern);
  path_ = pattern;
}

RunDirectory::~RunDirectory() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);  // fails, harmlessly, while failed cases are kept
}

}  // namespace cs::suites
