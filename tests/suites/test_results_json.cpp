// results.json round trip and row verdicts from a small hand-made set of cases.

#include <cmath>

#include <gtest/gtest.h>

#include "suites/results_json.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

CaseResult make_case(ProblemId p, MeshLevel m, double value, double exact) {
  CaseResult r;
  r.spec.problem = p;
  r.spec.mesh = m;
  r.spec.algorithm = Algorithm::AL;
  r.spec.contact = ContactKind::ss;
  r.status = CaseStatus::converged;
  QuantityResult q;
  q.name = is_singular(p) ? "sigma_c_star" : "sigma_c";
  q.value = value;
  q.exact = exact;
  q.error_percent = std::isfinite(exact) ? error_percent(value, exact) : 0.0;
  q.grade = std::isfinite(exact) ? grade_from_error(q.error_percent) : Grade::u;
  q.contact_pressure = value * 0.99;
  r.quantities.push_back(q);
  r.profile.x_over_a = {0.0, 0.5};
  r.profile.sigma_z_over_p = {value, 0.5 * value};
  r.profile.pressure_over_p = {value, NAN};
  return r;
}

TEST(ResultsJson, CasesRoundTripThroughTheDocument) {
  std::vector<CaseResult> cases{make_case(ProblemId::H_p, MeshLevel::C, 1.30, 4 / M_PI),
                                make_case(ProblemId::F_p, MeshLevel::C, 2.0, INFINITY)};
  cases[1].status = CaseStatus::not_converged;
  cases[1].reason = "iteration cap (1) reached";
  cases[1].spec.recovery = Recovery::extrapolated;
  const auto doc = make_results_document(RunInfo{}, cases);
  // JSON text has no NaN/inf: the non-finite profile value is null, the singular exact "inf".
  const std::string text = doc.dump();
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  EXPECT_EQ(text.find("Infinity"), std::string::npos);
  const auto back = cases_from_results_document(nlohmann::json::parse(text));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(case_id(back[0].spec), case_id(cases[0].spec));
  EXPECT_EQ(back[0].spec.recovery, Recovery::spr);
  EXPECT_EQ(back[1].spec.recovery, Recovery::extrapolated);
  EXPECT_EQ(back[0].quantities[0].value, 1.30);
  EXPECT_EQ(*back[0].quantities[0].contact_pressure, 1.30 * 0.99);
  EXPECT_TRUE(std::isinf(back[1].quantities[0].exact));
  EXPECT_EQ(back[1].status, CaseStatus::not_converged);
  EXPECT_EQ(back[1].reason, "iteration cap (1) reached");
  EXPECT_TRUE(std::isnan(back[0].profile.pressure_over_p[1]));
}

TEST(ResultsJson, RejectsOtherSchemasAndVersions) {
  EXPECT_THROW(cases_from_results_document(nlohmann::json::parse("[1,2]")), SuiteInputError);
  auto doc = make_results_document(RunInfo{}, {});
  doc["schema_version"] = kResultsSchemaVersion + 1;
  EXPECT_THROW(cases_from_results_document(doc), SuiteInputError);
  doc = make_results_document(RunInfo{}, {make_case(ProblemId::H_p, MeshLevel::C, 1.3, 1.27)});
  doc["cases"][0].erase("problem");
  EXPECT_THROW(cases_from_results_document(doc), SuiteInputError);
}

TEST(RowVerdicts, ConvergingRowGradedOnTheFineMesh) {
  const double exact = 4 / M_PI;
  const auto rows = make_row_verdicts({make_case(ProblemId::H_p, MeshLevel::C, 1.2628, exact),
                                       make_case(ProblemId::H_p, MeshLevel::M, 1.2704, exact),
                                       make_case(ProblemId::H_p, MeshLevel::F, 1.2737, exact)});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].id, "H_p/Q4/AL/ss/sigma_c");
  EXPECT_EQ(*rows[0].grade, Grade::e);
  EXPECT_EQ(*rows[0].graded_mesh, MeshLevel::F);
  EXPECT_TRUE(*rows[0].converging);
  EXPECT_FALSE(rows[0].diverging.has_value());
}

TEST(RowVerdicts, MissingMeshGivesNoConvergenceVerdict) {
  auto failed = make_case(ProblemId::H_p, MeshLevel::F, NAN, 4 / M_PI);
  failed.status = CaseStatus::failed;
  const auto rows =
      make_row_verdicts({make_case(ProblemId::H_p, MeshLevel::C, 1.40, 4 / M_PI), failed});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_FALSE(rows[0].converging.has_value());
  EXPECT_FALSE(rows[0].values[2].has_value());
  EXPECT_EQ(*rows[0].graded_mesh, MeshLevel::C);  // graded on the finest mesh present
  EXPECT_EQ(*rows[0].grade, Grade::s);            // 1.40 vs 1.2732: 9.96 %
}

TEST(RowVerdicts, SingularRowsAreCheckedForDivergenceNotGraded) {
  const auto rows = make_row_verdicts({make_case(ProblemId::F_p, MeshLevel::C, 2.0, INFINITY),
                                       make_case(ProblemId::F_p, MeshLevel::M, 2.5, INFINITY),
                                       make_case(ProblemId::F_p, MeshLevel::F, 3.2, INFINITY)});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_TRUE(*rows[0].diverging);
  EXPECT_FALSE(rows[0].grade.has_value());
  EXPECT_FALSE(rows[0].converging.has_value());
}

}  // namespace
}  // namespace cs::suites
