// The cross-code section of the report (reports/facts/solvers, reports/tables/
// cross_code_section): built from small in-memory results documents whose rows are made by the
// suite's own grading (suites::make_row_verdicts), and once from a real run of CalculiX and our
// solver on the coarse H_p mesh.

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "report_test_support.hpp"
#include "reports/facts/solvers.hpp"
#include "reports/report_writer.hpp"
#include "reports/tables/cross_code_section.hpp"
#include "suites/executor_factory.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/row_verdict.hpp"
#include "suites/runner.hpp"

namespace cs::reports {
namespace {

using schema::CaseResult;
using schema::CaseStatus;
using schema::Element;
using schema::MeshLevel;
using schema::ProblemId;
using schema::Quantity;
using schema::SolverKind;
using testing::study;

const double kHertzExact = 4.0 / std::numbers::pi;  // -sigma_z(0,0)/p, plane strain

/// A document made the way `run` makes it: problem records and rows from the cases.
schema::ResultsDocument document(std::vector<CaseResult> cases) {
  schema::ResultsDocument doc;
  doc.problems = suites::problem_records(cases);
  doc.rows = suites::make_row_verdicts(cases);
  doc.cases = std::move(cases);
  return doc;
}

/// CalculiX, a registered code: its cases carry its option (here linear-ss, its LINEAR penalty).
constexpr SolverKind kCalculix = SolverKind::external;

/// An H_p case (Q4, PM ss) of `solver` with sigma_c at `error` percent of the exact value.
CaseResult hertz_case(SolverKind solver, MeshLevel mesh, double error, double wall = 1.0,
                      double peak = 10.0, CaseStatus status = CaseStatus::converged) {
  CaseResult c;
  c.spec.problem = ProblemId::H_p;
  c.spec.mesh = mesh;
  c.spec.element = Element::Q4;
  c.spec.algorithm = schema::Algorithm::PM;
  c.spec.contact = schema::ContactKind::ss;
  c.spec.solver = solver;
  if (solver == kCalculix) {
    c.spec.solver_name = "calculix";
    c.spec.solver_option = "linear-ss";
  }
  c.status = status;
  c.wall_seconds = wall;
  c.peak_rss_mb = peak;
  c.element_size_h = 0.25 / std::ldexp(1.0, static_cast<int>(mesh));
  if (status == CaseStatus::timeout || status == CaseStatus::failed) {
    c.reason = "ccx timed out";
    return c;
  }
  schema::QuantityResult q;
  q.quantity = Quantity::sigma_c;
  q.exact = kHertzExact;
  q.value = kHertzExact * (1 + error / 100);
  q.error_percent = error;
  q.grade = grading::grade_of_error(error);
  c.quantities.push_back(q);
  // A pressure profile on a few nodes: the exact one scaled by the error.
  for (double x : {0.0, 0.5, 0.9}) {
    c.profile.x_over_a.push_back(x);
    c.profile.sigma_z_over_p.push_back(kHertzExact * std::sqrt(1 - x * x) * (1 + error / 100));
    c.profile.pressure_over_p.push_back(kHertzExact * std::sqrt(1 - x * x) * (1 + error / 100));
  }
  for (double x : {0.0, 0.5, 1.0, 1.5}) {
    c.exact_profile.x_over_a.push_back(x);
    c.exact_profile.sigma_z_over_p.push_back(x < 1 ? kHertzExact * std::sqrt(1 - x * x) : 0.0);
  }
  return c;
}

/// Ours converging to e (errors 4, 2, 0.5 %); CalculiX to g (8, 4, 2 %), or timing out on F.
std::vector<CaseResult> hertz_pair(bool calculix_times_out = false) {
  std::vector<CaseResult> cases;
  const double ours[] = {4.0, 2.0, 0.5}, theirs[] = {8.0, 4.0, 2.0};
  for (const auto m : kMeshes) {
    const int i = static_cast<int>(m);
    cases.push_back(hertz_case(SolverKind::builtin, m, ours[i], 1.0 * (1 << i), 10.0 * (i + 1)));
    const bool timeout = calculix_times_out && m == MeshLevel::F;
    cases.push_back(hertz_case(kCalculix, m, theirs[i], 10.0 * (1 << i), 30.0 * (i + 1),
                               timeout ? CaseStatus::timeout : CaseStatus::converged));
  }
  return cases;
}

// Requirement: the solvers of a document are found, ours first; a document of one solver has
// no cross-code section.
TEST(CrossCodeRows, SolversOursFirstAndNoSectionForOneSolver) {
  const auto doc = document(hertz_pair());
  const ResultsIndex index(doc);
  EXPECT_EQ(solvers_in(index), (std::vector<std::string>{"builtin", "calculix:linear-ss"}));
  EXPECT_TRUE(is_cross_code(index));

  std::vector<CaseResult> ours_only;
  for (const auto& c : doc.cases) {
    if (c.spec.solver == SolverKind::builtin)
      ours_only.push_back(c);
  }
  const auto single = document(ours_only);
  const ResultsIndex single_index(single);
  EXPECT_FALSE(is_cross_code(single_index));
  EXPECT_EQ(cross_code_section(single_index, study(), {}, {}), "");
}

// Requirement: a solver's row is its own (CalculiX's values for CalculiX, ours for ours), not
// the other's.
TEST(CrossCodeRows, EachSolverGetsItsOwnRow) {
  const auto doc = document(hertz_pair());
  const ResultsIndex index(doc);
  const Option pm_ss{schema::Algorithm::PM, schema::ContactKind::ss};
  const auto* ours =
      solver_row(index, "builtin", ProblemId::H_p, Quantity::sigma_c, Element::Q4, pm_ss);
  const auto* theirs = solver_row(index, "calculix:linear-ss", ProblemId::H_p, Quantity::sigma_c,
                                  Element::Q4, pm_ss);
  ASSERT_NE(ours, nullptr);
  ASSERT_NE(theirs, nullptr);
  EXPECT_NEAR(*ours->errors[2], 0.5, 1e-9);
  EXPECT_NEAR(*theirs->errors[2], 2.0, 1e-9);
  EXPECT_EQ(cross_code_options(index, ProblemId::H_p, Quantity::sigma_c, Element::Q4),
            std::vector<Option>{pm_ss});
}

// Requirement: Table 2′ shows each solver's fine-mesh grade (Eq. 46 on the F error: 0.5 % is e,
// 2 % is g) beside the study's own Table 2 cell for that option.
TEST(CrossCodeGradeTable, GradesSideBySideWithTheStudysCell) {
  const auto doc = document(hertz_pair());
  const ResultsIndex index(doc);
  const auto table = build_cross_code_grade_table(index, study(), Element::Q4);
  ASSERT_TRUE(table.has_value());
  ASSERT_EQ(table->n_rows(), 1U);
  const schema::StudyGrade* ansys = study().find_grade(
      ProblemId::H_p, "contact", Element::Q4, schema::Algorithm::PM, schema::ContactKind::ss);
  ASSERT_NE(ansys, nullptr);
  const auto cell = table->cell(table->rows()[0][0], "PM ss");
  ASSERT_TRUE(cell.has_value());
  EXPECT_EQ(*cell, fmt::format("e, c │ g, c │ ANSYS {}", ansys->cell()));
  EXPECT_FALSE(build_cross_code_grade_table(index, study(), Element::Q8).has_value());

  const auto tally = cross_code_grade_tally(index, study());
  EXPECT_EQ(tally.at("builtin").by_class.at("e, c"), 1);
  EXPECT_EQ(tally.at("calculix:linear-ss").by_class.at("g"), 1);
}

// Requirement: a case CalculiX did not finish on F shows as its status with the mesh, and the
// tally counts the row as without a grade.
TEST(CrossCodeGradeTable, TimeoutOnTheFineMeshIsShownAsSuch) {
  const auto doc = document(hertz_pair(true));
  const ResultsIndex index(doc);
  const auto table = build_cross_code_grade_table(index, study(), Element::Q4);
  ASSERT_TRUE(table.has_value());
  const auto cell = table->cell(table->rows()[0][0], "PM ss");
  ASSERT_TRUE(cell.has_value());
  EXPECT_NE(cell->find("│ g (M)*, timeout (F) │"), std::string::npos) << *cell;
  EXPECT_EQ(cross_code_grade_tally(index, study()).at("calculix:linear-ss").by_class.at("no grade"),
            1);
  const std::string outcome = cross_code_section(index, study(), {}, {});
  EXPECT_NE(outcome.find("**calculix:linear-ss**: 2 converged, 1 timeout in all."),
            std::string::npos)
      << outcome;
}

// Requirement: cost ratios are the sums of the recorded wall times and the largest peaks of
// the same cases: ours 1 + 2 + 4 s and 10..30 MB, CalculiX ten times the time and three times
// the memory; a pair where either did not converge is left out of the "both converged" line.
TEST(CrossCodeCost, RatiosOfTheSameCases) {
  const auto doc = document(hertz_pair(true));
  const ResultsIndex index(doc);
  const auto c = solver_cost(index);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->solvers, (std::vector<std::string>{"builtin", "calculix:linear-ss"}));
  EXPECT_EQ(c->total.cases, 3);
  EXPECT_DOUBLE_EQ(c->total.seconds[0], 7.0);
  EXPECT_DOUBLE_EQ(*c->total.time_ratio(1), 10.0);
  EXPECT_DOUBLE_EQ(*c->total.memory_ratio(1), 3.0);
  EXPECT_EQ(c->total.converged[1], 2);
  EXPECT_EQ(c->all_converged.cases, 2);
  EXPECT_DOUBLE_EQ(c->all_converged.seconds[0], 3.0);
  ASSERT_EQ(c->lines.size(), 3U);  // H_p C, M, F
  const std::string md = cost_table(*c).render();
  EXPECT_NE(md.find("| all cases | 3 | 3 | 7 | 30 | 2 | 70 | 90 | 10 | 3 |"), std::string::npos)
      << md;
}

// Requirement: the appendix gives each solver's value and error per mesh, 4 decimals, and
// the status of a case that has no value.
TEST(CrossCodeAppendix, ValuesPerMeshAndSolver) {
  const auto doc = document(hertz_pair(true));
  const ResultsIndex index(doc);
  const auto tables = build_cross_code_appendix(index, study());
  ASSERT_EQ(tables.size(), 1U);
  const auto& t = tables[0].second;
  ASSERT_EQ(t.n_rows(), 1U);
  const auto col = [&](const std::string& name) {
    return t.cell(t.rows()[0][0], name).value_or("no column " + name);
  };
  EXPECT_EQ(col("Exact"), fmt::format("{:.4f}", kHertzExact));
  EXPECT_EQ(col("C calculix:linear-ss").substr(0, 6), fmt::format("{:.4f}", kHertzExact * 1.08));
  EXPECT_NE(col("C calculix:linear-ss").find("+8.00 %"), std::string::npos);
  EXPECT_EQ(col("F calculix:linear-ss"), "timeout");
  EXPECT_EQ(col("F ours").substr(0, 6), fmt::format("{:.4f}", kHertzExact * 1.005));
}

// Requirement: an error is printed with its sign: an under-estimate of the peak reads "−52.3 %",
// never "+52.3 %".
TEST(CrossCodeAppendix, ErrorsAreSigned) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    cases.push_back(hertz_case(SolverKind::builtin, m, 1.0));
    cases.push_back(hertz_case(kCalculix, m, -52.26));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const auto tables = build_cross_code_appendix(index, study());
  ASSERT_EQ(tables.size(), 1U);
  const auto& t = tables[0].second;
  const std::string cell = t.cell(t.rows()[0][0], "F calculix:linear-ss").value_or("");
  EXPECT_NE(cell.find("(−52.3 %)"), std::string::npos) << cell;
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_EQ(md.find("+52.3"), std::string::npos);
  EXPECT_NE(md.find("−52.3 %"), std::string::npos);
}

// Requirement: the figure has one curve per solver with a fine-mesh pressure and the exact
// curve; a solver without one is named with its case's status.
TEST(CrossCodeFigure, OneCurvePerSolverAndTheExactOne) {
  const auto doc = document(hertz_pair());
  const ResultsIndex index(doc);
  const auto panels = cross_code_profile_panels(index);
  ASSERT_EQ(panels.size(), 1U);
  ASSERT_EQ(panels[0].curves.size(), 3U);
  EXPECT_EQ(panels[0].curves[0].title, "ours");
  EXPECT_EQ(panels[0].curves[1].title, "calculix:linear-ss");
  EXPECT_EQ(panels[0].curves[2].title, "exact");
  EXPECT_NEAR(panels[0].curves[1].xy[0].second, kHertzExact * 1.02, 1e-12);

  const auto with_timeout = document(hertz_pair(true));
  const ResultsIndex index2(with_timeout);
  const auto panels2 = cross_code_profile_panels(index2);
  ASSERT_EQ(panels2.size(), 1U);
  EXPECT_EQ(panels2[0].curves.size(), 2U);
  EXPECT_EQ(panels2[0].missing, std::vector<std::string>{"calculix:linear-ss (timeout)"});
}

// Requirement: the report of a document with two solvers has the cross-code section, with the
// option mapping handed in, and a document of one solver has none.
TEST(CrossCodeSection, InTheReportOnlyWithSeveralSolvers) {
  const auto doc = document(hertz_pair());
  const ResultsIndex index(doc);
  const std::vector<SolverOptionMapping> mapping{
      {"calculix:linear-ss", "PM", "PRESSURE-OVERCLOSURE=LINEAR", "same", "penalty"}};
  const std::string md = cross_code_section(index, study(), {}, mapping);
  EXPECT_NE(md.find("## Cross-code comparison: ours and calculix:linear-ss"), std::string::npos);
  EXPECT_NE(md.find("| PM | PRESSURE-OVERCLOSURE=LINEAR | same | penalty |"), std::string::npos);
  EXPECT_NE(md.find("time calculix:linear-ss/ours"), std::string::npos);
  const ReportContent content{.cross_code_md = md, .companions = {{"x/report.md", "T"}}};
  const auto appendices = appendix_pages(index, study(), content);
  const std::string report = report_markdown(index, study(), content, {}, appendices);
  EXPECT_NE(report.find("(appendix-cross-code.md)"), std::string::npos);
  EXPECT_EQ(
      report.rfind("# contact-suite report: ours and calculix:linear-ss beside the study's ANSYS "
                   "results\n",
                   0),
      0u);
  EXPECT_NE(report.find("\nAlso: [T](x/report.md).\n"), std::string::npos);
}

// Requirement (ccx-backed, small): the same H_p coarse-mesh case solved by ours and by CalculiX
// through the engine gives a section whose values are each solver's own, both within 10 % of
// the exact 4/pi (the coarse mesh's errors, docs/calculix.md: +5.6 % for ns Q4 at h = a/8), and
// whose cost ratio is the ratio of the recorded wall times.
TEST(CrossCodeSection, RealRunOfBothSolversOnTheCoarseMesh) {
  if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "ccx not on PATH (ci/install-deps.sh installs calculix-ccx)";
  std::vector<suites::CaseSpec> specs;
  for (const auto solver : {SolverKind::builtin, kCalculix}) {
    suites::CaseSpec s;
    s.problem = ProblemId::H_p;
    s.mesh = MeshLevel::C;
    s.element = Element::Q4;
    s.algorithm = schema::Algorithm::PM;
    s.contact = schema::ContactKind::ns;
    s.solver = solver;
    if (solver == kCalculix) {
      s.solver_name = "calculix";
      s.solver_option = "linear-ns";
    }
    specs.push_back(s);
  }
  suites::RunnerOptions options;
  options.jobs = 1;
  suites::ExecutorOptions exec;
  exec.external_time_limit_seconds = 300;
  auto results = suites::run_cases(specs, suites::executor_factory(exec), options);
  ASSERT_EQ(results.size(), 2U);
  for (const auto& r : results)
    ASSERT_EQ(r.status, CaseStatus::converged) << r.reason;
  const auto doc = document(results);
  const ResultsIndex index(doc);
  const auto tables = build_cross_code_appendix(index, study());
  ASSERT_EQ(tables.size(), 1U);  // H_p
  const auto* ours = results[0].quantity(Quantity::sigma_c);
  const auto* theirs = results[1].quantity(Quantity::sigma_c);
  ASSERT_NE(ours, nullptr);
  ASSERT_NE(theirs, nullptr);
  EXPECT_NEAR(ours->value, kHertzExact, 0.1 * kHertzExact);
  EXPECT_NEAR(theirs->value, kHertzExact, 0.1 * kHertzExact);
  EXPECT_NE(ours->value, theirs->value);  // two solvers, two answers
  bool found = false;
  for (const auto& row : tables[0].second.rows()) {
    if (row[0] != "sigma_c Q4 PM ns")
      continue;
    found = true;
    EXPECT_EQ(row[2].substr(0, 6), fmt::format("{:.4f}", ours->value));
    EXPECT_EQ(row[3].substr(0, 6), fmt::format("{:.4f}", theirs->value));
  }
  EXPECT_TRUE(found);
  const auto cost = solver_cost(index);
  ASSERT_TRUE(cost.has_value());
  EXPECT_NEAR(*cost->total.time_ratio(1), results[1].wall_seconds / results[0].wall_seconds, 1e-12);
}

}  // namespace
}  // namespace cs::reports
