// The regression report: a drifted value, a worsened grade, lost verdicts, and the cases
// only in one of the two files are all listed.

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/findings/regression_report.hpp"
#include "suites/gate.hpp"
#include "support/tolerance.hpp"

namespace cs::reports {
namespace {

using testing::sample_json;

struct Pair {
  schema::ResultsDocument old_file, new_file;
};

Pair drifted_pair() {
  auto old_doc = sample_json();
  auto new_doc = old_doc;
  // A drift that keeps the grade (e): +0.5 %.
  testing::set_value(new_doc, "H_p/F/Q4/AL/ss", "sigma_c", 1.2730 * 1.005);
  // A drift that worsens the grade e -> s and loses the converging flag of the row.
  testing::set_value(new_doc, "H_p/F/Q4/LMP/ss", "sigma_c", 1.35);
  for (auto& r : new_doc["rows"]) {
    if (r["id"] == "H_p/Q4/LMP/ss/sigma_c")
      r["converging"] = false;
  }
  // One case gone, one case new.
  auto& cases = new_doc["cases"];
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (cases[i]["id"] == "P_p/C/Q4/LMP/ss") {
      cases.erase(i);
      break;
    }
  }
  auto extra = cases[0];
  extra["id"] = "P_p/C/Q4/PLM/ss";
  extra["algorithm"] = "PLM";
  cases.push_back(extra);
  return {schema::results_from_json(old_doc, "old.json"),
          schema::results_from_json(new_doc, "new.json")};
}

TEST(RegressionReport, DetectsDriftAndWorseGrades) {
  const Pair p = drifted_pair();
  const Regression r = compare_results(p.old_file, p.new_file);
  const QuantityDrift* al = nullptr;
  const QuantityDrift* lmp = nullptr;
  int drifted = 0;
  for (const auto& q : r.quantities) {
    if (q.case_id == "H_p/F/Q4/AL/ss" && q.quantity == schema::Quantity::sigma_c)
      al = &q;
    if (q.case_id == "H_p/F/Q4/LMP/ss" && q.quantity == schema::Quantity::sigma_c)
      lmp = &q;
    if (q.relative && *q.relative != 0.0)
      ++drifted;
  }
  EXPECT_EQ(drifted, 2);
  ASSERT_NE(al, nullptr);
  ASSERT_TRUE(al->relative.has_value());
  EXPECT_TRUE(
      cs::testing::Near(*al->relative, 0.005, {1e-12, 0}));  // relative drift, exact arithmetic
  EXPECT_FALSE(al->grade_worse());
  ASSERT_NE(lmp, nullptr);
  EXPECT_EQ(lmp->old_grade, schema::Grade::e);
  EXPECT_EQ(lmp->new_grade, schema::Grade::s);
  EXPECT_TRUE(lmp->grade_worse());
  EXPECT_EQ(r.grades_worse, 1);
  EXPECT_EQ(r.grades_better, 0);
  ASSERT_EQ(r.row_changes.size(), 1u);
  EXPECT_EQ(r.row_changes[0].row_id, "H_p/Q4/LMP/ss/sigma_c");
  EXPECT_TRUE(r.row_changes[0].worse());
  EXPECT_EQ(r.only_in_old, std::vector<std::string>{"P_p/C/Q4/LMP/ss"});
  EXPECT_EQ(r.only_in_new, std::vector<std::string>{"P_p/C/Q4/PLM/ss"});
}

TEST(RegressionReport, MarkdownListsTheChanges) {
  const Pair p = drifted_pair();
  const std::string md = regression_markdown(compare_results(p.old_file, p.new_file));
  EXPECT_NE(md.find("| `H_p/F/Q4/LMP/ss` | sigma_c | **worse** e → s | 1.2790 | 1.3500 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `H_p/F/Q4/AL/ss` | sigma_c | 1.2730 | 1.2794 | +0.5 % | e |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("**worse** `H_p/Q4/LMP/ss/sigma_c` | e → s | c → no"), std::string::npos) << md;
  EXPECT_NE(md.find("## Cases only in the baseline\n\n- `P_p/C/Q4/LMP/ss`"), std::string::npos);
  EXPECT_NE(md.find("## Cases only in the current file\n\n- `P_p/C/Q4/PLM/ss`"), std::string::npos);
  EXPECT_NE(md.find("Case grades: 1 worse, 0 better"), std::string::npos);
}

// Requirement: a grade that flips while its value moves by round-off (an F error from
// 0.99999995 % to 1.00000005 %, e to g, a drift of 1e-9) is at a band's edge, neither worse nor
// better, as the accuracy gate judges it; the same flip with a real drift is worse.
TEST(RegressionReport, AGradeFlipByRoundOffIsAtABandsEdge) {
  auto old_doc = sample_json();
  const double exact = [&] {
    for (const auto& c : old_doc["cases"]) {
      if (c["id"] == "H_p/F/Q4/AL/ss")
        return c["quantities"]["sigma_c"]["exact"].get<double>();
    }
    return 0.0;
  }();
  ASSERT_GT(exact, 0.0);
  testing::set_value(old_doc, "H_p/F/Q4/AL/ss", "sigma_c", exact * (1 + 0.99999995e-2));
  auto edge_doc = old_doc, real_doc = old_doc;
  testing::set_value(edge_doc, "H_p/F/Q4/AL/ss", "sigma_c", exact * (1 + 1.00000005e-2));
  testing::set_value(real_doc, "H_p/F/Q4/AL/ss", "sigma_c", exact * 1.012);
  const auto old_file = schema::results_from_json(old_doc, "old.json");
  const Regression edge =
      compare_results(old_file, schema::results_from_json(edge_doc, "edge.json"));
  EXPECT_EQ(edge.grades_worse, 0);
  EXPECT_EQ(edge.grades_better, 0);
  EXPECT_EQ(edge.grades_at_edge, 1);
  ASSERT_EQ(edge.row_changes.size(), 1u);
  EXPECT_TRUE(edge.row_changes[0].grade_at_edge);
  EXPECT_FALSE(edge.row_changes[0].worse());
  const std::string md = regression_markdown(edge);
  EXPECT_NE(md.find("| at a band's edge e → g |"), std::string::npos) << md;
  EXPECT_NE(md.find("Case grades: 0 worse, 0 better, 1 at a band's edge"), std::string::npos) << md;
  const auto real_file = schema::results_from_json(real_doc, "real.json");
  const Regression real = compare_results(old_file, real_file);
  EXPECT_EQ(real.grades_worse, 1);
  EXPECT_EQ(real.grades_at_edge, 0);
  ASSERT_EQ(real.row_changes.size(), 1u);
  EXPECT_TRUE(real.row_changes[0].worse());
  // The accuracy gate, with its default tolerances, judges the same pairs alike.
  const suites::Baseline baseline = suites::make_baseline(old_file.cases, {});
  const auto edge_gate =
      suites::run_gate(baseline, schema::results_from_json(edge_doc, "edge.json").cases);
  EXPECT_TRUE(edge_gate.passed());
  const auto real_gate = suites::run_gate(baseline, real_file.cases);
  EXPECT_TRUE(std::ranges::any_of(real_gate.failures, [](const auto& f) {
    return f.check == "grade";
  })) << suites::format_gate_failures(real_gate);
}

TEST(RegressionReport, IdenticalFilesHaveNoChanges) {
  const auto doc = sample_json();
  const Regression r =
      compare_results(schema::results_from_json(doc, "a"), schema::results_from_json(doc, "b"));
  EXPECT_EQ(r.grades_worse + r.grades_better + r.status_changes, 0);
  EXPECT_TRUE(r.row_changes.empty());
  EXPECT_TRUE(r.only_in_new.empty() && r.only_in_old.empty());
  EXPECT_NE(regression_markdown(r).find("None: every common value is identical."),
            std::string::npos);
}

}  // namespace
}  // namespace cs::reports
