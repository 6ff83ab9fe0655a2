#include "platform/output_transaction.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "platform/platform_error.hpp"

namespace cs::platform {
namespace fs = std::filesystem;
namespace {

std::string quoted(const fs::path& p) {
  std::string out(1, '\'');
  out += p.string();
  out += '\'';
  return out;
}

/// Hard-links `from` (a file, or recursively a directory) to `to`; copies where linking fails.
void link_tree(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  if (fs::is_directory(fs::symlink_status(from, ec))) {
    fs::create_directory(to, ec);
    for (const auto& entry : fs::directory_iterator(from)) {
      if (!fs::exists(to / entry.path().filename(), ec))
        link_tree(entry.path(), to / entry.path().filename());
    }
    return;
  }
  fs::create_hard_link(from, to, ec);
  if (ec)
    fs::copy(from, to, fs::copy_options::copy_symlinks, ec);
  if (ec)
    throw PlatformError("cannot keep " + quoted(from) + " in the new output: " + ec.message());
}

void remove_stale_staging(const fs::path& parent, const std::string& prefix) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    if (entry.path().filename().string().rfind(prefix, 0) == 0)
      fs::remove_all(entry.path(), ec);
  }
}

}  // namespace

void require_printable_path(const fs::path& path, const char* what) {
  for (unsigned char c : path.string()) {
    if (c < 0x20 || c == 0x7f) {
      throw PlatformError(std::string(what) +
                          ": the path holds a control character (newline, tab, ...); "
                          "choose a name without one");
    }
  }
}

OutputTransaction::OutputTransaction(fs::path dir, bool wait) {
  require_printable_path(dir, "output directory");
  if (dir.empty())
    throw PlatformError("output directory: empty path");
  dir_ = fs::absolute(dir).lexically_normal();
  if (!dir_.has_filename())
    dir_ = dir_.parent_path();
  const fs::path parent = dir_.parent_path();
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw PlatformError("output directory " + quoted(dir) + ": " + quoted(parent) +
                        " does not exist");
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw PlatformError("output directory " + quoted(dir) + " exists and is not a directory");
  const std::string name = dir_.filename().string();
  const fs::path lock_path = parent / ("." + name + ".lock");
  lock_fd_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (lock_fd_ >= 0)
    created_lock_ = lock_path;
  else if (errno == EEXIST)
    lock_fd_ = ::open(lock_path.c_str(), O_RDWR | O_CLOEXEC);
  if (lock_fd_ < 0)
    throw PlatformError("output directory " + quoted(dir) + ": cannot create its lock file " +
                        quoted(lock_path) + ": " + std::strerror(errno));
  if (::flock(lock_fd_, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    created_lock_.clear();
    throw PlatformError("another contact-suite process is writing to " + quoted(dir) + " (lock " +
                        quoted(lock_path) + "); wait for it or choose another --out");
  }
  const std::string prefix = "." + name + ".staging-";
  remove_stale_staging(parent, prefix);
  staging_ = parent / (prefix + std::to_string(::getpid()));
  if (!fs::create_directory(staging_, ec) || ec) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    if (!created_lock_.empty())
      fs::remove(created_lock_, ec);
    throw PlatformError("output directory " + quoted(dir) + ": cannot create " + quoted(staging_) +
                        ": " + (ec ? ec.message() : "it exists"));
  }
}

OutputTransaction::~OutputTransaction() {
  std::error_code ec;
  if (!staging_.empty())
    fs::remove_all(staging_, ec);
  // A lock file this transaction created for a directory it never wrote is removed again, so
  // that a refused run leaves nothing behind; an existing lock file is kept.
  if (!committed_ && !created_lock_.empty())
    fs::remove(created_lock_, ec);
  if (lock_fd_ >= 0)
    ::close(lock_fd_);  // releases the flock
}

void OutputTransaction::commit() {
  if (committed_)
    throw PlatformError("output transaction committed twice");
  std::error_code ec;
  if (!fs::exists(dir_, ec)) {
    if (::rename(staging_.c_str(), dir_.c_str()) != 0)
      throw PlatformError("cannot create " + quoted(dir_) + ": " + std::strerror(errno));
    fs::create_directory(staging_, ec);  // so that the destructor's cleanup stays uniform
    committed_ = true;
    return;
  }
  for (const auto& entry : fs::directory_iterator(dir_)) {
    if (entry.path().filename().string().rfind(".tmp-", 0) == 0)
      continue;  // a staging directory of an older contact-suite, interrupted: not kept
    const fs::path target = staging_ / entry.path().filename();
    if (!fs::exists(fs::symlink_status(target, ec)))
      link_tree(entry.path(), target);
  }
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, dir_.c_str(), RENAME_EXCHANGE) != 0)
    throw PlatformError("cannot replace " + quoted(dir_) + ": " + std::strerror(errno));
  committed_ = true;  // staging_ now holds the old set; the destructor removes it
}

}  // namespace cs::platform
