// The CI gate fails on a drifted value, a worsened grade, a case that stopped converging and a
// row that stopped converging; passes on identical results; refuses files of different cases.

#include <cmath>

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "schema/baseline_file.hpp"
#include "schema/schema_error.hpp"
#include "suites/gate.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

CaseResult hertz_case(MeshLevel mesh, double value) {
  CaseResult r;
  r.spec.problem = ProblemId::H_p;
  r.spec.mesh = mesh;
  r.spec.algorithm = Algorithm::AL;
  r.status = CaseStatus::converged;
  QuantityResult q;
  q.quantity = Quantity::sigma_c;
  q.exact = 4.0 / M_PI;
  q.value = value;
  q.error_percent = grading::error_percent(value, q.exact);
  q.grade = grading::grade_of_error(q.error_percent);
  r.quantities.push_back(q);
  return r;
}

/// C, M, F converging towards 4/pi: row graded e, converging.
std::vector<CaseResult> good_results() {
  return {hertz_case(MeshLevel::C, 1.2628), hertz_case(MeshLevel::M, 1.2704),
          hertz_case(MeshLevel::F, 1.2737)};
}

Baseline good_baseline() {
  // Round trip through JSON, as the gate reads the committed file.
  return schema::baseline_from_json(schema::to_json(make_baseline(good_results(), {})), "B");
}

bool has_failure(const GateReport& r, const std::string& id, const std::string& check) {
  for (const auto& f : r.failures) {
    if (f.id == id && f.check == check)
      return true;
  }
  return false;
}

TEST(Gate, IdenticalResultsPass) {
  const auto report = run_gate(good_baseline(), good_results());
  EXPECT_TRUE(report.passed()) << format_gate_failures(report);
  EXPECT_EQ(report.cases_checked, 3);
  EXPECT_EQ(report.rows_checked, 1);
}

TEST(Gate, DriftBeyondToleranceFailsWithinPasses) {
  auto results = good_results();
  results[1].quantities[0].value *= 1.0 + 5e-7;  // within 1e-6
  EXPECT_TRUE(run_gate(good_baseline(), results).passed());
  results[1].quantities[0].value *= 1.0 + 5e-6;  // beyond
  const auto report = run_gate(good_baseline(), results);
  EXPECT_TRUE(has_failure(report, "H_p/M/Q4/AL/ss sigma_c", "value drift"));
  EXPECT_EQ(report.failures.size(), 1u);
}

TEST(Gate, PerQuantityToleranceFromTheBaselineIsUsed) {
  Baseline loose = good_baseline();
  loose.tolerances.per_quantity[Quantity::sigma_c] = 1e-2;
  auto results = good_results();
  results[1].quantities[0].value *= 1.001;
  EXPECT_TRUE(run_gate(loose, results).passed());
}

TEST(Gate, WorsenedGradeAndLostConvergenceFail) {
  Baseline loose = good_baseline();
  loose.tolerances.per_quantity[Quantity::sigma_c] = 1.0;  // isolate the analytic-reference checks
  auto results = good_results();
  const double exact = 4.0 / M_PI;
  results[2] = hertz_case(MeshLevel::F, exact * 1.07);  // 7 %: grade s, and not converging
  const auto report = run_gate(loose, results);
  EXPECT_TRUE(has_failure(report, "H_p/Q4/AL/ss/sigma_c", "grade")) << format_gate_failures(report);
  EXPECT_TRUE(has_failure(report, "H_p/Q4/AL/ss/sigma_c", "converging"));
}

// Requirement: a grade that changes while its value moves by round-off (the F error from
// 0.99999995 % to 1.00000005 %, e to g, a drift of 1e-9) is no regression; the same grade drop
// with a drift beyond round-off fails even where the quantity's tolerance is loose.
TEST(Gate, AGradeOnABandsEdgeMovedByRoundOffPasses) {
  const double exact = 4.0 / M_PI;
  auto edge = good_results();
  edge[2] = hertz_case(MeshLevel::F, exact * (1.0 + 0.99999995e-2));
  const Baseline baseline =
      schema::baseline_from_json(schema::to_json(make_baseline(edge, {})), "B");
  ASSERT_EQ(baseline.rows.at(0).grade, Grade::e);
  auto moved = edge;
  moved[2] = hertz_case(MeshLevel::F, exact * (1.0 + 1.00000005e-2));
  ASSERT_EQ(moved[2].quantities[0].grade, Grade::g);
  const auto report = run_gate(baseline, moved);
  EXPECT_TRUE(report.passed()) << format_gate_failures(report);

  Baseline loose = baseline;
  loose.tolerances.per_quantity[Quantity::sigma_c] = 1e-2;
  moved[2] = hertz_case(MeshLevel::F, exact * 1.012);  // g by 0.2 points: no round-off
  EXPECT_TRUE(has_failure(run_gate(loose, moved), "H_p/Q4/AL/ss/sigma_c", "grade"));
}

TEST(Gate, CaseThatStoppedConvergingFails) {
  auto results = good_results();
  results[0].status = CaseStatus::not_converged;
  results[0].reason = "iteration limit";
  const auto report = run_gate(good_baseline(), results);
  EXPECT_TRUE(has_failure(report, "H_p/C/Q4/AL/ss", "status"));
}

TEST(Gate, LostDivergenceFails) {
  auto punch = [](MeshLevel m, double v) {
    CaseResult r = hertz_case(m, v);
    r.spec.problem = ProblemId::F_p;
    r.quantities[0].quantity = Quantity::sigma_c_star;
    r.quantities[0].exact = INFINITY;
    r.quantities[0].error_percent = 0.0;
    return r;
  };
  const std::vector<CaseResult> diverging{punch(MeshLevel::C, 2.0), punch(MeshLevel::M, 2.4),
                                          punch(MeshLevel::F, 3.0)};
  Baseline b =
      make_baseline(diverging, {schema::kDefaultGateTolerance, {{Quantity::sigma_c_star, 1.0}}});
  auto now = diverging;
  now[2].quantities[0].value = 2.5;  // increments shrink: no longer diverging
  EXPECT_TRUE(has_failure(run_gate(b, now), "F_p/Q4/AL/ss/sigma_c_star", "diverging"));
}

TEST(Gate, DifferentCasesAreBadInputListingThem) {
  auto results = good_results();
  results.pop_back();
  try {
    run_gate(good_baseline(), results);
    FAIL() << "no exception";
  } catch (const SuiteInputError& e) {
    EXPECT_NE(std::string(e.what()).find("only in the baseline: H_p/F/Q4/AL/ss"), std::string::npos)
        << e.what();
  }
}

TEST(Gate, BaselineSchemaIsChecked) {
  auto doc = schema::to_json(make_baseline(good_results(), {}));
  doc["schema_version"] = 99;
  EXPECT_THROW(schema::baseline_from_json(doc, "B"), schema::SchemaError);
  EXPECT_THROW(schema::baseline_from_json(nlohmann::json::parse(R"({"schema":"x"})"), "B"),
               schema::SchemaError);
  doc = schema::to_json(make_baseline(good_results(), {}));
  doc.erase("rows");
  EXPECT_THROW(schema::baseline_from_json(doc, "B"), schema::SchemaError);
}

// Requirement: --update keeps the tolerances of a baseline of an older schema version (whose
// case records it can no longer read), and still refuses a file that is not a baseline.
TEST(Gate, TolerancesAreReadFromAnOlderBaseline) {
  auto doc = schema::to_json(make_baseline(good_results(), {1e-5, {{Quantity::sigma_c, 1e-3}}}));
  doc["schema_version"] = 1;
  for (auto& c : doc["cases"])
    c.erase("recovery");  // a version-1 case record
  EXPECT_THROW(schema::baseline_from_json(doc, "B"), schema::SchemaError);
  const auto tolerances = schema::tolerances_from_json(doc, "B");
  EXPECT_EQ(tolerances.default_tolerance, 1e-5);
  EXPECT_EQ(tolerances.of(Quantity::sigma_c), 1e-3);
  EXPECT_THROW(schema::tolerances_from_json(nlohmann::json::parse(R"({"schema":"x"})"), "B"),
               schema::SchemaError);
}

}  // namespace
}  // namespace cs::suites
