// Findings are generated from the data: each sentence names what the data says, and changes
// when the data changes.

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/findings/findings.hpp"
#include "reports/findings/summary_section.hpp"

namespace cs::reports {
namespace {

using testing::Loaded;
using testing::sample_json;
using testing::study;

std::string finding(const nlohmann::json& doc, FindingTopic topic,
                    const std::string& starts_with = "") {
  const Loaded data(doc);
  for (const auto& f : generate_findings(data.index, study())) {
    if (f.topic == topic && f.sentence.rfind(starts_with, 0) == 0)
      return f.sentence;
  }
  return {};
}

TEST(Findings, BestOptionPerProblemFollowsTheFineMeshError) {
  auto doc = sample_json();
  std::string s = finding(doc, FindingTopic::best_option, "H<sub>p</sub> (contact)");
  EXPECT_NE(s.find("best LMP mortar on Q4 — −0.01 % on F (e, c)"), std::string::npos) << s;
  EXPECT_NE(s.find("worst MPC ss on Q4 (+19.4 %)"), std::string::npos) << s;
  EXPECT_NE(s.find("The study's best ANSYS grade: e, c (AL, PM ss 4Q and AL, PM ss 8Q)"),
            std::string::npos)
      << s;
  // Worsen mortar's fine value: AL and PM (coincident) become the best, named together.
  testing::set_value(doc, "H_p/F/Q4/LMP/mortar", "sigma_c", 1.2790);
  s = finding(doc, FindingTopic::best_option, "H<sub>p</sub> (contact)");
  EXPECT_NE(s.find("best AL ss on Q4 and PM ss on Q4 — −0.02 % on F"), std::string::npos) << s;
}

TEST(Findings, LargestDifferenceFromTheStudy) {
  auto doc = sample_json();
  std::string s = finding(doc, FindingTopic::largest_difference);
  // F_p MPC ss: ours 2.8000 against the study's Table 13a IMC 3.6348: -23 %.
  EXPECT_NE(s.find("differ most on F<sub>p</sub> sigma_c_star Q4 MPC ss (F: ours 2.8000 vs ANSYS "
                   "3.6348, −23.0 %)"),
            std::string::npos)
      << s;
  testing::set_value(doc, "S_1_3/F/Q4/AL/ss", "sigma_c", 4.766);  // half the study's 9.5320
  s = finding(doc, FindingTopic::largest_difference);
  EXPECT_NE(s.find("differ most on S(1/3) sigma_c Q4 AL ss (F: ours 4.7660 vs ANSYS 9.5320, "
                   "−50.0 %)"),
            std::string::npos)
      << s;
}

TEST(Findings, FlatPunchOptionsThatFailToDiverge) {
  auto doc = sample_json();
  std::string s = finding(doc, FindingTopic::divergence);
  EXPECT_NE(s.find("by the study's Eq. 47 1 of 2 option set(s) diverge; not: F<sub>p</sub> Q4 "
                   "MPC ss"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("On the study's own values Eq. 47 fails for 0"), std::string::npos) << s;
  // With the strict verdicts recorded: the MPC row passes Eq. 47 but shrinks.
  for (auto& r : doc["rows"]) {
    if (r["id"] == "F_p/Q4/MPC/ss/sigma_c_star") {
      r["values"] = {{"C", 3.0}, {"M", 2.9}, {"F", 2.5}};
      r["diverging"] = true;
      r["divergence"] = {
          {"eq47", true}, {"monotone", false}, {"exponent", -0.13}, {"diverges", false}};
    }
    if (r["id"] == "F_p/Q4/AL/ss/sigma_c_star")
      r["divergence"] = {{"eq47", true}, {"monotone", true}, {"exponent", 0.5}, {"diverges", true}};
  }
  s = finding(doc, FindingTopic::divergence);
  EXPECT_NE(s.find("by the study's Eq. 47 2 of 2 option set(s) diverge."), std::string::npos) << s;
  EXPECT_NE(s.find("1 of 2 diverge; not: F<sub>p</sub> Q4 MPC ss (shrinking)"), std::string::npos)
      << s;
}

TEST(Findings, MortarOnTheMismatchedNodePatchTest) {
  auto doc = sample_json();
  std::string s = finding(doc, FindingTopic::mortar_mismatched);
  EXPECT_NE(s.find("P′<sub>p</sub> Q4 LMP mortar: e, c, +0.02 % on F (ANSYS: AL, PM ss g, LMP, "
                   "PLM u)"),
            std::string::npos)
      << s;
  testing::set_value(doc, "Pprime_p/F/Q4/LMP/mortar", "sigma_z_max", 1.03);
  s = finding(doc, FindingTopic::mortar_mismatched);
  EXPECT_NE(s.find("LMP mortar: g, c, +3.00 % on F"), std::string::npos) << s;
}

TEST(Findings, AgreementWithTheStudysGrades) {
  const std::string s = finding(sample_json(), FindingTopic::study_agreement);
  EXPECT_EQ(s,
            "Against the study's Table 2: of 17 cells graded by both, our grade is the same in "
            "12, better in 5 and worse in 0.");
}

TEST(Findings, AbsentProblemsAreSaidSo) {
  auto doc = sample_json();
  nlohmann::json kept_cases = nlohmann::json::array(), kept_rows = nlohmann::json::array();
  for (const auto& c : doc["cases"]) {
    if (c["problem"] == "H_p")
      kept_cases.push_back(c);
  }
  for (const auto& r : doc["rows"]) {
    if (r["problem"] == "H_p")
      kept_rows.push_back(r);
  }
  doc["cases"] = kept_cases;
  doc["rows"] = kept_rows;
  nlohmann::json kept_problems = nlohmann::json::array();
  for (const auto& p : doc["problems"]) {
    if (p["id"] == "H_p")
      kept_problems.push_back(p);
  }
  doc["problems"] = kept_problems;
  EXPECT_NE(finding(doc, FindingTopic::divergence).find("No flat-punch case"), std::string::npos);
  EXPECT_NE(finding(doc, FindingTopic::mortar_mismatched).find("No mismatched-node patch test"),
            std::string::npos);
}

// Requirement: a merged results file's summary says what its numbers are: the parts' machine
// time and the most workers of any one part (not "N parallel workers" for N files), and its
// command without the list of part files.
TEST(Summary, AMergedRunIsDescribedAsItsParts) {
  auto doc = sample_json();
  doc["run"]["merged_files"] = 130;
  doc["run"]["jobs"] = 1;
  doc["run"]["wall_seconds"] = 600.0;
  doc["run"]["command_line"] = "contact-suite merge out/x out/p1/results.json out/p2/results.json";
  const Loaded merged(doc);
  const std::string md = summary_section(merged.index, {});
  EXPECT_NE(md.find("Merged from 130 results files"), std::string::npos) << md;
  EXPECT_NE(md.find("10.0 min of wall time summed over them"), std::string::npos) << md;
  EXPECT_NE(md.find("each part with at most 1 parallel worker(s)"), std::string::npos) << md;
  EXPECT_NE(md.find("command `contact-suite merge out/x …`"), std::string::npos) << md;
  EXPECT_EQ(md.find("p1/results.json"), std::string::npos) << md;
  doc["run"].erase("merged_files");
  const Loaded single(doc);
  EXPECT_NE(summary_section(single.index, {}).find("wall time with 1 parallel worker(s)"),
            std::string::npos);
}

}  // namespace
}  // namespace cs::reports
