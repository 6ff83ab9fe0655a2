// The analyst's sections at the top of the report: the recommendation table, the study's four
// conclusions checked, Table 1′, and the problems beyond the study. Each is checked against the
// hand-made results file, whose errors are known (data/make_small_results.py).

#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "grading/divergence.hpp"
#include "report_test_support.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/findings/anomalies_section.hpp"
#include "reports/tables/divergence_table.hpp"
#include "reports/tables/interface_table.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/mesh_table.hpp"
#include "suites/problem_catalog.hpp"

namespace cs::reports {
namespace {

using testing::Loaded;
using testing::sample_json;
using testing::study;

// Requirement: Table 1′ prints our count beside the study's and the difference where they
// differ (the sample's meshes are small, so every count differs).
TEST(MeshTable, ShowsOursBesideTheStudysTable1) {
  const Loaded data(sample_json());
  const std::string md = mesh_table_section(data.index, study());
  EXPECT_EQ(md.rfind("## Meshes: Table 1′\n", 0), 0u);
  EXPECT_NE(md.find("| P<sub>p</sub> | 64 / 64 | 256 / 256 | 1024 / 1024 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("64 / 16222 (−99.6 %)"), std::string::npos) << md;
  ASSERT_TRUE(study().table1_elements(schema::ProblemId::S_1_7, schema::MeshLevel::F));
  EXPECT_EQ(*study().table1_elements(schema::ProblemId::S_1_7, schema::MeshLevel::F), 268944);
  EXPECT_EQ(*study().table1_elements(schema::ProblemId::H_a, schema::MeshLevel::M), 1024);
}

// Requirement: the axis weights the anomaly rests on are right: integral of N r dr over [0, h]
// for the quadratic edge is 0 (corner on the axis), h^2/3 (midside), h^2/6 (far corner),
// summing to h^2/2; for the linear edge h^2/6 and h^2/3. Checked at h = 2 against the closed
// forms, not against the quadrature itself.
TEST(Anomalies, AxisymmetricEdgeWeights) {
  const double h = 2.0;
  EXPECT_NEAR(quadratic_edge_axisymmetric_weight(0, h), 0.0, 1e-14);
  EXPECT_NEAR(quadratic_edge_axisymmetric_weight(2, h), h * h / 3.0, 1e-14);
  EXPECT_NEAR(quadratic_edge_axisymmetric_weight(1, h), h * h / 6.0, 1e-14);
  EXPECT_NEAR(linear_edge_axisymmetric_weight(0, h), h * h / 6.0, 1e-14);
  EXPECT_NEAR(linear_edge_axisymmetric_weight(1, h), h * h / 3.0, 1e-14);
}

// Requirement: the integrals behind the Q8 multiplier-basis anomaly are right, against closed
// forms at h = 2: int |N_c| r dr = h^2/16 on the axis edge; a Q8 corner function against a gap
// growing linearly from it gives -h^3/60 with the r weight and 0 without; the Bernstein
// functions (1-t)^2, t^2, 2t(1-t) integrate with r to h^2/12, h^2/4, h^2/6 (all > 0).
TEST(Anomalies, MultiplierBasisIntegrals) {
  const double h = 2.0;
  EXPECT_NEAR(quadratic_edge_axisymmetric_abs_weight(0, h), h * h / 16.0, 1e-14);
  EXPECT_NEAR(corner_weighted_linear_gap(true, h), -h * h * h / 60.0, 1e-14);
  EXPECT_NEAR(corner_weighted_linear_gap(false, h), 0.0, 1e-14);
  EXPECT_NEAR(bernstein_axisymmetric_weight(0, h), h * h / 12.0, 1e-14);
  EXPECT_NEAR(bernstein_axisymmetric_weight(1, h), h * h / 4.0, 1e-14);
  EXPECT_NEAR(bernstein_axisymmetric_weight(2, h), h * h / 6.0, 1e-14);
}

// Requirement: a fine-mesh e after a C or M error above 100 % is the luck of one mesh (through
// RowFacts); AL = PM is counted on the rows where both ran.
TEST(Anomalies, ExplainsCrossingsAndAlEqualsPm) {
  auto doc = sample_json();
  for (auto& r : doc["rows"]) {
    if (r["id"] == "H_p/Q4/MPC/ss/sigma_c") {
      r["error_percent"]["C"] = 270.0;  // C unresolved, F e: a crossing
      r["error_percent"]["F"] = 0.5;
      r["grade"] = "e";
    }
  }
  const Loaded data(doc);
  const std::vector<RowFacts> rows = row_facts(data.index);
  const AnomalyFacts a = anomaly_facts(data.index, rows);
  ASSERT_EQ(a.luck.size(), 1u);
  EXPECT_EQ(a.luck[0]->row->id, "H_p/Q4/MPC/ss/sigma_c");
  EXPECT_FALSE(a.luck[0]->study_c);
  // AL/PM pairs with an F value: H_p Q4 ss sigma_c and sigma_h, equal on every mesh (the Q8
  // pairs have no F case, so no graded row).
  EXPECT_EQ(a.al_pm.rows, 2);
  EXPECT_EQ(a.al_pm.coinciding, 2);
  EXPECT_EQ(a.al_pm.frictional_rows, 0);
  EXPECT_FALSE(anomalies_section(data.index).empty());
  // With friction the penetration argument does not hold: those rows are counted apart.
  for (auto& p : doc["problems"]) {
    if (p["id"] == "H_p")
      p["situation"] = "frictional";
  }
  const Loaded with_friction(doc);
  const AnomalyFacts f = anomaly_facts(with_friction.index, row_facts(with_friction.index));
  EXPECT_EQ(f.al_pm.rows, 0);
  EXPECT_EQ(f.al_pm.frictional_rows, 2);
  EXPECT_EQ(f.al_pm.frictional_coinciding, 2);
}

// Requirement (issue 12, item 3): the issue's three flat-punch sequences pass Eq. 47 but do not
// diverge by the strict verdict, each for its stated reason; a growth of sqrt(2) per halving
// (the square-root singularity) diverges.
TEST(StrictDivergence, TheIssuesSequencesDoNotDiverge) {
  struct Case {
    std::array<double, 3> v;
    const char* reason;
  };
  for (const Case& c :
       {Case{{-11.97, -12.02, -10.71}, "tensile, not monotone"},
        Case{{73.55, 73.30, 72.94}, "shrinking"}, Case{{3.156, 2.690, 3.164}, "not monotone"}}) {
    const auto d = grading::divergence_verdict(c.v[0], c.v[1], c.v[2]);
    EXPECT_TRUE(d.eq47) << c.reason;
    EXPECT_FALSE(d.diverges) << c.reason;
    EXPECT_EQ(strict_failure_reason({c.v[0], c.v[1], c.v[2]}, d), c.reason);
  }
  const double s = 1.5;
  const auto sqrt_growth = grading::divergence_verdict(s, s * std::sqrt(2.0), 2.0 * s);
  EXPECT_TRUE(sqrt_growth.diverges);
  EXPECT_NEAR(*sqrt_growth.exponent, 0.5, 1e-12);
  EXPECT_EQ(strict_failure_reason({s, s * std::sqrt(2.0), 2.0 * s}, sqrt_growth), "");
}

// Requirement: the divergence table's counts are those of the row facts (grading's Eq. 47 and
// strict verdict, once per complete singular row), and the table has a row per singular option
// set present.
TEST(DivergenceTable, CountsComeFromTheRowFacts) {
  const Loaded data(sample_json());
  const DivergenceTableFacts t = build_divergence_table(data.index, study());
  int eq47 = 0, strict = 0, complete = 0;
  for (const auto& d : divergence_facts(data.index)) {
    ++complete;
    eq47 += d.eq47 ? 1 : 0;
    strict += d.strict ? 1 : 0;
  }
  ASSERT_GT(complete, 0);
  EXPECT_EQ(t.eq47, eq47);
  EXPECT_EQ(t.eq47_fails, complete - eq47);
  EXPECT_EQ(t.strict, strict);
  EXPECT_EQ(t.strict_fails, complete - strict);
  EXPECT_EQ(static_cast<int>(t.table.n_rows()), complete + t.undecided);
}

// Requirement: a flat-punch row whose F case fails an interface check (AL ss pulling, tensile
// pressure 5 p) keeps its Eq. 47 verdict in the table but marked ✗, and is counted as no
// evidence, also where it passes Eq. 47.
TEST(DivergenceTable, ARowThatFailsAnInterfaceCheckIsMarked) {
  auto doc = sample_json();
  for (auto& c : doc["cases"]) {
    if (c["id"] == "F_p/F/Q4/AL/ss")
      c["interface"]["max_tensile_over_p"] = 5.0;
  }
  const Loaded data(doc);
  const DivergenceTableFacts t = build_divergence_table(data.index, study());
  EXPECT_EQ(t.not_credible, 1);
  EXPECT_EQ(t.not_credible_eq47, 1);
  const std::string md = t.table.render();
  EXPECT_NE(md.find("| AL ss |"), std::string::npos) << md;
  const auto row = md.substr(md.find("| AL ss |"));
  EXPECT_NE(row.substr(0, row.find('\n')).find("diverges ✗"), std::string::npos) << row;
}

}  // namespace
}  // namespace cs::reports

namespace cs::reports {
namespace {

// Requirement: the anomalies quote default-parameter cases only: the Q8 weighted-row force
// balance and the AL penetration of a case with an override (FKN = 0.001, whose contact is soft
// by choice) are not the default's, however large.
TEST(Anomalies, QuoteDefaultParameterCasesOnly) {
  schema::ResultsDocument doc;
  doc.problems.push_back(suites::problem_descriptor(schema::ProblemId::P_a).record);
  const auto add = [&](schema::Algorithm a, double fkn, double balance, double penetration) {
    schema::CaseResult c;
    c.spec = {.problem = schema::ProblemId::P_a,
              .mesh = schema::MeshLevel::F,
              .element = schema::Element::Q8,
              .algorithm = a,
              .contact = schema::ContactKind::mortar};
    if (fkn > 0.0)
      c.spec.overrides["fkn"] = fkn;
    c.status = schema::CaseStatus::converged;
    auto& checks = c.interface.emplace();
    checks.force_balance = balance;
    checks.max_penetration_over_h = penetration;
    doc.cases.push_back(c);
  };
  add(schema::Algorithm::AL, 0.0, 9.8e-7, 0.00112);
  add(schema::Algorithm::PM, 0.001, 0.0072, 4.04);
  add(schema::Algorithm::AL, 0.001, 0.0072, 4.04);
  const ResultsIndex index(doc);
  const std::vector<RowFacts> rows = row_facts(index);
  const AnomalyFacts a = anomaly_facts(index, rows);
  ASSERT_TRUE(a.weighted_force_balance.has_value());
  EXPECT_DOUBLE_EQ(a.weighted_force_balance->first, 9.8e-7);
  EXPECT_EQ(a.weighted_force_balance->second, "P_a/F/Q8/AL/mortar");
  ASSERT_TRUE(a.al_pm.largest_penetration.has_value());
  EXPECT_DOUBLE_EQ(*a.al_pm.largest_penetration, 0.00112);
}

// Requirement: the interface-checks table names the problems a check is not measured on, with
// their number of cases: force balance needs an applied normal load, which a fit has not.
TEST(InterfaceChecks, NameTheProblemsACheckIsNotMeasuredOn) {
  schema::ResultsDocument doc;
  for (const auto p : {schema::ProblemId::H_p, schema::ProblemId::IF_p})
    doc.problems.push_back(suites::problem_descriptor(p).record);
  const auto add = [&](schema::ProblemId p, schema::ContactKind contact) {
    schema::CaseResult c;
    c.spec.problem = p;
    c.spec.contact = contact;
    auto& checks = c.interface.emplace();
    checks.max_tensile_over_p = 0.0;
    checks.max_outside_over_p = 0.0;
    checks.max_penetration_over_h = 0.0;
    if (p == schema::ProblemId::H_p)
      checks.force_balance = 1e-5;
    doc.cases.push_back(c);
  };
  add(schema::ProblemId::H_p, schema::ContactKind::ss);
  add(schema::ProblemId::IF_p, schema::ContactKind::ss);
  add(schema::ProblemId::IF_p, schema::ContactKind::ns);
  const ResultsIndex index(doc);
  const std::string md = interface_section(index);
  EXPECT_NE(md.find("| force balance |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 1 | 0 | `H_p/C/Q4/LMP/ss`: 1e-05 | IF<sub>p</sub> (2 cases) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 3 | 0 | `H_p/C/Q4/LMP/ss`: 0 | — |"), std::string::npos) << md;
}

}  // namespace
}  // namespace cs::reports
