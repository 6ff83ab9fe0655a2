#include "platform/output_commit.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "platform/output_directory.hpp"
#include "platform/platform_error.hpp"

namespace cs::platform {
namespace fs = std::filesystem;
namespace {

const std::string kList = std::string(kOwnershipMark) + ".set";
const std::string kJournal = std::string(kOwnershipMark) + ".commit";
const std::string kOld = std::string(kOwnershipMark) + ".old";
const std::string kStagingPrefix = std::string(kOwnershipMark) + ".staging-";
const std::string kResults = "results.json";

OutputError failure(const std::string& what, const fs::path& path, int error) {
  return OutputError(what + " '" + path.string() + "': " + std::strerror(error));
}

bool exists_no_follow(const fs::path& p, struct stat* st = nullptr) {
  struct stat local {};
  return ::lstat(p.c_str(), st != nullptr ? st : &local) == 0;
}

/// A name a set may hold: one path component, not the tool's bookkeeping.
bool is_entry_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         !is_bookkeeping_name(name);
}

/// The names listed in a set list; none when it does not exist.
std::vector<std::string> read_list(const fs::path& list) {
  std::vector<std::string> names;
  std::ifstream in(list);
  for (std::string line; std::getline(in, line);) {
    if (is_entry_name(line))
      names.push_back(line);
  }
  return names;
}

void write_list(const fs::path& list, const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names)
    text += n + "\n";
  const int fd = ::open(list.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const bool ok =
      fd >= 0 && ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  const int error = errno;
  if (fd >= 0)
    ::close(fd);
  if (!ok)
    throw failure("cannot write", list, error);
}

/// The entry names of a staged set, results.json last.
std::vector<std::string> staged_names(const fs::path& staging) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(staging)) {
    const std::string name = e.path().filename().string();
    if (is_entry_name(name))
      names.push_back(name);
  }
  std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    return (a == kResults) != (b == kResults) ? b == kResults : a < b;
  });
  return names;
}

/// Moves DIR/name into DIR/.contact-suite.old (replacing an older leftover of that name).
void move_aside(const fs::path& dir, const std::string& name) {
  const fs::path old = dir / kOld;
  if (::mkdir(old.c_str(), 0700) != 0 && errno != EEXIST)
    throw failure("cannot create", old, errno);
  std::error_code ec;
  fs::remove_all(old / name, ec);
  if (::rename((dir / name).c_str(), (old / name).c_str()) != 0)
    throw failure("cannot move the previous", dir / name, errno);
}

/// Renames journal/name to DIR/name; skipped when already done.
void install(const fs::path& dir, const std::string& name) {
  const fs::path from = dir / kJournal / name, to = dir / name;
  struct stat src {
  }, dst{};
  if (!exists_no_follow(from, &src))
    return;
  if (exists_no_follow(to, &dst) && (S_ISDIR(src.st_mode) || S_ISDIR(dst.st_mode)))
    move_aside(dir, name);
  if (::rename(from.c_str(), to.c_str()) != 0)
    throw failure("cannot move into place", to, errno);
}

void roll_forward(const fs::path& dir) {
  const fs::path journal = dir / kJournal;
  const std::vector<std::string> next = read_list(journal / kList);
  const std::vector<std::string> previous = read_list(dir / kList);
  for (const auto& name : next) {
    if (name != kResults)
      install(dir, name);
  }
  for (const auto& name : previous) {
    if (std::find(next.begin(), next.end(), name) == next.end() && exists_no_follow(dir / name))
      move_aside(dir, name);
  }
  install(dir, kResults);
  if (exists_no_follow(journal / kList) &&
      ::rename((journal / kList).c_str(), (dir / kList).c_str()) != 0)
    throw failure("cannot move into place", dir / kList, errno);
  std::error_code ec;
  fs::remove_all(journal, ec);
  fs::remove_all(dir / kOld, ec);
}

}  // namespace

void commit_staged_set(const fs::path& dir, const fs::path& staging) {
  write_list(staging / kList, staged_names(staging));
  if (::rename(staging.c_str(), (dir / kJournal).c_str()) != 0)
    throw failure("cannot commit", dir, errno);
  roll_forward(dir);
}

void recover_output_directory(const fs::path& dir) {
  if (exists_no_follow(dir / kJournal)) {
    if (exists_no_follow(dir / kJournal / kList))
      roll_forward(dir);
    else
      fs::remove_all(dir / kJournal);  // the list was installed: only the cleanup was left
  }
  std::error_code ec;
  fs::remove_all(dir / kOld, ec);
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().filename().string().rfind(kStagingPrefix, 0) == 0)
      fs::remove_all(e.path(), ec);
  }
}

}  // namespace cs::platform
