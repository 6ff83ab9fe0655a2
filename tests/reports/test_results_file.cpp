// Loading a results file: the fields the reports read, and compatibility with the writer of
// suites/ (a document made by cs::suites::make_results_document loads here).

#include <cmath>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/report_error.hpp"
#include "reports/results_file.hpp"
#include "suites/results_json.hpp"

namespace cs::reports {
namespace {

TEST(ResultsFile, LoadsTheHandMadeSample) {
  const ResultsFile r = load_results_file(testing::sample_path());
  ASSERT_EQ(r.cases.size(), 59u);
  ASSERT_EQ(r.rows.size(), 32u);
  EXPECT_EQ(r.run.jobs, 2);
  EXPECT_EQ(r.run.environment["solver"]["factorization"], "CHOLMOD supernodal");
  const CaseRecord* punch = nullptr;
  for (const auto& c : r.cases) {
    if (c.id == "F_p/F/Q4/MPC/ss")
      punch = &c;
  }
  ASSERT_NE(punch, nullptr);
  const auto* q = punch->quantity("sigma_c_star");
  ASSERT_NE(q, nullptr);
  EXPECT_TRUE(q->singular);
  EXPECT_FALSE(q->exact.has_value());
  EXPECT_EQ(r.rows.back().variant(), "extrapolated");
  EXPECT_EQ(r.rows.back().recovery, "extrapolated");
  EXPECT_EQ(r.rows.back().case_key(), "H_p/Q4/LMP/ss/extrapolated");
  EXPECT_EQ(r.rows[r.rows.size() - 3].variant(), "fkn=10");
  EXPECT_EQ(r.rows[0].recovery, "spr");
  EXPECT_EQ(r.rows[0].variant(), "");
  EXPECT_EQ(case_key_of("H_p/F/Q4/AL/ss/rigid"), "H_p/Q4/AL/ss/rigid");
}

TEST(ResultsFile, NullValuesOfAFailedCaseAreEmpty) {
  const ResultsFile r = load_results_file(testing::sample_path());
  for (const auto& c : r.cases) {
    if (c.id != "H_p/F/Q8/PM/ss")
      continue;
    EXPECT_EQ(c.status, "failed");
    EXPECT_FALSE(c.quantity("sigma_c")->value.has_value());
    return;
  }
  FAIL() << "no failed case in the sample";
}

TEST(ResultsFile, ReadsWhatTheSuitesWrite) {
  suites::CaseResult c;
  c.spec.problem = suites::ProblemId::S_1_3;
  c.spec.mesh = suites::MeshLevel::M;
  c.spec.algorithm = suites::Algorithm::MPC;
  c.spec.contact = suites::ContactKind::mortar;
  c.spec.target = suites::TargetKind::Rigid;
  c.status = suites::CaseStatus::not_converged;
  c.reason = "cap";
  c.element_size_h = 0.02;
  suites::QuantityResult q;
  q.name = "sigma_c";
  q.value = 11.0;
  q.exact = 11.2424;
  q.error_percent = suites::error_percent(q.value, q.exact);
  q.grade = suites::grade_from_error(q.error_percent);
  q.study_exact = 10.9571;
  c.quantities.push_back(q);
  c.profile.x_over_a = {0.0, 1.0};
  c.profile.sigma_z_over_p = {1.0, NAN};
  suites::RunInfo run;
  run.environment = {{"compiler", "GCC"}};
  const auto doc = suites::make_results_document(run, {c});
  const ResultsFile r = parse_results_document(nlohmann::json::parse(doc.dump()), "suites");
  ASSERT_EQ(r.cases.size(), 1u);
  EXPECT_EQ(r.cases[0].id, "S_1_3/M/Q4/MPC/mortar/rigid");
  EXPECT_EQ(r.cases[0].target, "rigid");
  EXPECT_EQ(r.cases[0].status, "not_converged");
  EXPECT_EQ(*r.cases[0].quantities[0].study_exact, 10.9571);
  EXPECT_EQ(r.cases[0].quantities[0].grade, "g");
  EXPECT_TRUE(std::isnan(r.cases[0].profile.sigma_z_over_p[1]));
  ASSERT_EQ(r.rows.size(), 1u);
  EXPECT_EQ(r.rows[0].variant(), "rigid");
  EXPECT_EQ(*r.rows[0].graded_mesh, "M");
  EXPECT_FALSE(r.rows[0].converging.has_value());
}

TEST(ResultsFile, MalformedRecordsAreNamed) {
  auto doc = testing::sample_json();
  doc["rows"][2]["converging"] = "yes";
  EXPECT_THROW(
      {
        try {
          parse_results_document(doc, "r.json");
        } catch (const ReportError& e) {
          EXPECT_STREQ(e.what(),
                       "r.json: row #2 (Pprime_p/Q4/AL/ss/sigma_z_max): 'converging' is not true, "
                       "false or null");
          throw;
        }
      },
      ReportError);
  doc = testing::sample_json();
  doc["cases"][0]["quantities"]["sigma_z_max"]["value"] = "1.0";
  EXPECT_THROW(parse_results_document(doc, "r.json"), ReportError);
  doc = testing::sample_json();
  doc["cases"][12]["profile"]["x_over_a"] = {0.0};  // an H_p case: 13 points
  EXPECT_THROW(parse_results_document(doc, "r.json"), ReportError);
  doc = testing::sample_json();
  doc.erase("run");
  EXPECT_THROW(parse_results_document(doc, "r.json"), ReportError);
}

}  // namespace
}  // namespace cs::reports
