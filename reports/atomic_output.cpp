#include "reports/atomic_output.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "reports/report_error.hpp"

namespace cs::reports {

namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw ReportError(fmt::format("output '{}' exists and is not a directory", dir_.string()));
  if (!fs::exists(dir_, ec)) {
    created_dir_ = fs::create_directories(dir_, ec);
    if (ec) {
      throw ReportError(
          fmt::format("cannot create output directory '{}': {}", dir_.string(), ec.message()));
    }
  }
  std::string pattern = (dir_ / ".tmp-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    const std::string why = std::error_code(errno, std::generic_category()).message();
    if (created_dir_)
      fs::remove(dir_, ec);
    throw ReportError(fmt::format("cannot write in output directory '{}': {}", dir_.string(), why));
  }
  staging_ = pattern;
}

AtomicOutput::~AtomicOutput() {
  std::error_code ec;
  if (!staging_.empty())
    fs::remove_all(staging_, ec);
  if (!committed_ && created_dir_ && fs::is_empty(dir_, ec))
    fs::remove(dir_, ec);
}

fs::path AtomicOutput::staging_path(const std::string& relative) const {
  const fs::path path = staging_ / relative;
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec) {
    throw ReportError(
        fmt::format("cannot create '{}': {}", path.parent_path().string(), ec.message()));
  }
  return path;
}

void AtomicOutput::write_text(const std::string& relative, std::string_view content) {
  const fs::path path = staging_path(relative);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();
  if (!out)
    throw ReportError(fmt::format("cannot write '{}'", path.string()));
}

std::vector<std::string> AtomicOutput::commit() {
  std::vector<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(staging_, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    if (it->is_regular_file())
      files.push_back(fs::relative(it->path(), staging_).generic_string());
  }
  if (ec)
    throw ReportError(fmt::format("cannot list '{}': {}", staging_.string(), ec.message()));
  std::sort(files.begin(), files.end());
  for (const auto& rel : files) {
    const fs::path target = dir_ / rel;
    fs::create_directories(target.parent_path(), ec);
    if (!ec)
      fs::rename(staging_ / rel, target, ec);
    if (ec) {
      throw ReportError(fmt::format("cannot move the report file '{}' into place: {}",
                                    target.string(), ec.message()));
    }
  }
  committed_ = true;
  fs::remove_all(staging_, ec);
  staging_.clear();
  return files;
}

}  // namespace cs::reports
