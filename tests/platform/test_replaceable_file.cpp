// Single files the tool writes where the user names them: replace_written_file checks again at
// the rename, so a file that appears at the path while a run works is the user's and is kept.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "platform/platform_error.hpp"
#include "platform/replaceable_file.hpp"
#include "support/temp_dir.hpp"

namespace cs::platform {
namespace {

namespace fs = std::filesystem;

class ReplaceWrittenFile : public ::testing::Test {
 protected:
  fs::path path(const std::string& name) const { return dir_.path() / name; }
  static std::string read(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  /// The directory's entries: no temporary file may be left.
  int entries() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_.path()))
      ++n;
    return n;
  }

  testing::TempDir dir_;
};

const std::string kOurs = written_mark() + "\nnew\n";

TEST_F(ReplaceWrittenFile, CreatesAnAbsentFile) {
  replace_written_file(path("a.xml"), kOurs, "--junit");
  EXPECT_EQ(read(path("a.xml")), kOurs);
  EXPECT_EQ(fs::status(path("a.xml")).permissions() & fs::perms::all, fs::perms(0644));
  EXPECT_EQ(entries(), 1);
}

TEST_F(ReplaceWrittenFile, ReplacesAFileItWrote) {
  std::ofstream(path("a.xml")) << written_mark() << "\nold\n";
  replace_written_file(path("a.xml"), kOurs, "--junit");
  EXPECT_EQ(read(path("a.xml")), kOurs);
  EXPECT_EQ(entries(), 1);
}

TEST_F(ReplaceWrittenFile, AnOlderVersionsFileIsKnownByItsMark) {
  std::ofstream(path("a.xml")) << "<testsuites name=\"contact-suite x\">";
  replace_written_file(path("a.xml"), kOurs, "--junit", "<testsuites name=\"contact-suite ");
  EXPECT_EQ(read(path("a.xml")), kOurs);
}

// Requirement: a file of the user's that appeared after the start-up check (a long run) is
// kept: the call refuses in one line naming the option and the path, and leaves no temporary.
TEST_F(ReplaceWrittenFile, KeepsAFileTheUserPutThereMeanwhile) {
  require_replaceable(path("a.xml"), "--junit");  // the start-up check: nothing there yet
  std::ofstream(path("a.xml")) << "the user's notes\n";
  try {
    replace_written_file(path("a.xml"), kOurs, "--junit");
    FAIL() << "replaced a file the tool did not write";
  } catch (const PlatformError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--junit " + path("a.xml").string()), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_EQ(read(path("a.xml")), "the user's notes\n");
  EXPECT_EQ(entries(), 1);
}

TEST_F(ReplaceWrittenFile, KeepsALinkTheUserPutThereMeanwhile) {
  std::ofstream(path("target")) << written_mark();
  fs::create_symlink(path("target"), path("a.vtu"));
  EXPECT_THROW(replace_written_file(path("a.vtu"), kOurs, "--vtu"), PlatformError);
  EXPECT_TRUE(fs::is_symlink(path("a.vtu")));
  EXPECT_EQ(read(path("target")), written_mark());
  EXPECT_EQ(entries(), 2);
}

TEST_F(ReplaceWrittenFile, AMissingDirectoryIsAnOutputError) {
  EXPECT_THROW(replace_written_file(path("missing/a.xml"), kOurs, "--junit"), OutputError);
  EXPECT_EQ(entries(), 0);
}

}  // namespace
}  // namespace cs::platform
