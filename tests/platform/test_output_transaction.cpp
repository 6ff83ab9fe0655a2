// Requirement (issues 16 and 25): an output directory is the tool's own and one transaction.
// The tool creates and marks it, or takes an empty one, and refuses any other directory before
// writing anything; a second writer is refused while the first holds it; without commit the old
// set is untouched and a directory the transaction created is removed again; after commit the
// new set is in place, entries the user added keep their inode, and entries of the old set that
// the new one lacks are gone; a commit interrupted at any step is finished by the next
// transaction; nothing is ever written beside the directory.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <iterator>
#include <string>

#include "platform/output_commit.hpp"
#include "platform/output_transaction.hpp"
#include "platform/platform_error.hpp"
#include "support/temp_dir.hpp"

namespace cs::platform {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

ino_t inode(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::lstat(p.c_str(), &st), 0) << p;
  return st.st_ino;
}

/// The names in `dir`, sorted, one per line.
std::string listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string out;
  for (const auto& n : names)
    out += n + "\n";
  return out;
}

/// Commits a set of {results.json: `tag`, report.md: `tag`, figures/a.png: `tag`} (plus
/// regression.md when `with_regression`) into `dir`.
void commit_set(const fs::path& dir, const std::string& tag, bool with_regression = false) {
  OutputTransaction t(dir);
  t.write_text("results.json", tag);
  t.write_text("report.md", tag);
  t.write_text("figures/a.png", tag);
  if (with_regression)
    t.write_text("regression.md", tag);
  t.commit();
}

TEST(OutputTransaction, CreatesAndMarksTheDirectoryAndReturnsTheCommittedFiles) {
  cs::testing::TempDir tmp;
  OutputTransaction t(tmp.path() / "out");
  t.write_text("results.json", "new");
  t.write_text("figures/a.png", "png");
  EXPECT_EQ(t.commit(), (std::vector<std::string>{"figures/a.png", "results.json"}));
  EXPECT_NE(read(tmp.path() / "out" / ".contact-suite").find("format 1"), std::string::npos);
  EXPECT_EQ(listing(tmp.path() / "out"),
            ".contact-suite\n.contact-suite.set\nfigures\nresults.json\n");
  EXPECT_EQ(listing(tmp.path()), "out\n");  // nothing beside it: no lock, no staging
}

TEST(OutputTransaction, CommitReplacesOurEntriesAndKeepsTheUsersWithTheirInode) {
  cs::testing::TempDir tmp;
  const fs::path out = tmp.path() / "out";
  commit_set(out, "old", true);
  write(out / "notes.txt", "mine");
  fs::create_directory(out / "private");
  fs::permissions(out / "private", fs::perms::owner_all);
  const ino_t notes = inode(out / "notes.txt"), priv = inode(out / "private"), dir = inode(out);
  commit_set(out, "new");
  EXPECT_EQ(read(out / "results.json"), "new");
  EXPECT_EQ(read(out / "figures" / "a.png"), "new");
  EXPECT_FALSE(fs::exists(out / "regression.md"));  // the old set's, not in the new one
  EXPECT_EQ(read(out / "notes.txt"), "mine");
  EXPECT_EQ(inode(out / "notes.txt"), notes);
  EXPECT_EQ(inode(out / "private"), priv);
  EXPECT_EQ(fs::status(out / "private").permissions(), fs::perms::owner_all);
  EXPECT_EQ(inode(out), dir);
  EXPECT_EQ(listing(tmp.path()), "out\n");
}

TEST(OutputTransaction, WithoutCommitTheOldSetStays) {
  cs::testing::TempDir tmp;
  const fs::path out = tmp.path() / "out";
  commit_set(out, "old");
  {
    OutputTransaction t(out);
    t.write_text("results.json", "half");
  }  // an error on the way: destroyed without commit
  EXPECT_EQ(read(out / "results.json"), "old");
  EXPECT_EQ(listing(out), ".contact-suite\n.contact-suite.set\nfigures\nreport.md\nresults.json\n");
}

TEST(OutputTransaction, AFailedFirstTransactionLeavesNothing) {
  cs::testing::TempDir tmp;
  fs::create_directory(tmp.path() / "empty");
  {
    OutputTransaction fresh(tmp.path() / "fresh");
    OutputTransaction empty(tmp.path() / "empty");
    fresh.write_text("results.json", "x");
  }
  EXPECT_EQ(listing(tmp.path()), "empty\n");
  EXPECT_EQ(listing(tmp.path() / "empty"), "");
}

TEST(OutputTransaction, ASecondWriterIsRefusedWhileTheFirstHoldsIt) {
  cs::testing::TempDir tmp;
  OutputTransaction first(tmp.path() / "out");
  try {
    OutputTransaction second(tmp.path() / "out");
    FAIL() << "second writer accepted";
  } catch (const PlatformError& e) {
    EXPECT_NE(std::string(e.what()).find("another contact-suite process"), std::string::npos);
  }
}

// A kill after the journal was made, at each step of the roll-forward: the next transaction
// finishes the commit, so the directory holds the complete new set.
TEST(OutputTransaction, AnInterruptedCommitIsFinishedByTheNextTransaction) {
  for (int moved = 0; moved <= 3; ++moved) {
    cs::testing::TempDir tmp;
    const fs::path out = tmp.path() / "out";
    commit_set(out, "old", true);
    write(out / "notes.txt", "mine");
    // The journal as commit_staged_set leaves it, then `moved` entries already in place.
    const fs::path journal = out / ".contact-suite.commit";
    fs::create_directories(journal / "figures");
    write(journal / "figures" / "a.png", "new");
    write(journal / "report.md", "new");
    write(journal / "results.json", "new");
    write(journal / ".contact-suite.set", "figures\nreport.md\nresults.json\n");
    fs::create_directory(out / ".contact-suite.old");
    if (moved >= 1)
      fs::rename(out / "figures", out / ".contact-suite.old" / "figures");
    if (moved >= 2)
      fs::rename(journal / "figures", out / "figures");
    if (moved >= 3)
      fs::rename(journal / "report.md", out / "report.md");
    fs::create_directory(out / ".contact-suite.staging-999999");  // a killed run's staging
    { OutputTransaction next(out); }
    EXPECT_EQ(read(out / "results.json"), "new") << moved;
    EXPECT_EQ(read(out / "report.md"), "new") << moved;
    EXPECT_EQ(read(out / "figures" / "a.png"), "new") << moved;
    EXPECT_FALSE(fs::exists(out / "regression.md")) << moved;
    EXPECT_EQ(read(out / "notes.txt"), "mine");
    EXPECT_EQ(listing(out),
              ".contact-suite\n.contact-suite.set\nfigures\nnotes.txt\nreport.md\nresults.json\n")
        << moved;
  }
}

TEST(OutputTransaction, TenTransactionsLeaveNothingBesideTheDirectory) {
  cs::testing::TempDir tmp;
  for (int i = 0; i < 10; ++i)
    commit_set(tmp.path() / "out", std::to_string(i));
  EXPECT_EQ(listing(tmp.path()), "out\n");
  EXPECT_EQ(read(tmp.path() / "out" / "results.json"), "9");
}

/// Expects `dir` to be refused with a message holding `why`, and `parent` unchanged.
void expect_refused(const fs::path& dir, const std::string& why, const fs::path& parent) {
  const std::string before = listing(parent);
  try {
    OutputTransaction t(dir);
    FAIL() << dir << " accepted";
  } catch (const PlatformError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(why), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_EQ(listing(parent), before) << dir;
}

TEST(OutputTransaction, DirectoriesItMayNotUseAreRefusedWithNothingCreated) {
  cs::testing::TempDir tmp;
  const fs::path& t = tmp.path();
  expect_refused(t / "a\nsystem \"touch x\"\n#", "control character", t);
  expect_refused(t / "tab\tname", "control character", t);
  expect_refused(t / "missing" / "out", "does not exist", t);
  write(t / "file", "x");
  expect_refused(t / "file", "is not a directory", t);
  fs::create_directory(t / "home");
  write(t / "home" / "notes.txt", "mine");
  expect_refused(t / "home", "not empty and was not made by contact-suite", t / "home");
  fs::create_directory_symlink(t / "home", t / "link");
  expect_refused(t / "link", "symbolic link", t / "home");
  fs::create_directory(t / "future");
  write(t / "future" / ".contact-suite", "contact-suite output directory\nformat 99\n");
  expect_refused(t / "future", "newer contact-suite", t / "future");
  expect_refused("/", "not empty and was not made by contact-suite", "/");
  EXPECT_EQ(listing(t), "file\nfuture\nhome\nlink\n");
}

TEST(OutputTransaction, ASymlinkToADirectoryItMadeIsFollowed) {
  cs::testing::TempDir tmp;
  commit_set(tmp.path() / "real", "old");
  fs::create_directory_symlink(tmp.path() / "real", tmp.path() / "link");
  commit_set(tmp.path() / "link", "new");
  EXPECT_TRUE(fs::is_symlink(tmp.path() / "link"));
  EXPECT_EQ(read(tmp.path() / "real" / "results.json"), "new");
}

TEST(OutputTransaction, AnEmptyMarkHandsADirectoryOver) {
  cs::testing::TempDir tmp;
  const fs::path out = tmp.path() / "older";
  fs::create_directory(out);
  write(out / "results.json", "older");
  write(out / ".contact-suite", "");
  commit_set(out, "new");
  EXPECT_EQ(read(out / "results.json"), "new");
  EXPECT_NE(read(out / ".contact-suite").find("format 1"), std::string::npos);
}

}  // namespace
}  // namespace cs::platform
