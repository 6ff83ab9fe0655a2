// Requirement (issue 25, item 1): output directories the tool owns. Every command that writes
// (run, merge, report, grade, export) refuses, with exit code 2 and one line naming the
// directory, a non-empty directory it did not make, and changes nothing in it: not a mode, an
// owner, an inode or a byte, whatever it holds (a private directory of another user, a setgid
// directory, a mount point), and `--out /` is refused at once. A directory it made before keeps
// the user's files beside the new set, with their inode. No lock or staging file is left beside
// the directory. Bad --out values (a file, a symbolic link to a directory the tool did not
// make, an unwritable parent, a control character) get exit 2, one line, and nothing created.

#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "apps/cli_support.hpp"

namespace cs::apps::testing {
namespace {

namespace fs = std::filesystem;

/// What must not change about one entry.
struct EntryState {
  mode_t mode;
  uid_t uid;
  gid_t gid;
  ino_t inode;
  std::string content;  ///< a regular file's bytes, a link's target
  bool operator==(const EntryState&) const = default;
};

/// Every entry under `root` (and root itself), by path, without following links.
std::map<std::string, EntryState> snapshot(const fs::path& root) {
  std::map<std::string, EntryState> out;
  auto add = [&out](const fs::path& p) {
    struct stat st {};
    ::lstat(p.c_str(), &st);
    std::string content;
    if (S_ISREG(st.st_mode))
      content = read_text(p);
    else if (S_ISLNK(st.st_mode))
      content = fs::read_symlink(p).string();
    out[p.string()] = {st.st_mode, st.st_uid, st.st_gid, st.st_ino, content};
  };
  add(root);
  for (const auto& e : fs::recursive_directory_iterator(root))
    add(e.path());
  return out;
}

bool is_root() {
  return ::geteuid() == 0;
}

/// The names in `dir`, sorted.
std::vector<std::string> names(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// A tmpfs mounted on `dir` for the life of the object (root only).
class Tmpfs {
 public:
  Tmpfs(const fs::path& dir, const std::string& options) : dir_(dir) {
    fs::create_directories(dir);
    mounted_ = ::mount("tmpfs", dir.c_str(), "tmpfs", 0, options.c_str()) == 0;
  }
  ~Tmpfs() {
    if (mounted_)
      ::umount2(dir_.c_str(), MNT_DETACH);
  }
  Tmpfs(const Tmpfs&) = delete;
  Tmpfs& operator=(const Tmpfs&) = delete;
  bool mounted() const { return mounted_; }

 private:
  fs::path dir_;
  bool mounted_ = false;
};

const std::vector<std::string> kTinyRun = {
    "run",          "--problems", "P_p",        "--meshes", "C",      "--elements", "Q4",
    "--algorithms", "AL",         "--contacts", "ss",       "--jobs", "1"};

CliRun run_into(const fs::path& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = kTinyRun;
  args.insert(args.end(), extra.begin(), extra.end());
  args.push_back("--out");
  args.push_back(out.string());
  return run_cli(args);
}

void expect_one_line_refusal(const CliRun& r, const std::string& why) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

/// Every writing command with --out `dir`, each refused.
void expect_every_command_refuses(const fs::path& dir, const std::string& why) {
  const std::string d = dir.string();
  expect_one_line_refusal(run_into(dir), why);
  expect_one_line_refusal(run_cli({"report", "--results", "/nonexistent.json", "--out", d}), why);
  expect_one_line_refusal(run_cli({"merge", d, "/nonexistent.json"}), why);
  expect_one_line_refusal(
      run_cli({"grade", "--import", "/nonexistent.csv", "--solver-name", "x", "--out", d}), why);
  expect_one_line_refusal(run_cli({"export", "--problems", "P_p", "--meshes", "C", "--out", d}),
                          why);
}

// The probes of the issue: a home-like directory with a private directory of another user, a
// setgid group directory and a mount point.
TEST(OutputOwnership, ANonEmptyDirectoryItDidNotMakeIsRefusedAndUnchanged) {
  TempDir tmp;
  const fs::path home = tmp.path() / "home";
  fs::create_directories(home / ".ssh");
  std::ofstream(home / ".ssh" / "id") << "secret\n";
  std::ofstream(home / "notes.txt") << "mine\n";
  fs::create_directories(home / "shared");
  ::chmod((home / ".ssh").c_str(), 0700);
  ::chmod((home / "shared").c_str(), 02770);
  if (is_root()) {
    ASSERT_EQ(::chown((home / ".ssh").c_str(), 65534, 65534), 0);  // nobody:nogroup
    ASSERT_EQ(::chown((home / "shared").c_str(), 65534, 65534), 0);
    ::chmod((home / "shared").c_str(), 02770);  // chown clears setgid
  }
  Tmpfs mount(home / "mnt", "size=1m");
  if (mount.mounted())
    std::ofstream(home / "mnt" / "on-the-mount") << "x\n";
  const auto before = snapshot(home);
  expect_every_command_refuses(home, "not empty and was not made by contact-suite");
  EXPECT_EQ(snapshot(home), before);
  EXPECT_EQ(names(tmp.path()), std::vector<std::string>{"home"});
  if (!mount.mounted())
    GTEST_SKIP() << "the mount point probe needs root (mount -t tmpfs); the rest passed";
}

TEST(OutputOwnership, TheFileSystemRootIsRefusedAtOnce) {
  const auto before = names("/");
  const auto start = std::chrono::steady_clock::now();
  expect_every_command_refuses("/", "'/' is not empty and was not made by contact-suite");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(names("/"), before);
  // Five refusals, each one process start and a few system calls; walking / would take far
  // longer than 5 s.
  EXPECT_LT(seconds, 5.0);
}

TEST(OutputOwnership, ItsOwnDirectoryKeepsTheUsersFilesAndGetsTheNewSet) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  ASSERT_EQ(run_into(out, {"--no-report"}).exit_code, 0);
  std::ofstream(out / "notes.txt") << "the user's notes\n";
  fs::create_directory(out / "private");
  ::chmod((out / "private").c_str(), 0700);
  const auto users = snapshot(out / "private");
  struct stat notes_before {};
  ::lstat((out / "notes.txt").c_str(), &notes_before);
  const std::string old_results = read_text(out / "results.json");
  const auto r = run_into(out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  struct stat notes_after {};
  ::lstat((out / "notes.txt").c_str(), &notes_after);
  EXPECT_EQ(notes_after.st_ino, notes_before.st_ino);
  EXPECT_EQ(read_text(out / "notes.txt"), "the user's notes\n");
  EXPECT_EQ(snapshot(out / "private"), users);
  EXPECT_NE(read_text(out / "results.json"), old_results);  // a new run: a new start time
  EXPECT_TRUE(fs::exists(out / "report.md"));
  EXPECT_TRUE(fs::exists(out / "results.csv"));
}

TEST(OutputOwnership, TenRunsLeaveNoLockOrStagingBesideTheDirectory) {
  TempDir tmp;
  for (int i = 0; i < 10; ++i)
    ASSERT_EQ(run_into(tmp.path() / "out", {"--no-report"}).exit_code, 0);
  EXPECT_EQ(names(tmp.path()), std::vector<std::string>{"out"});
  for (const auto& n : names(tmp.path() / "out"))
    EXPECT_TRUE(n == "results.json" || n == ".contact-suite" || n == ".contact-suite.set") << n;
}

TEST(OutputOwnership, BadOutValuesAreRefusedWithNothingCreated) {
  TempDir tmp;
  const fs::path& t = tmp.path();
  std::ofstream(t / "file") << "x\n";
  fs::create_directory(t / "theirs");
  std::ofstream(t / "theirs" / "data") << "y\n";
  fs::create_directory_symlink(t / "theirs", t / "link");
  fs::create_directory(t / "ro");
  Tmpfs read_only(t / "ro", "size=1m");
  if (read_only.mounted())
    ::mount(nullptr, (t / "ro").c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr);
  else
    ::chmod((t / "ro").c_str(), 0555);  // refuses a non-root user
  const auto before = snapshot(t);
  expect_one_line_refusal(run_into(t / "file"), "exists and is not a directory");
  expect_one_line_refusal(run_into(t / "link"), "is a symbolic link");
  expect_one_line_refusal(run_into(t / "ro" / "out"), "is not writable");
  expect_one_line_refusal(run_into(t / "a\nb"), "control character");
  expect_one_line_refusal(run_into(t / "missing" / "out"), "does not exist");
  EXPECT_EQ(snapshot(t), before);
}

// Requirement: no command loses what a user has through a file it reads or writes beside --out.
// An input among the set of the output directory (report --results out/results.json --out out
// would remove it with the old set), a --junit, --summary or --vtu among the set of any output
// directory of the tool (overwriting its results.json or its mark), the two CI files as one, and
// a CI file or an updated baseline that is also the gate's input: each refused with exit 2 and
// one line, nothing changed. Files in the user's own subdirectory of an output directory (a
// Slurm run's shard-K/) stay usable.
TEST(OutputOwnership, FilesAmongASetAreNeitherReadIntoNorWrittenOver) {
  TempDir tmp;
  const fs::path& t = tmp.path();
  const fs::path out = t / "out";
  ASSERT_EQ(run_into(out, {"--no-report"}).exit_code, 0);
  fs::create_directory(out / "shard-1");
  fs::copy_file(out / "results.json", out / "shard-1" / "results.json");
  fs::copy_file(out / "results.json", t / "results.json");
  const std::string o = out.string(), results = (out / "results.json").string();
  const auto before = snapshot(t);
  expect_one_line_refusal(run_cli({"report", "--results", results, "--out", o, "--no-figures"}),
                          "among the set");
  expect_one_line_refusal(run_cli({"merge", o, results}), "among the set");
  expect_one_line_refusal(run_into(out, {"--junit", results}), "among the set");
  expect_one_line_refusal(run_into(t / "other", {"--junit", (out / ".contact-suite").string()}),
                          "among the set");
  expect_one_line_refusal(run_into(t / "other", {"--junit", (t / "ci.xml").string(), "--summary",
                                                 (t / "ci.xml").string()}),
                          "name one file");
  expect_one_line_refusal(run_cli({"case", "P_p", "--vtu", results}), "among the set");
  const std::string copy = (t / "results.json").string();
  expect_one_line_refusal(run_cli({"gate", "--baseline", copy, "--results", copy, "--update"}),
                          "name one file");
  expect_one_line_refusal(
      run_cli({"gate", "--baseline", "b.json", "--results", copy, "--junit", copy}),
      "name one file");
  EXPECT_EQ(snapshot(t), before);
  // The user's own subdirectory: read from (a Slurm merge) and written into.
  const auto merged = run_cli({"merge", o, (out / "shard-1" / "results.json").string()});
  EXPECT_EQ(merged.exit_code, 0) << merged.err;
  const auto vtu = run_cli({"case", "P_p", "--vtu", (out / "shard-1" / "p.vtu").string()});
  EXPECT_EQ(vtu.exit_code, 0) << vtu.err;
  EXPECT_TRUE(fs::exists(out / "shard-1" / "p.vtu"));
}

// Requirement (issue 25, item 3): disk full. A run into a small tmpfs that fills up fails with
// a line naming the cause, and the previous set stays whole; once space is back the next run
// succeeds and leaves no staging behind.
TEST(OutputOwnership, DiskFullGivesAClearErrorAndKeepsTheOldSet) {
  if (!is_root())
    GTEST_SKIP() << "needs root to mount a small tmpfs";
  TempDir tmp;
  Tmpfs disk(tmp.path() / "disk", "size=4m");
  ASSERT_TRUE(disk.mounted());
  const fs::path out = tmp.path() / "disk" / "out";
  ASSERT_EQ(run_into(out).exit_code, 0);
  const auto old_set = snapshot(out);
  {  // fill the disk: a file as large as the space left
    std::ofstream fill(tmp.path() / "disk" / "fill", std::ios::binary);
    const std::string block(64 * 1024, 'x');
    while (fill.write(block.data(), block.size()))
      fill.flush();
  }
  const auto r = run_into(out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(snapshot(out), old_set);
  fs::remove(tmp.path() / "disk" / "fill");
  ASSERT_EQ(run_into(out).exit_code, 0);
  for (const auto& n : names(out))
    EXPECT_EQ(n.find("staging"), std::string::npos) << n;
}

// Requirement (issue 25, item 3): memory. A selection whose largest model is estimated above
// what the run may use is refused before it starts (exit 2, nothing created); one whose default
// schedule would exceed it is scheduled to fit, and says so.
TEST(OutputOwnership, MemoryBeyondTheLimitIsRefusedOrScheduledToFit) {
  TempDir tmp;
  // S(1/7) F Q8: cost 16 x 30 x 3 = 1440 units, 3.9 GiB at 2.75 MiB a unit; 0.5 GiB cannot hold it.
  const auto refused = run_cli({"run", "--problems", "S_1_7", "--meshes", "F", "--elements", "Q8",
                                "--max-memory", "0.5", "--out", (tmp.path() / "big").string()});
  expect_one_line_refusal(refused, "refused before starting: the largest model");
  EXPECT_NE(refused.err.find("S_1_7/F/Q8"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(tmp.path() / "big"));
  // P_p C and M Q4: costs 1 and 4, 2.75 and 11 MiB; the default budget 16.5 MiB exceeds 0.012
  // GiB (12.3 MiB), which still holds the largest: scheduled to fit.
  const auto fitted = run_cli({"run", "--problems", "P_p", "--meshes", "C,M", "--elements", "Q4",
                               "--algorithms", "AL", "--contacts", "ss", "--max-memory", "0.012",
                               "--no-report", "--out", (tmp.path() / "fit").string()});
  EXPECT_EQ(fitted.exit_code, 0) << fitted.err;
  EXPECT_NE(fitted.err.find("memory: scheduled to fit"), std::string::npos) << fitted.err;
}

}  // namespace
}  // namespace cs::apps::testing
