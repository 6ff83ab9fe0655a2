// The cross-code section of the report (reports/facts/solvers, reports/tables/
// cross_code_section): built from small in-memory results documents whose rows are made by the
// suite's own grading (suites::make_row_verdicts), and once from a real run of CalculiX and our
// solver on the coarse H_p mesh.

#include <cmath>
#include <cstdlib>
#include <map>
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
                      double peak = 10.0, CaseStatus status = CaseStatus::converged,
                      const std::string& option = "linear-ss",
                      schema::Recovery recovery = schema::Recovery::spr) {
  CaseResult c;
  c.spec.problem = ProblemId::H_p;
  c.spec.mesh = mesh;
  c.spec.element = Element::Q4;
  c.spec.algorithm = schema::Algorithm::PM;
  c.spec.contact = schema::ContactKind::ss;
  c.spec.solver = solver;
  if (solver == kCalculix) {
    c.spec.solver_name = "calculix";
    c.spec.solver_option = option;
    c.spec.contact = option.ends_with("ns") ? schema::ContactKind::ns : schema::ContactKind::ss;
  }
  c.spec.recovery = recovery;
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

/// The row of `code` and `option` in code_rows of H_p sigma_c Q4, or nullptr.
const CodeRow* find_row(const std::vector<CodeRow>& rows, const std::string& code,
                        const std::string& option) {
  for (const auto& r : rows) {
    if (r.code == code && r.option == option)
      return &r;
  }
  return nullptr;
}

// Requirement: the codes of a document are found, ours first, each CalculiX option under the
// one code with its own label; a document of one code has no cross-code section.
TEST(CrossCodeRows, CodesOursFirstAndNoSectionForOneCode) {
  const auto doc = document(hertz_pair());
  const ResultsIndex index(doc);
  EXPECT_EQ(solvers_in(index), (std::vector<std::string>{"builtin", "calculix"}));
  EXPECT_TRUE(is_cross_code(index));
  EXPECT_EQ(option_label_of(doc.cases[1].spec), "linear-ss");
  EXPECT_EQ(option_label_of(doc.cases[0].spec), "PM ss");

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

// Requirement: each code's row is its own, on both bases: CalculiX's common-basis row holds its
// spr values (2 % on F), its own-basis row its own stresses (here 3 %); ours has no own row
// (its own basis is the common one).
TEST(CrossCodeRows, EachCodeOnBothBases) {
  auto cases = hertz_pair();
  for (const auto m : kMeshes)
    cases.push_back(hertz_case(kCalculix, m, 3.0, 0.0, 30.0, CaseStatus::converged, "linear-ss",
                               schema::Recovery::own));
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const auto rows = code_rows(index, ProblemId::H_p, Quantity::sigma_c, Element::Q4);
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_EQ(rows[0].code, "builtin");  // ours first
  const CodeRow* theirs = find_row(rows, "calculix", "linear-ss");
  ASSERT_NE(theirs, nullptr);
  ASSERT_NE(theirs->common, nullptr);
  ASSERT_NE(theirs->own, nullptr);
  EXPECT_NEAR(*rows[0].common->errors[2], 0.5, 1e-9);
  EXPECT_EQ(rows[0].own, nullptr);
  EXPECT_NEAR(*theirs->common->errors[2], 2.0, 1e-9);
  EXPECT_NEAR(*theirs->own->errors[2], 3.0, 1e-9);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(md.find("| calculix | linear-ss | discretized | PM ss | +8.00 % | +4.00 % | +2.00 % | "
                    "g, c | — | +3.00 % |"),
            std::string::npos)
      << md;
}

// Requirement: a case CalculiX did not finish on F shows as its status, and the row has no
// grade (the study grades F only).
TEST(CrossCodeRows, TimeoutOnTheFineMeshIsShownAsSuch) {
  const auto doc = document(hertz_pair(true));
  const ResultsIndex index(doc);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(md.find("| +8.00 % | +4.00 % | timeout | no grade | — |"), std::string::npos) << md;
}

// Requirement: an error is printed with its sign: an under-estimate of the peak reads "−52.3 %",
// never "+52.3 %".
TEST(CrossCodeRows, ErrorsAreSigned) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    cases.push_back(hertz_case(SolverKind::builtin, m, 1.0));
    cases.push_back(hertz_case(kCalculix, m, -52.26));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_EQ(md.find("+52.3"), std::string::npos);
  EXPECT_NE(md.find("−52.3 %"), std::string::npos);
}

// Requirement: the advice per code names the options with the most e rows that are evidence,
// ties together; a row whose F case fails force balance is not evidence, whatever its error.
TEST(CrossCodeAdvice, MostERowsTiesTogetherNotCredibleLeftOut) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    const int i = static_cast<int>(m);
    const double errors[] = {2.0, 1.0, 0.5};
    cases.push_back(hertz_case(SolverKind::builtin, m, errors[i]));
    for (const std::string option : {"linear-ss", "linear-ns", "hard-ss"}) {
      CaseResult c = hertz_case(kCalculix, m, errors[i], 1.0, 10.0, CaseStatus::converged, option);
      if (option == "hard-ss" && m == MeshLevel::F)
        c.interface.emplace().force_balance = 0.5;
      cases.push_back(std::move(c));
    }
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const auto tallies = option_tallies(index);
  const auto best = advised(tallies, "calculix");
  ASSERT_EQ(best.size(), 2U);
  for (const OptionTally* t : best)
    EXPECT_EQ(t->e, 1) << t->option;
  const auto hard = std::find_if(tallies.begin(), tallies.end(),
                                 [](const OptionTally& t) { return t.option == "hard-ss"; });
  ASSERT_NE(hard, tallies.end());
  EXPECT_EQ(hard->e, 0);
  EXPECT_EQ(hard->not_evidence, 1);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(md.find("**calculix**: use linear-ns or linear-ss (best in 1 of 1 verdict cells)."),
            std::string::npos)
      << md;
  // Its table row: the grade marked as no evidence, beside the failed check.
  EXPECT_NE(md.find("| e, c ✗ | force balance 0.5 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| linear-ss | discretized | PM ss | +2.00 % | +1.00 % | +0.50 % | e, c | — |"),
            std::string::npos)
      << md;
}

// Requirement: a code's advice follows its verdict cells, as the verdict page weighs options, not
// a count of e rows that a situation of many rows can swing. On the rounded punch (S(1), S(1/3),
// S(1/7): one cell per element) linear-ns is e, e and u, linear-ss g, g and g; on the patch both
// are e. By e rows linear-ns led 6 to 2; by cells linear-ss is best in 4 of 4 (the punch's worst
// is u for linear-ns, which is never counted) and linear-ns in 2.
TEST(CrossCodeAdvice, AdviceFollowsTheVerdictCellsNotTheCountOfERows) {
  std::vector<CaseResult> cases;
  const auto add = [&](ProblemId problem, Quantity q, const std::string& option, MeshLevel m,
                       Element el, double error) {
    CaseResult c = hertz_case(kCalculix, m, error, 1.0, 10.0, CaseStatus::converged, option);
    c.spec.problem = problem;
    c.spec.element = el;
    c.quantities[0].quantity = q;
    cases.push_back(std::move(c));
  };
  for (const auto m : kMeshes) {
    cases.push_back(hertz_case(SolverKind::builtin, m, 0.5));  // ours: a cross-code document
    for (const Element el : {Element::Q4, Element::Q8}) {
      add(ProblemId::P_p, Quantity::sigma_z_max, "linear-ns", m, el, 0.1);
      add(ProblemId::P_p, Quantity::sigma_z_max, "linear-ss", m, el, 0.1);
      for (const ProblemId p : {ProblemId::S_1, ProblemId::S_1_3, ProblemId::S_1_7}) {
        add(p, Quantity::sigma_c, "linear-ns", m, el, p == ProblemId::S_1_7 ? 20.0 : 0.5);
        add(p, Quantity::sigma_c, "linear-ss", m, el, 2.0);
      }
    }
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const auto tallies = option_tallies(index);
  std::map<std::string, const OptionTally*> by;
  for (const auto& t : tallies)
    by[t.option] = &t;
  ASSERT_TRUE(by.count("linear-ns") && by.count("linear-ss"));
  EXPECT_EQ(by["linear-ns"]->e, 6);  // the punch's S(1) and S(1/3), and the patch, Q4 and Q8
  EXPECT_EQ(by["linear-ss"]->e, 2);
  EXPECT_EQ(by["linear-ns"]->cells, 4);  // the punch and the patch, Q4 and Q8
  EXPECT_EQ(by["linear-ns"]->best_cells, 2);
  EXPECT_EQ(by["linear-ss"]->best_cells, 4);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(md.find("**calculix**: use linear-ss (best in 4 of 4 verdict cells)."),
            std::string::npos)
      << md;
}

// Requirement: a code's options are counted on the same rows: a quantity only one option has
// (an option without contact pressure has no contact half-width) does not add to its count.
TEST(CrossCodeAdvice, OptionsCountedOnTheRowsTheyShare) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    cases.push_back(hertz_case(SolverKind::builtin, m, 0.5));
    cases.push_back(hertz_case(kCalculix, m, 0.5, 1.0, 10.0, CaseStatus::converged, "linear-ns"));
    CaseResult extra = hertz_case(kCalculix, m, 0.5, 1.0, 10.0, CaseStatus::converged, "linear-ss");
    schema::QuantityResult q = extra.quantities.front();
    q.quantity = Quantity::sigma_h;
    extra.quantities.push_back(q);
    cases.push_back(std::move(extra));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  int calculix_options = 0;
  for (const auto& t : option_tallies(index)) {
    if (t.code != "calculix")
      continue;
    ++calculix_options;
    EXPECT_EQ(t.rows, 1) << t.option;
    EXPECT_EQ(t.e, 1) << t.option;
  }
  EXPECT_EQ(calculix_options, 2);
  EXPECT_EQ(advised(option_tallies(index), "calculix").size(), 2U);
}

// Requirement: a code's options are counted like with like per target: an option run on
// another target too (GetFEM's labels between two meshes on IF_p) is tallied apart and named
// with its target, and does not empty the rows the code's options share on the first (counted
// over both targets, the shared rows were none: every tally read 0).
TEST(CrossCodeAdvice, OptionsOnAnotherTargetAreCountedApart) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    cases.push_back(hertz_case(SolverKind::builtin, m, 0.5));
    for (const std::string option : {"linear-ns", "linear-ss"})
      cases.push_back(hertz_case(kCalculix, m, 0.5, 1.0, 10.0, CaseStatus::converged, option));
    CaseResult other = hertz_case(kCalculix, m, 0.5, 1.0, 10.0, CaseStatus::converged, "linear-ns");
    other.spec.element = Element::Q8;
    other.spec.target = schema::TargetKind::Rigid;
    cases.push_back(std::move(other));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  int rigid = 0, discretized = 0;
  for (const auto& t : option_tallies(index)) {
    if (t.code != "calculix")
      continue;
    ++(t.target == schema::TargetKind::Rigid ? rigid : discretized);
    EXPECT_EQ(t.rows, 1) << t.option << " " << schema::to_string(t.target);
  }
  EXPECT_EQ(rigid, 1);
  EXPECT_EQ(discretized, 2);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(md.find("| linear-ns (rigid target) | 1 of 1 | 1 |"), std::string::npos) << md;
  // The advice is given per target: the rigid target's one option is not outnumbered.
  EXPECT_NE(md.find("**calculix**: with the discretized target, use linear-ns or linear-ss (best "
                    "in 1 of 1 verdict cells); with the rigid target, use linear-ns (best in 1 of "
                    "1 verdict cells)."),
            std::string::npos)
      << md;
}

// Requirement: a code's cost is its recorded wall time per converged case beside ours on the same
// models: CalculiX 10 and 20 s (its F case timed out at 40 s: counted, not timed) against ours
// 1, 2, 4 s, so 15 s against 2.33 s per case; peaks 30..90 MB against 10..30 MB (three times).
TEST(CrossCodeCost, PerCaseRatiosOnTheSameModels) {
  const auto doc = document(hertz_pair(true));
  const ResultsIndex index(doc);
  const auto costs = code_costs(index);
  ASSERT_EQ(costs.size(), 1U);
  EXPECT_EQ(costs[0].code, "calculix");
  ASSERT_EQ(costs[0].lines.size(), 3U);  // H_p C, M, F
  EXPECT_EQ(costs[0].total.cases, 3);
  EXPECT_EQ(costs[0].total.converged, 2);
  EXPECT_DOUBLE_EQ(costs[0].total.seconds, 30.0);
  EXPECT_DOUBLE_EQ(costs[0].total.ours_seconds, 7.0);
  EXPECT_DOUBLE_EQ(costs[0].total.peak_mb, 90.0);
  EXPECT_DOUBLE_EQ(costs[0].total.ours_peak_mb, 30.0);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(md.find("| all models | 3 (2) | 15 | 90 | 3 | 2.33 | 30 | 6.43 | 3 |"),
            std::string::npos)
      << md;
}

// Requirement: a case that did not converge gives no grade and its value is marked as the last
// iterate: CalculiX's F case stops at -100 % (GetFEM's integral brick on H_p Q8 does), which
// read "u" before, a grade from a solve that failed.
TEST(CrossCodeSection, ANotConvergedFineCaseHasNoGradeAndAMarkedValue) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    cases.push_back(hertz_case(SolverKind::builtin, m, 0.5));
    const bool fine = m == MeshLevel::F;
    cases.push_back(hertz_case(kCalculix, m, fine ? -100.0 : 1.0, 1.0, 10.0,
                               fine ? CaseStatus::not_converged : CaseStatus::converged));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const std::string md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(md.find("| +1.00 % | +1.00 % | −100.0 %! | none: F not converged | not converged |"),
            std::string::npos)
      << md;
}

// Requirement (issue #24, each code's cost measured in one run): given a cost run, the cost
// tables are its times, not those the graded results recorded (CalculiX 10, 20, 40 s against
// ours 1, 2, 4 s there; 3 s against 1 s per case in the cost run), and say where they come from.
TEST(CrossCodeCost, FromTheCostRunWhenOneIsGiven) {
  const auto doc = document(hertz_pair(true));
  const ResultsIndex index(doc);
  std::vector<CaseResult> timed;
  for (const auto m : kMeshes) {
    timed.push_back(hertz_case(SolverKind::builtin, m, 1.0, 1.0, 20.0));
    timed.push_back(hertz_case(kCalculix, m, 2.0, 3.0, 50.0));
  }
  auto cost_doc = document(timed);
  cost_doc.run.started_utc = "2026-11-27T09:30:00Z";
  const ResultsIndex cost_run(cost_doc);
  const std::string md = cross_code_section(index, study(), {}, {}, &cost_run);
  EXPECT_NE(md.find("| all models | 3 (3) | 3 | 50 | 3 | 1 | 20 | 3 | 2.5 |"), std::string::npos)
      << md;
  EXPECT_EQ(md.find("| all models | 3 (2) | 23.3 |"), std::string::npos);
  EXPECT_NE(md.find("measured in one run (`ci/cost-run.sh`, started 2026-11-27T09:30:00Z"),
            std::string::npos);
  EXPECT_NE(md.find("the same models (target: discretized)"), std::string::npos) << md;
  EXPECT_EQ(md.find("as each battery part recorded them"), std::string::npos);
}

// Requirement: the report of a document with two codes has the cross-code appendix, titled by
// the codes, with the option mapping handed in.
TEST(CrossCodeSection, InTheReportOnlyWithSeveralCodes) {
  const auto doc = document(hertz_pair());
  const ResultsIndex index(doc);
  const std::vector<SolverOptionMapping> mapping{
      {"calculix:linear-ss", "PM ss", "PRESSURE-OVERCLOSURE=LINEAR", "penalty"}};
  const std::string md = cross_code_section(index, study(), {}, mapping);
  EXPECT_NE(md.find("## Other codes beside ours: ours and calculix"), std::string::npos);
  EXPECT_NE(md.find("| linear-ss | penalty | PM ss | PRESSURE-OVERCLOSURE=LINEAR |"),
            std::string::npos);
  ReportContent content;
  content.cross_code_md = md;
  content.companions = {{.path = "x/report.md", .title = "T", .writer = ""}};
  const auto appendices = appendix_pages(index, study(), content);
  const std::string report = report_markdown(index, content, {}, appendices);
  EXPECT_NE(report.find("(appendix-cross-code.md)"), std::string::npos);
  EXPECT_EQ(report.rfind(
                "# contact-suite report: ours and calculix beside the study's ANSYS results\n", 0),
            0u);
  EXPECT_NE(report.find("\nAlso: [T](x/report.md).\n"), std::string::npos);
}

// Requirement: the first screen's matrices set each other code's options beside ours, on the
// common basis only (its own stresses, 3 % on F here, are not shown), named by code; each code
// gets its advice there in one line (the cross-code appendix's own), linked to that appendix; the
// caveat names the matrix's solvers and its recovery (no code's own stresses called
// "extrapolated").
TEST(CrossCodeSection, TheVerdictPageGivesEachOtherCodesAdvice) {
  std::vector<CaseResult> cases = hertz_pair();
  for (const auto m : kMeshes) {  // CalculiX's own stresses too, as the battery grades them
    const double own[] = {9.0, 5.0, 3.0};
    cases.push_back(hertz_case(kCalculix, m, own[static_cast<int>(m)], 1.0, 10.0,
                               CaseStatus::converged, "linear-ss", schema::Recovery::own));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const std::vector<std::string> lines = code_advice_lines(index);
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_EQ(lines[0], "**calculix**: use linear-ss (best in 1 of 1 verdict cells).");
  ReportContent content;
  content.cross_code_md = cross_code_section(index, study(), {}, {});
  EXPECT_NE(content.cross_code_md.find("\n" + lines[0] + "\n"), std::string::npos);
  const auto appendices = appendix_pages(index, study(), content);
  const std::string report = report_markdown(index, content, {}, appendices);
  const std::string verdict = report.substr(0, report.find("## The study's claims"));
  // Our row names the algorithm run, PM alone here (not "AL, PM": no AL case is in the results).
  EXPECT_NE(verdict.find("| PM ss | e +0.50 % |\n| calculix linear-ss | g +2.00 % |\n"),
            std::string::npos)
      << verdict;
  EXPECT_NE(verdict.find("- **Smooth curved contact (Hertz):** use PM ss Q4: e, +0.50 %."),
            std::string::npos);
  EXPECT_NE(verdict.find("**Other codes.** Their options are rows of the matrices, named by code"),
            std::string::npos);
  EXPECT_NE(verdict.find("; [Other codes beside ours](appendix-cross-code.md)):"),
            std::string::npos);
  EXPECT_NE(verdict.find("\n- " + lines[0] + "\n"), std::string::npos);
  EXPECT_NE(verdict.find("**Caveats.** Solver: ours and calculix. Graded with patch-recovered "
                         "nodal stresses (SPR);"),
            std::string::npos);
  EXPECT_EQ(verdict.find("extrapolated nodal stresses (as ANSYS prints them)"), std::string::npos);

  // One code: no such note.
  const auto ours_doc = document({hertz_case(SolverKind::builtin, MeshLevel::F, 0.5)});
  const ResultsIndex ours_only(ours_doc);
  EXPECT_TRUE(code_advice_lines(ours_only).empty());
  const std::string alone = report_markdown(ours_only, {}, {}, {});
  EXPECT_EQ(alone.find("**Other codes.**"), std::string::npos);
}

// Requirement: results of another code alone (imported, or run without ours) get a verdict of
// their own, graded as ours would be, and the caveat names that code; no cross-code note.
TEST(CrossCodeSection, AnotherCodeAloneGetsItsOwnVerdict) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    const double errors[] = {3.0, 1.5, 0.6};
    cases.push_back(hertz_case(kCalculix, m, errors[static_cast<int>(m)]));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  EXPECT_TRUE(code_advice_lines(index).empty());
  const std::string report = report_markdown(index, {}, {}, {});
  EXPECT_NE(report.find("| calculix linear-ss | e +0.60 % |"), std::string::npos) << report;
  EXPECT_NE(report.find("- **Smooth curved contact (Hertz):** use calculix linear-ss Q4: e, "
                        "+0.60 %."),
            std::string::npos);
  EXPECT_NE(report.find("**Caveats.** Solver: calculix. Graded with"), std::string::npos) << report;
  EXPECT_EQ(report.find("**Other codes.**"), std::string::npos);
}

// Requirement: no grade from a solve that failed, on the first screen either: an option whose F
// case did not converge shows its last iterate's error marked †, no grade, is to be avoided, and
// its failure says so.
TEST(CrossCodeSection, TheVerdictGradesNoCellWhoseFineCaseDidNotConverge) {
  std::vector<CaseResult> cases;
  for (const auto m : kMeshes) {
    const int i = static_cast<int>(m);
    const double ours[] = {4.0, 2.0, 0.5}, theirs[] = {8.0, 4.0, 0.2};
    cases.push_back(hertz_case(SolverKind::builtin, m, ours[i]));
    cases.push_back(
        hertz_case(kCalculix, m, theirs[i], 1.0, 10.0,
                   m == MeshLevel::F ? CaseStatus::not_converged : CaseStatus::converged));
  }
  const auto doc = document(cases);
  const ResultsIndex index(doc);
  const std::string report = report_markdown(index, {}, {}, {});
  EXPECT_NE(report.find("| calculix linear-ss | +0.20 % † |"), std::string::npos) << report;
  EXPECT_NE(report.find("use PM ss Q4: e, +0.50 %. Avoid calculix linear-ss Q4."),
            std::string::npos);
  EXPECT_NE(report.find("- Smooth curved contact (Hertz), calculix linear-ss Q4: F not converged "
                        "on 1 of 1 rows."),
            std::string::npos);
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
  const auto rows = code_rows(index, ProblemId::H_p, Quantity::sigma_c, Element::Q4);
  ASSERT_EQ(rows.size(), 2U);
  const auto* ours = results[0].quantity(Quantity::sigma_c);
  const auto* theirs = results[1].quantity(Quantity::sigma_c);
  ASSERT_NE(ours, nullptr);
  ASSERT_NE(theirs, nullptr);
  EXPECT_NEAR(ours->value, kHertzExact, 0.1 * kHertzExact);
  EXPECT_NEAR(theirs->value, kHertzExact, 0.1 * kHertzExact);
  EXPECT_NE(ours->value, theirs->value);  // two solvers, two answers
  EXPECT_EQ(rows[0].code, "builtin");
  EXPECT_EQ(rows[1].code, "calculix");
  EXPECT_EQ(rows[0].common->values[0], ours->value);
  EXPECT_EQ(rows[1].common->values[0], theirs->value);
  const auto costs = code_costs(index);
  ASSERT_EQ(costs.size(), 1U);
  EXPECT_DOUBLE_EQ(costs[0].total.seconds, results[1].wall_seconds);
  EXPECT_DOUBLE_EQ(costs[0].total.ours_seconds, results[0].wall_seconds);
}

}  // namespace
}  // namespace cs::reports
