// What the report does with results that lack some of its inputs: an appendix whose inputs are
// not in the results is left out and report.md names it with the reason, and the results of an
// imported solver without a fine mesh are reported without a fine-mesh grade or error, under
// that solver's name.

#include <string>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/report_writer.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::study;

fs::path battery_path() {
  return testing::source_dir() / "tests" / "reports" / "data" / "battery_results.json";
}

/// The lines of `text` from the one that starts with `marker` on, up to the first empty line
/// after at least one list item.
std::vector<std::string> list_after(const std::string& text, const std::string& marker) {
  std::vector<std::string> out;
  std::istringstream in(text.substr(std::min(text.find(marker), text.size())));
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("- "))
      out.push_back(line);
    else if (!out.empty())
      break;
  }
  return out;
}

// Requirement: every appendix left out for want of its inputs is named in report.md with one
// line saying why (the battery fixture has no sweep, extent, friction, conformal problem, second
// solver, benchmark or mesh export), and no appendix with content is among them.
TEST(MissingInputs, EveryAppendixLeftOutIsNamedWithItsReason) {
  const schema::ResultsDocument doc = schema::read_results_file(battery_path());
  const ResultsIndex index(doc);
  const ReportContent content;
  const auto appendices = appendix_pages(index, study(), content);
  const std::string md = report_markdown(index, content, {}, appendices);
  int omitted = 0;
  for (const auto& page : appendices)
    omitted += page.markdown.empty() ? 1 : 0;
  ASSERT_GT(omitted, 5);
  const auto reasons = list_after(md, "Not in this report");
  EXPECT_EQ(static_cast<int>(reasons.size()), omitted) << md;
  EXPECT_NE(md.find("- *Parameter sweeps*: no parameter was swept"), std::string::npos);
  EXPECT_NE(md.find("- *Benchmarks*: no benchmark file was given"), std::string::npos);
  EXPECT_NE(md.find("- *Other codes beside ours*: these results hold one solver only"),
            std::string::npos);
  EXPECT_EQ(md.find("- *Interface checks*:"), std::string::npos);  // it has content
}

/// The battery fixture's H_p cases and rows as an imported solver's ("getfem") that ran the
/// C and M meshes only.
nlohmann::json imported_without_fine_mesh() {
  nlohmann::json doc = nlohmann::json::parse(read_text(battery_path()));
  nlohmann::json cases = nlohmann::json::array(), rows = nlohmann::json::array();
  for (auto c : doc["cases"]) {
    if (c["problem"] != "H_p" || c["mesh"] == "F")
      continue;
    c["solver"] = "getfem";
    c["id"] = c["id"].get<std::string>() + "/@getfem";
    cases.push_back(c);
  }
  for (auto r : doc["rows"]) {
    if (r["problem"] != "H_p")
      continue;
    std::string id = r["id"];  // ".../<quantity>" -> ".../@getfem/<quantity>"
    id.insert(id.rfind('/'), "/@getfem");
    r["id"] = id;
    r["solver"] = "getfem";
    r["values"]["F"] = nullptr;
    r["error_percent"]["F"] = nullptr;
    r["graded_mesh"] = "M";
    rows.push_back(r);
  }
  doc["cases"] = cases;
  doc["rows"] = rows;
  nlohmann::json problems = nlohmann::json::array();
  for (const auto& p : doc["problems"]) {
    if (p["id"] == "H_p")
      problems.push_back(p);
  }
  doc["problems"] = problems;
  return doc;
}

// Requirement: the report of an imported solver's results names that solver (not ours), and
// where no fine mesh was given it shows no fine-mesh verdict, grade or error: the verdict page
// and the problem page say in one line that nothing is graded, and name the meshes given.
TEST(MissingInputs, ImportedSolverWithoutFineMeshShowsNoFineError) {
  testing::TempDir tmp;
  const testing::Loaded loaded(imported_without_fine_mesh());
  ReportOptions options;
  options.out_dir = tmp.path() / "report";
  options.figures = false;
  write_report(loaded.file, options);
  const std::string md = read_text(options.out_dir / "report.md");
  const std::string page = read_text(options.out_dir / "problem-H_p.md");
  EXPECT_EQ(md.rfind("# contact-suite report: getfem beside the study's ANSYS results\n", 0), 0u)
      << md.substr(0, 200);
  EXPECT_NE(md.find("No verdict: these results hold no row with the study's settings and a "
                    "fine-mesh (F) value"),
            std::string::npos);
  EXPECT_NE(md.find("Solver: getfem."), std::string::npos);
  EXPECT_EQ(md.find("**Other codes.**"), std::string::npos);  // one code: no cross-code appendix
  EXPECT_EQ(md.find("F error"), std::string::npos);
  EXPECT_EQ(md.find("on the fine mesh F over"), std::string::npos);
  EXPECT_NE(page.find("(C, M only), so none is graded here"), std::string::npos) << page;
  EXPECT_EQ(page.find("| F |"), std::string::npos);
}

}  // namespace
}  // namespace cs::reports
