// The whole report: files written from a results document in memory, bad input rejected with
// one line (a results file by the one reader of results, schema/), and the output directory
// untouched on failure (nothing half-written, nothing the user had lost).

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include <gtest/gtest.h>
#include <CLI/CLI.hpp>

#include "apps/report_command.hpp"
#include "report_test_support.hpp"
#include "reports/pages/run_page.hpp"
#include "reports/report_error.hpp"
#include "reports/report_writer.hpp"
#include "schema/combined_results.hpp"
#include "schema/schema_error.hpp"
#include "suites/run_environment.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::sample_path;
using testing::TempDir;
using testing::write_text;

ReportOptions options_for(const fs::path& out) {
  ReportOptions o;
  o.out_dir = out;
  o.study_data = testing::study_dir();
  o.figures = false;  // figures have their own test
  return o;
}

const schema::ResultsDocument& sample() {
  static const schema::ResultsDocument doc = schema::read_results_file(sample_path());
  return doc;
}

/// What `report --results FILE` does: the file through the one reader, then the report.
ReportOutcome report_from_file(const fs::path& results, const ReportOptions& options) {
  return write_report(schema::read_results_file(results), options);
}

/// A directory an earlier report made (it carries the mark), with the user's files in it, to
/// check that a failed report leaves it alone.
struct UserDir {
  explicit UserDir(const fs::path& root) : path(root / "out") {
    fs::create_directories(path / "figures");
    write_text(path / ".contact-suite", "");
    write_text(path / "report.md", "the user's previous report\n");
    write_text(path / "notes.txt", "the user's own notes\n");
    write_text(path / "figures" / "mine.png", "not really a png");
  }
  void expect_untouched() const {
    EXPECT_EQ(read_text(path / "report.md"), "the user's previous report\n");
    EXPECT_EQ(read_text(path / "notes.txt"), "the user's own notes\n");
    EXPECT_EQ(read_text(path / "figures" / "mine.png"), "not really a png");
    int entries = 0;
    for (const auto& e : fs::directory_iterator(path)) {
      if (e.path().filename().string().rfind(".contact-suite", 0) == 0)
        continue;  // the mark, which a report writes into an empty mark
      ++entries;
      EXPECT_EQ(e.path().filename().string().find("staging"), std::string::npos) << e.path();
    }
    EXPECT_EQ(entries, 3);  // report.md, notes.txt, figures/: nothing added
    EXPECT_FALSE(fs::exists(path / "results.csv"));
  }
  fs::path path;
};

TEST(ReportWriter, WritesReportCsvAndRegression) {
  TempDir tmp;
  auto o = options_for(tmp.path() / "new");  // created: its parent exists
  o.baseline = sample_path();
  const auto outcome = write_report(sample(), o);
  EXPECT_EQ(outcome.n_cases, 59);
  for (const char* file : {"regression.md", "report.md", "results.csv", "problem-H_p.md",
                           "appendix-tables-2.md", "appendix-run.md"})
    EXPECT_NE(std::find(outcome.files.begin(), outcome.files.end(), file), outcome.files.end())
        << file;
  const std::string md = read_text(o.out_dir / "report.md");
  // The verdict first, then the claims, then the links to the pages.
  std::vector<std::string> headings;
  for (std::size_t at = md.find("\n## "); at != std::string::npos; at = md.find("\n## ", at + 1))
    headings.push_back(md.substr(at + 4, md.find('\n', at + 1) - at - 4));
  EXPECT_EQ(headings, (std::vector<std::string>{"Verdict: which contact option to trust",
                                                "The study's claims, checked",
                                                "One page per problem", "Appendices"}));
  EXPECT_NE(md.find("57 converged, 1 not converged, 1 failed"), std::string::npos);
  EXPECT_NE(md.find("[regression.md](regression.md)"), std::string::npos);
  // Every page report.md links exists.
  for (std::size_t at = md.find("]("); at != std::string::npos; at = md.find("](", at + 1)) {
    const std::string link = md.substr(at + 2, md.find(')', at) - at - 2);
    EXPECT_TRUE(fs::exists(o.out_dir / link)) << link;
  }
  const std::string run = read_text(o.out_dir / "appendix-run.md");
  EXPECT_NE(run.find("| solver.factorization | CHOLMOD supernodal |"), std::string::npos);
  EXPECT_NE(run.find("| `" + sample_path().string() + "` |"), std::string::npos);
  for (const auto& e : fs::directory_iterator(o.out_dir))
    EXPECT_EQ(e.path().filename().string().find("staging"), std::string::npos);
}

TEST(ReportWriter, ReplacesItsOwnFilesAndKeepsTheUsers) {
  TempDir tmp;
  UserDir user(tmp.path());
  write_report(sample(), options_for(user.path));
  EXPECT_NE(read_text(user.path / "report.md").find("\n## Verdict"), std::string::npos);
  EXPECT_EQ(read_text(user.path / "notes.txt"), "the user's own notes\n");
  EXPECT_TRUE(fs::exists(user.path / "results.csv"));
}

// Requirement: a document built in memory (not read from a file) is reported the same way,
// without naming a results file.
TEST(ReportWriter, ReportsADocumentInMemory) {
  TempDir tmp;
  schema::ResultsDocument doc = sample();
  doc.source.clear();
  const auto outcome = write_report(doc, options_for(tmp.path() / "out"));
  EXPECT_EQ(outcome.n_cases, 59);
  const std::string md = read_text(tmp.path() / "out" / "report.md");
  write_report(sample(), options_for(tmp.path() / "file"));
  EXPECT_EQ(md, read_text(tmp.path() / "file" / "report.md"));
  const std::string run = read_text(tmp.path() / "out" / "appendix-run.md");
  EXPECT_EQ(run.find(sample_path().string()), std::string::npos);
  EXPECT_NE(run.find("| `(this run)` |"), std::string::npos);
}

/// A results file that `report` refuses. Its text is made when the test runs, not when the
/// tests are registered: every test of this program runs in a process of its own, and each
/// would otherwise parse and write the sample results for all of them.
struct BadInput {
  const char* name;
  std::string (*content)();  ///< the results file's text; nullptr: no file
  const char* message;       ///< expected in the error
};

class ReportWriterBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ReportWriterBadInput, OneLineErrorAndTheDirectoryUntouched) {
  const BadInput& bad = GetParam();
  TempDir tmp;
  UserDir user(tmp.path());
  const fs::path results = tmp.path() / "results.json";
  if (bad.content != nullptr)
    write_text(results, bad.content());
  try {
    report_from_file(results, options_for(user.path));
    FAIL() << "no error for " << bad.name;
  } catch (const schema::SchemaError& e) {  // exit code 2 in main()
    const std::string what = e.what();
    EXPECT_NE(what.find(bad.message), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  user.expect_untouched();
  // A directory that did not exist is not created either.
  EXPECT_THROW(report_from_file(results, options_for(tmp.path() / "fresh")), schema::SchemaError);
  EXPECT_FALSE(fs::exists(tmp.path() / "fresh"));
}

std::string truncated_sample() {
  const std::string text = read_text(sample_path());
  return text.substr(0, text.size() / 2);
}

std::string sample_with(const char* key, const nlohmann::json& value) {
  auto doc = testing::sample_json();
  doc[key] = value;
  return doc.dump();
}

std::string sample_with_bad_case() {
  auto doc = testing::sample_json();
  doc["cases"][3]["mesh"] = "X";
  return doc.dump();
}

std::string sample_with_unknown_algorithm() {
  auto doc = testing::sample_json();
  doc["rows"][1]["algorithm"] = "IMCX";
  return doc.dump();
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, ReportWriterBadInput,
    ::testing::Values(
        BadInput{"missing", nullptr, "does not exist"},
        BadInput{"empty", [] { return std::string(); }, "is not valid JSON"},
        BadInput{"not JSON", [] { return std::string("results, but in prose"); },
                 "is not valid JSON"},
        BadInput{"truncated", truncated_sample, "is not valid JSON (truncated?)"},
        BadInput{"other schema", [] { return sample_with("schema", "someone/else"); },
                 "not a contact-suite results file"},
        BadInput{"older version", [] { return sample_with("schema_version", 2); },
                 "schema_version: 2 is not supported (this build reads 3 and 4)"},
        BadInput{"no cases", [] { return sample_with("cases", 7); }, ".cases: is not an array"},
        BadInput{"bad case", sample_with_bad_case,
                 "cases[3].mesh: unknown mesh level \"X\" (expected one of: C, M, F, VF)"},
        BadInput{"unknown algorithm", sample_with_unknown_algorithm,
                 "rows[1].algorithm: unknown algorithm \"IMCX\""}),
    [](const auto& info) {
      std::string name = info.param.name;
      for (char& c : name)
        c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

TEST(ReportWriter, BadBaselineOrStudyDataLeavesTheDirectoryUntouched) {
  TempDir tmp;
  UserDir user(tmp.path());
  auto o = options_for(user.path);
  o.baseline = tmp.path() / "no-such-baseline.json";
  EXPECT_THROW(write_report(sample(), o), schema::SchemaError);
  user.expect_untouched();
  o = options_for(user.path);
  o.study_data = tmp.path();
  EXPECT_THROW(write_report(sample(), o), schema::SchemaError);
  user.expect_untouched();
}

TEST(ReportWriter, OutputThatIsAFileIsAnError) {
  TempDir tmp;
  write_text(tmp.path() / "file", "x");
  EXPECT_THROW(write_report(sample(), options_for(tmp.path() / "file")), std::invalid_argument);
  EXPECT_EQ(read_text(tmp.path() / "file"), "x");
}

/// Runs `report ARGS` through the subcommand as main() would; returns what it threw.
std::string run_command(std::vector<std::string> args) {
  CLI::App app;
  apps::add_report_command(app);
  args.insert(args.begin(), "report");
  args.insert(args.begin(), "contact-suite");
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const schema::SchemaError& e) {
    return std::string("bad input: ") + e.what();
  } catch (const std::invalid_argument& e) {
    return std::string("bad input: ") + e.what();
  } catch (const CLI::ParseError& e) {
    return std::string("parse error: ") + e.what();
  }
  return "ok";
}

// Requirement: `report --results FILE` reads FILE through the one reader of results: a file it
// rejects is bad input (schema::SchemaError, exit code 2), named in one line.
TEST(ReportCommand, ParsesOptionsAndReportsBadInputAsSuch) {
  TempDir tmp;
  const std::string study = testing::study_dir().string();
  const std::string out = (tmp.path() / "out").string();
  EXPECT_EQ(run_command({"--results", sample_path().string(), "--out", out, "--study-data", study,
                         "--no-figures", "--baseline", sample_path().string()}),
            "ok");
  EXPECT_TRUE(fs::exists(tmp.path() / "out" / "regression.md"));
  const std::string bad = run_command(
      {"--results", (tmp.path() / "nope.json").string(), "--out", out, "--study-data", study});
  EXPECT_EQ(bad.rfind("bad input: results file", 0), 0u) << bad;
  EXPECT_EQ(run_command({"--out", out}).rfind("parse error", 0), 0u);
}

// Requirement: `report --companion PATH` links another report, written first under --out, by
// its own title; a path that leaves the directory, could break the Markdown link, is missing
// or is not a report is refused in one line before the directory is touched.
TEST(ReportCommand, CompanionReportIsLinkedByItsTitle) {
  TempDir tmp;
  const std::string study = testing::study_dir().string();
  const fs::path out = tmp.path() / "out";
  fs::create_directories(out / "other");
  write_text(out / ".contact-suite", "");  // a directory contact-suite made
  write_text(out / "other" / "report.md", "# contact-suite report: ours and X beside Y\n\nz\n");
  write_text(out / "other" / "notes.md", "no title\n");
  EXPECT_EQ(run_command({"--results", sample_path().string(), "--out", out.string(), "--study-data",
                         study, "--no-figures", "--companion", "other/report.md"}),
            "ok");
  // Written by a build that did not name itself: the link says whose rules it follows.
  const std::string link = "\nAlso: [ours and X beside Y](other/report.md).";
  EXPECT_NE(read_text(out / "report.md")
                .find(link + " It was written by an earlier build, which did not name itself, "
                             "not by this report's build"),
            std::string::npos)
      << read_text(out / "report.md");
  // This report names its build at its end; a companion written by the same build is linked
  // without a note, one written by another build names it.
  const std::string version = suites::contact_suite_version();
  const std::string written = "*Written by contact-suite " + version + ".*";
  EXPECT_NE(read_text(out / "report.md").find("\n" + written + "\n"), std::string::npos);
  for (const auto& [writer, note] :
       {std::pair{version, std::string(".\n")},
        std::pair{std::string("0.0.9+abc1234"),
                  std::string(". It was written by contact-suite 0.0.9+abc1234, not by")}}) {
    write_text(out / "other" / "report.md",
               "# contact-suite report: ours and X beside Y\n\nz\n\n*Written by contact-suite " +
                   writer + ".*\n");
    EXPECT_EQ(
        run_command({"--results", sample_path().string(), "--out", out.string(), "--study-data",
                     study, "--no-figures", "--companion", "other/report.md"}),
        "ok");
    EXPECT_NE(
        read_text(out / "report.md").find("\nAlso: [ours and X beside Y](other/report.md)" + note),
        std::string::npos)
        << read_text(out / "report.md");
  }
  // A file saved with CRLF line ends names its build all the same; a "Written by" line that is
  // not the last names none.
  write_text(out / "other" / "report.md",
             "# contact-suite report: ours and X beside Y\r\n\r\n*Written by contact-suite " +
                 version + ".*\r\n\r\n");
  EXPECT_EQ(reports::read_companion_report(out, "other/report.md").writer, version);
  write_text(out / "other" / "report.md",
             "# contact-suite report: ours and X beside Y\n\n" + written + "\n\nmore text\n");
  EXPECT_EQ(reports::read_companion_report(out, "other/report.md").writer, "");
  const std::string before = read_text(out / "report.md");
  for (const std::string bad : {"../report.md", "/etc/report.md", "other/missing.md",
                                "other/report.txt", "other/r(1).md", "other/notes.md"}) {
    const std::string msg =
        run_command({"--results", sample_path().string(), "--out", out.string(), "--study-data",
                     study, "--no-figures", "--companion", bad});
    EXPECT_EQ(msg.rfind("bad input: --companion '" + bad + "'", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  EXPECT_EQ(read_text(out / "report.md"), before);
}

TEST(ReportCommand, ExecutableExitsWith2OnBadInput) {
  const std::string exe = CONTACT_SUITE_EXE;
  TempDir tmp;
  // Registered when `contact-suite --help` lists it (apps/main.cpp calls add_report_command).
  const int help =
      std::system((exe + " --help >" + (tmp.path() / "help.txt").string() + " 2>&1").c_str());
  if (help != 0 || read_text(tmp.path() / "help.txt").find("\n  report ") == std::string::npos)
    GTEST_SKIP() << "the report subcommand is not registered in apps/main.cpp yet";
  UserDir user(tmp.path());
  write_text(tmp.path() / "bad.json", truncated_sample());
  const std::string command = exe + " report --results " + (tmp.path() / "bad.json").string() +
                              " --out " + user.path.string() + " 2>" +
                              (tmp.path() / "stderr.txt").string();
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = read_text(tmp.path() / "stderr.txt");
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("is not valid JSON"), std::string::npos) << err;
  user.expect_untouched();
}

}  // namespace
}  // namespace cs::reports

namespace cs::reports {
namespace {

// Requirement: the run appendix of a combined set names each file once (the first row is the
// first file, not the whole list), gives each file's build, and counts the analyses behind the
// cases (an extrapolated twin shares its case's solve).
TEST(RunPage, CombinedFilesOneRowEachWithTheirBuild) {
  const auto document = [](const std::string& source, const std::string& build,
                           schema::ProblemId problem) {
    schema::ResultsDocument d;
    d.source = source;
    d.run.environment["contact_suite_version"] = build;
    for (const auto recovery : {schema::Recovery::spr, schema::Recovery::extrapolated}) {
      schema::CaseResult c;
      c.spec.problem = problem;
      c.spec.recovery = recovery;
      c.status = schema::CaseStatus::converged;
      d.cases.push_back(c);
    }
    return d;
  };
  std::vector<schema::ResultsDocument> docs;
  docs.push_back(document("a/results.json", "0.1.0+aaa", schema::ProblemId::H_p));
  docs.push_back(document("b/results.json", "0.1.0+bbb", schema::ProblemId::H_a));
  const std::string md = run_page(schema::combine_results(std::move(docs)));
  EXPECT_NE(md.find("| `a/results.json` | 0.1.0+aaa |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `b/results.json` | 0.1.0+bbb |"), std::string::npos) << md;
  EXPECT_EQ(md.find("a/results.json, b/results.json"), std::string::npos) << md;
  EXPECT_NE(md.find("These results hold 4 cases (4 converged, 0 not converged, 0 failed or timed "
                    "out) from 2 analyses"),
            std::string::npos)
      << md;
  // The environment is free-form: a version that is not a text reads as not recorded.
  schema::ResultsDocument odd = document("c/results.json", "", schema::ProblemId::H_p);
  odd.run.environment["contact_suite_version"] = 5;
  EXPECT_NE(run_page(odd).find("| `c/results.json` | — |"), std::string::npos) << run_page(odd);
}

}  // namespace
}  // namespace cs::reports
