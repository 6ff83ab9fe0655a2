#include "platform/output_directory.hpp"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "platform/platform_error.hpp"

namespace cs::platform {
namespace fs = std::filesystem;
namespace {

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

/// "output directory 'X' " + what: every refusal starts so.
PlatformError refusal(const fs::path& shown, const std::string& what) {
  return PlatformError("output directory " + quoted(shown) + " " + what);
}

/// The format a mark names: 1 for an empty mark, -1 when the text is not a mark.
int mark_format(const fs::path& mark) {
  std::ifstream in(mark);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (text.empty())
    return 1;
  if (text.rfind("contact-suite output directory\n", 0) != 0)
    return -1;
  const auto at = text.find("\nformat ");
  if (at == std::string::npos)
    return -1;
  try {
    return std::stoi(text.substr(at + 8));
  } catch (const std::exception&) {
    return -1;
  }
}

/// True when `dir` holds the mark as a regular file (a link named so does not count).
bool has_mark(const fs::path& dir) {
  struct stat st {};
  return ::lstat((dir / kOwnershipMark).c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

/// True when `dir` has no entry; reads at most one.
bool is_empty_directory(const fs::path& dir) {
  std::unique_ptr<DIR, int (*)(DIR*)> d(::opendir(dir.c_str()), ::closedir);
  if (!d)
    return false;
  while (const dirent* e = ::readdir(d.get())) {
    if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0)
      return false;
  }
  return true;
}

void require_writable(const fs::path& dir, const fs::path& shown) {
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw refusal(
        shown, std::string("is not writable (") + std::strerror(errno) + "); choose another --out");
}

OutputDirectory check_absent(const fs::path& path, const fs::path& shown) {
  const fs::path parent = path.parent_path();
  struct stat st {};
  if (::stat(parent.c_str(), &st) != 0)
    throw refusal(shown, "cannot be created: its parent " + quoted(parent) +
                             " does not exist; create it first");
  if (!S_ISDIR(st.st_mode))
    throw refusal(shown, "cannot be created: " + quoted(parent) + " is not a directory");
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    throw refusal(shown, "cannot be created: its parent " + quoted(parent) + " is not writable (" +
                             std::strerror(errno) + ")");
  return {path, OutputDirectoryState::absent};
}

OutputDirectory check_existing(const fs::path& path, const fs::path& shown) {
  if (has_mark(path)) {
    const int format = mark_format(path / kOwnershipMark);
    if (format < 1)
      throw refusal(shown, "has a " + std::string(kOwnershipMark) +
                               " file that is not contact-suite's mark; choose another --out");
    if (format > kOutputFormat)
      throw refusal(shown, "was written by a newer contact-suite (output format " +
                               std::to_string(format) + ", this one writes " +
                               std::to_string(kOutputFormat) + "); choose another --out");
    require_writable(path, shown);
    return {path, OutputDirectoryState::owned};
  }
  if (!is_empty_directory(path))
    throw refusal(shown, "is not empty and was not made by contact-suite (no " +
                             std::string(kOwnershipMark) +
                             " file in it); choose a new or empty directory");
  require_writable(path, shown);
  return {path, OutputDirectoryState::empty};
}

/// `p` absolute, with symbolic links of its existing part resolved and no trailing separator.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec)
    r = fs::absolute(p).lexically_normal();
  return r.has_filename() ? r : r.parent_path();
}

/// The names of the committed set of the output directory `dir` (none when it has no list).
std::vector<std::string> set_entries(const fs::path& dir) {
  std::vector<std::string> names;
  std::ifstream list(dir / (std::string(kOwnershipMark) + ".set"));
  for (std::string line; std::getline(list, line);)
    names.push_back(line);
  return names;
}

/// Whether the resolved `f` is directly in the resolved `d` or below a directory of its set.
bool in_set(const fs::path& f, const fs::path& d) {
  const auto [at_d, at_f] = std::mismatch(d.begin(), d.end(), f.begin(), f.end());
  if (at_d != d.end() || at_f == f.end())
    return false;  // not below d (or d itself)
  if (std::next(at_f) == f.end())
    return true;  // directly in d
  const std::vector<std::string> entries = set_entries(d);
  return std::ranges::find(entries, at_f->string()) != entries.end();
}

}  // namespace

void require_outside_set(const fs::path& file, const fs::path& dir, const char* what) {
  if (!file.empty() && !dir.empty() && in_set(resolved(file), resolved(dir))) {
    throw PlatformError(std::string(what) + " " + quoted(file) + " is in the output directory " +
                        quoted(dir) +
                        ", among the set this command replaces; choose another --out or move "
                        "the file");
  }
}

void require_outside_sets(const fs::path& file, const char* what) {
  if (file.empty())
    return;
  const fs::path f = resolved(file);
  std::error_code ec;
  for (fs::path dir = f.parent_path();; dir = dir.parent_path()) {
    if (fs::is_regular_file(dir / kOwnershipMark, ec) && in_set(f, dir)) {
      throw PlatformError(std::string(what) + " " + quoted(file) + " is in " + quoted(dir) +
                          ", among the set of a contact-suite output directory; write it "
                          "elsewhere");
    }
    if (dir == dir.root_path() || dir.empty())
      break;
  }
}

void require_distinct(const fs::path& a, const char* what_a, const fs::path& b,
                      const char* what_b) {
  if (!a.empty() && !b.empty() && resolved(a) == resolved(b)) {
    throw PlatformError(std::string(what_a) + " and " + what_b + " name one file, " + quoted(a) +
                        "; give two");
  }
}

void require_printable_path(const fs::path& path, const char* what) {
  for (unsigned char c : path.string()) {
    if (c < 0x20 || c == 0x7f) {
      throw PlatformError(std::string(what) +
                          ": the path holds a control character (newline, tab, ...); "
                          "choose a name without one");
    }
  }
}

std::string ownership_mark_text() {
  return "contact-suite output directory\nformat " + std::to_string(kOutputFormat) +
         "\nEntries beside this file that contact-suite did not write are left alone.\n";
}

bool is_bookkeeping_name(const std::string& name) {
  return name.rfind(kOwnershipMark, 0) == 0;
}

OutputDirectory check_output_directory(const fs::path& dir) {
  require_printable_path(dir, "output directory");
  if (dir.empty())
    throw PlatformError("output directory: empty path");
  fs::path path = fs::absolute(dir).lexically_normal();
  if (!path.has_filename() && path != path.root_path())
    path = path.parent_path();  // "out/" is "out"
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) {
    if (errno != ENOENT)
      throw refusal(dir, std::string("cannot be examined: ") + std::strerror(errno));
    return check_absent(path, dir);
  }
  if (S_ISLNK(st.st_mode)) {
    std::error_code ec;
    const fs::path target = fs::canonical(path, ec);
    if (ec || !fs::is_directory(target, ec) || !has_mark(target))
      throw refusal(dir, "is a symbolic link to " + (ec ? std::string("nothing") : quoted(target)) +
                             ", not a directory contact-suite made; give a new directory "
                             "or the real path of one contact-suite made");
    return check_existing(target, dir);
  }
  if (!S_ISDIR(st.st_mode))
    throw refusal(dir, "exists and is not a directory; choose another --out");
  return check_existing(path, dir);
}

}  // namespace cs::platform
