#include "platform/output_transaction.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "platform/output_commit.hpp"
#include "platform/platform_error.hpp"

namespace cs::platform {
namespace fs = std::filesystem;
namespace {

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

OutputError failure(const std::string& what, const fs::path& path, int error) {
  return OutputError(what + " " + quoted(path) + ": " + std::strerror(error));
}

/// Writes `text` as the whole of the open file `fd`.
bool write_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return false;
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

/// Creates (or truncates) `path` and writes `text` into it; throws naming the cause.
void write_file(const fs::path& path, std::string_view text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw failure("cannot write", path, errno);
  const bool ok = write_all(fd, text);
  int error = errno;
  if (::close(fd) != 0 && ok)
    error = errno;
  if (!ok || error == ENOSPC || error == EDQUOT || error == EIO)
    throw failure("cannot write", path, error);
}

}  // namespace

OutputTransaction::OutputTransaction(fs::path dir, bool wait) : shown_(std::move(dir)) {
  const OutputDirectory checked = check_output_directory(shown_);
  dir_ = checked.path;
  if (checked.state == OutputDirectoryState::absent) {
    if (::mkdir(dir_.c_str(), 0777) != 0)  // the mode the umask leaves, as mkdir(1)
      throw PlatformError("output directory " + quoted(shown_) +
                          " cannot be created: " + std::strerror(errno));
    created_dir_ = true;
  }
  take_directory(wait);
}

void OutputTransaction::take_directory(bool wait) {
  const fs::path mark = dir_ / kOwnershipMark;
  lock_fd_ = ::open(mark.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (lock_fd_ >= 0)
    created_mark_ = true;
  else if (errno == EEXIST)
    lock_fd_ = ::open(mark.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
  if (lock_fd_ < 0) {
    const int error = errno;
    release_on_failure();
    throw failure("cannot open the mark of the output directory", mark, error);
  }
  if (::flock(lock_fd_, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0) {
    release_on_failure();
    throw PlatformError("another contact-suite process is writing to " + quoted(shown_) +
                        "; wait for it or choose another --out");
  }
  struct stat st {};
  ::fstat(lock_fd_, &st);
  if (st.st_size == 0) {  // new (or an empty mark a user made): write the format into it
    const std::string text = ownership_mark_text();
    if (!write_all(lock_fd_, text)) {
      const int error = errno;
      release_on_failure();
      throw failure("cannot write", mark, error);
    }
  }
  try {
    recover_output_directory(dir_);
    staging_ = dir_ / (std::string(kOwnershipMark) + ".staging-" + std::to_string(::getpid()));
    if (::mkdir(staging_.c_str(), 0777) != 0)
      throw failure("cannot create", staging_, errno);
    // The staging directory is the tool's own: a nested transaction may write into it.
    write_file(staging_ / kOwnershipMark, ownership_mark_text());
  } catch (...) {
    release_on_failure();
    throw;
  }
}

void OutputTransaction::release_on_failure() {
  std::error_code ec;
  if (!staging_.empty())
    fs::remove_all(staging_, ec);
  staging_.clear();
  if (created_mark_ || created_dir_)
    ::unlink((dir_ / kOwnershipMark).c_str());
  if (created_dir_)
    ::rmdir(dir_.c_str());  // only if still empty
  if (lock_fd_ >= 0)
    ::close(lock_fd_);  // releases the flock
  lock_fd_ = -1;
}

OutputTransaction::~OutputTransaction() {
  if (committed_) {
    if (lock_fd_ >= 0)
      ::close(lock_fd_);
    return;
  }
  release_on_failure();
}

void OutputTransaction::write_text(const std::string& relative, std::string_view content) const {
  const fs::path path = staging_ / relative;
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec)
    throw OutputError("cannot create " + quoted(path.parent_path()) + ": " + ec.message());
  write_file(path, content);
}

std::vector<std::string> OutputTransaction::commit() {
  if (committed_)
    throw PlatformError("output transaction committed twice");
  std::vector<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(staging_, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const fs::path rel = fs::relative(it->path(), staging_);
    if (is_bookkeeping_name(rel.begin()->string())) {
      if (it->is_directory())
        it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file())
      files.push_back(rel.generic_string());
  }
  if (ec)
    throw OutputError("cannot list " + quoted(staging_) + ": " + ec.message());
  std::sort(files.begin(), files.end());
  try {
    commit_staged_set(dir_, staging_);
  } catch (...) {
    // Once the journal exists the new set is decided and the next transaction finishes it:
    // the mark must stay.
    struct stat st {};
    if (::lstat((dir_ / (std::string(kOwnershipMark) + ".commit")).c_str(), &st) == 0) {
      committed_ = true;
      staging_.clear();
    }
    throw;
  }
  committed_ = true;
  staging_.clear();
  return files;
}

}  // namespace cs::platform
