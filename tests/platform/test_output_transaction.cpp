// Requirement (issue 16): an output directory is one transaction. A second writer is refused
// while the first holds it; without commit the old set is untouched; after commit the new set
// is in place and files the user kept there survive; leftovers of an interrupted transaction
// are cleaned by the next; paths with control characters are refused.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

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

TEST(OutputTransaction, CommitReplacesTheSetAndKeepsOtherFiles) {
  cs::testing::TempDir tmp;
  const fs::path out = tmp.path() / "out";
  {
    OutputTransaction t(out);
    write(t.staging() / "results.json", "old");
    t.commit();
  }
  write(out / "notes.txt", "mine");
  {
    OutputTransaction t(out);
    write(t.staging() / "results.json", "new");
    fs::create_directory(t.staging() / "figures");
    write(t.staging() / "figures" / "a.png", "png");
    t.commit();
  }
  EXPECT_EQ(read(out / "results.json"), "new");
  EXPECT_EQ(read(out / "figures" / "a.png"), "png");
  EXPECT_EQ(read(out / "notes.txt"), "mine");
  for (const auto& e : fs::directory_iterator(tmp.path()))  // no staging left beside it
    EXPECT_EQ(e.path().filename().string().find("staging"), std::string::npos) << e.path();
}

TEST(OutputTransaction, WithoutCommitTheOldSetStays) {
  cs::testing::TempDir tmp;
  const fs::path out = tmp.path() / "out";
  {
    OutputTransaction t(out);
    write(t.staging() / "results.json", "old");
    t.commit();
  }
  {
    OutputTransaction t(out);
    write(t.staging() / "results.json", "half");
  }  // an error on the way: destroyed without commit
  EXPECT_EQ(read(out / "results.json"), "old");
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

TEST(OutputTransaction, StaleStagingOfAnInterruptedRunIsRemoved) {
  cs::testing::TempDir tmp;
  const fs::path stale = tmp.path() / ".out.staging-999999";
  fs::create_directory(stale);
  write(stale / "results.json", "stale");
  OutputTransaction t(tmp.path() / "out");
  EXPECT_FALSE(fs::exists(stale));
}

TEST(OutputTransaction, ControlCharactersAndBadParentsAreRefused) {
  cs::testing::TempDir tmp;
  EXPECT_THROW(OutputTransaction(tmp.path() / "a\nsystem \"touch x\"\n#"), PlatformError);
  EXPECT_THROW(OutputTransaction(tmp.path() / "tab\tname"), PlatformError);
  EXPECT_THROW(OutputTransaction(tmp.path() / "missing" / "out"), PlatformError);
  write(tmp.path() / "file", "x");
  EXPECT_THROW(OutputTransaction(tmp.path() / "file"), PlatformError);
  EXPECT_FALSE(fs::exists(tmp.path() / "x"));
  std::size_t n = 0;  // a refused transaction leaves no lock file behind
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path()))
    ++n;
  EXPECT_EQ(n, 1u);
}

}  // namespace
}  // namespace cs::platform
