#include "suites/run_directory.hpp"

#include <stdlib.h>

#include <cerrno>
#include <system_error>

namespace cs::suites {

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
