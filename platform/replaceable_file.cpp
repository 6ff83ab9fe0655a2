#include "platform/replaceable_file.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
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

/// A file beside `file` holding `text` (mode 0644, synced to disk); throws OutputError.
fs::path temporary_copy(const fs::path& file, std::string_view text, const char* what) {
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::string temp = (dir / ".contact-suite-XXXXXX").string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) {
    throw OutputError(std::string(what) + " " + file.string() + ": cannot be written (" +
                      std::strerror(errno) + ")");
  }
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
                       ::fchmod(fd, 0644) == 0 && ::fsync(fd) == 0;
  const int error = errno;
  ::close(fd);
  if (!written) {
    ::unlink(temp.c_str());
    throw OutputError(std::string(what) + " " + file.string() + ": cannot be written (" +
                      std::strerror(error) + ")");
  }
  return temp;
}

}  // namespace

void replace_written_file(const fs::path& file, std::string_view text, const char* what,
                          std::string_view older_mark) {
  const fs::path temp = temporary_copy(file, text, what);
  try {
    // Absent: created only while still absent. Present (or no RENAME_NOREPLACE here): replaced
    // only if it still is the tool's.
    if (::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, file.c_str(), RENAME_NOREPLACE) == 0)
      return;
    if (errno != EEXIST && errno != EINVAL && errno != ENOSYS)
      throw OutputError(std::string(what) + " " + file.string() + ": cannot be written (" +
                        std::strerror(errno) + ")");
    require_replaceable(file, what, older_mark);
    if (::rename(temp.c_str(), file.c_str()) != 0)
      throw OutputError(std::string(what) + " " + file.string() + ": cannot be written (" +
                        std::strerror(errno) + ")");
  } catch (...) {
    ::unlink(temp.c_str());
    throw;
  }
}

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
