#include "platform/replaceable_file.hpp"

#include <fstream>
#include <string>
#include <system_error>

#include "platform/platform_error.hpp"

namespace cs::platform {

namespace fs = std::filesystem;

namespace {

/// The first kWrittenMarkReach bytes of `file`, or "" when it cannot be read.
std::string head_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string head(kWrittenMarkReach, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

}  // namespace

std::string written_mark() {
  return "<!--" + std::string(kWrittenMarkText) + "-->";
}

void require_replaceable(const fs::path& file, const char* what, std::string_view older_mark) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(file, ec);
  if (ec || !fs::exists(status))
    return;
  const std::string head = fs::is_regular_file(status) ? head_of(file) : std::string();
  const bool ours = head.find(written_mark()) != std::string::npos ||
                    (!older_mark.empty() && head.find(older_mark) != std::string::npos);
  if (!ours) {
    throw PlatformError(std::string(what) + " " + file.string() +
                        ": the file exists and contact-suite did not write it; remove it or "
                        "name a new file");
  }
}

}  // namespace cs::platform
