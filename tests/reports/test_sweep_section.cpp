// The parameter-sweep section on in-memory results documents: absent without swept cases; the
// FKN answers (the e window, AL iterations, AL against PM, the study's S(1/3) AL error) computed
// from the numbers; the E-ratio settling point; FTOLN's spread; a series per option set.

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "report_test_support.hpp"
#include "reports/figures/sweep_figure.hpp"
#include "reports/findings/sweep_section.hpp"
#include "suites/row_verdict.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::CaseResult;
using schema::ContactKind;
using schema::Element;
using schema::MeshLevel;
using schema::ProblemId;
using schema::Quantity;

CaseResult swept_case(ProblemId p, Element e, Algorithm a, const std::string& key, double v,
                      double error, int iterations, bool converged = true,
                      MeshLevel mesh = MeshLevel::F) {
  CaseResult c;
  c.spec = schema::CaseSpec{.problem = p,
                            .mesh = mesh,
                            .element = e,
                            .algorithm = a,
                            .contact = ContactKind::ss,
                            .overrides = {}};
  c.spec.overrides[key] = v;
  c.status = converged ? schema::CaseStatus::converged : schema::CaseStatus::not_converged;
  c.iterations = iterations;
  schema::QuantityResult q;
  q.quantity = Quantity::sigma_c;
  q.exact = 1.0;
  q.value = 1.0 + error / 100.0;
  q.error_percent = error;
  q.grade = grading::grade_of_error(error);
  c.quantities.push_back(q);
  return c;
}

schema::ResultsDocument document(std::vector<CaseResult> cases,
                                 std::vector<schema::SweepAxis> sweep) {
  schema::ResultsDocument doc;
  doc.run.sweep = std::move(sweep);
  doc.cases = std::move(cases);
  return doc;
}

// Requirement: no swept case, no section (and no figure).
TEST(SweepSection, AbsentWithoutSweptCases) {
  const testing::Loaded data(testing::sample_json());
  EXPECT_EQ(sweep_section(data.index, testing::study(), {}), "");
  EXPECT_TRUE(swept_keys(data.file).empty());
}

// Requirement: the FKN answers come from the numbers: the window where every AL/PM row is e
// (and e or g), AL iterations at both ends, non-convergence at the top, where AL and PM
// separate, and the range of a default.
TEST(SweepSection, FknAnswersFromTheNumbers) {
  const std::vector<double> fkn{0.01, 1, 100, 1e4};
  // AL: soft at small FKN, e from 100; PM equal to AL except at 0.01 (AL augmented).
  const double al[] = {-40.0, -6.3, -0.7, -0.5};
  const double pm[] = {-73.0, -6.3, -0.7, -0.5};
  const int al_it[] = {3, 8, 13, 16};
  std::vector<CaseResult> cases;
  for (std::size_t i = 0; i < fkn.size(); ++i) {
    cases.push_back(swept_case(ProblemId::H_a, Element::Q4, Algorithm::AL, "fkn", fkn[i], al[i],
                               al_it[i], i < 3));
    cases.push_back(
        swept_case(ProblemId::H_a, Element::Q4, Algorithm::PM, "fkn", fkn[i], pm[i], 2, i < 3));
    cases.push_back(
        swept_case(ProblemId::H_a, Element::Q4, Algorithm::LMP, "fkn", fkn[i], -0.6, 10));
  }
  const auto doc = document(cases, {{"fkn", fkn}});
  const ResultsIndex index(doc);
  const std::string md = sweep_section(index, testing::study(), {});
  EXPECT_NE(md.find("## Parameter sweeps"), std::string::npos);
  EXPECT_NE(md.find("### FKN, the normal penalty stiffness (fkn)"), std::string::npos);
  // e at 100 only (1e4 did not converge), e or g likewise.
  // The two windows coincide: said once.
  EXPECT_NE(md.find("is e at FKN = 100, and e or g at no other"), std::string::npos) << md;
  EXPECT_NE(md.find("AL iterations (most of any swept case) go from 3 at FKN = 0.01 to 16 at "
                    "FKN = 10000; AL/PM cases that do not converge: 2 at FKN = 10000"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("smallest swept FKN at which every swept AL/PM row is e or g is 100; there "
                    "AL takes at most 13 iterations (LMP, which enforces contact exactly, 10)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("AL and PM separate at FKN = 0.01 (by up to 33 percentage points"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("−6.30 % s, 8 it"), std::string::npos) << md;
  EXPECT_NE(md.find("(not converged)"), std::string::npos);
  // A case that did not converge is not graded: its cell reads "<error>, <n> it (not
  // converged)", never a grade letter beside the error.
  for (std::size_t at = md.find(" (not converged)"); at != std::string::npos;
       at = md.find(" (not converged)", at + 1)) {
    const std::string cell = md.substr(md.rfind('|', at) + 1, at - md.rfind('|', at) - 1);
    EXPECT_EQ(cell.find(" % "), std::string::npos) << cell;  // "+0.23 %, 13 it"
  }
  EXPECT_NE(md.find("Convergence (c) needs the C, M and F meshes"), std::string::npos);
  // One panel (H_a sigma_c F Q4) with three curves.
  const auto series = sweep_series(doc, "fkn");
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series[0].points.size(), 4u);
  const auto panels = sweep_panels(series);
  ASSERT_EQ(panels.size(), 1u);
  EXPECT_EQ(panels[0].size(), 3u);
}

// Requirement: the S(1/3) question is answered against the study's own printed AL value
// (sigma_c, 4Q, ss, F): a crossing is interpolated in log FKN; none is reported as none.
TEST(SweepSection, StudyAlErrorOnSOneThird) {
  // Our exact value, not the study's printed 10.9571: the study's 9.5320 is -15.21 % of it.
  const auto s13 = [](double fkn, double error, int iterations) {
    CaseResult c =
        swept_case(ProblemId::S_1_3, Element::Q4, Algorithm::AL, "fkn", fkn, error, iterations);
    c.quantities[0].exact = 11.2424;
    c.quantities[0].value = 11.2424 * (1.0 + error / 100.0);
    return c;
  };
  const auto crossing = document({s13(0.1, -30.0, 4), s13(10, -2.0, 8)}, {{"fkn", {0.1, 10}}});
  const ResultsIndex a(crossing);
  const std::string md = sweep_section(a, testing::study(), {});
  // -15.21 % lies 0.528 of the way from -30 % to -2 %: 10^(-1 + 2 * 0.528) = 1.1.
  EXPECT_NE(md.find("9.5320, −15.2 % against the exact value 11.2424 of our errors; the study "
                    "printed 10.9571) is reproduced near FKN = 1.1"),
            std::string::npos)
      << md;
  const auto none =
      document({swept_case(ProblemId::S_1_3, Element::Q4, Algorithm::AL, "fkn", 1, -3.0, 4),
                swept_case(ProblemId::S_1_3, Element::Q4, Algorithm::AL, "fkn", 10, -2.0, 8)},
               {{"fkn", {1, 10}}});
  const ResultsIndex b(none);
  EXPECT_NE(sweep_section(b, testing::study(), {}).find("is reproduced by no swept FKN"),
            std::string::npos);
  // Only our own series of the study's option set is compared with the study's value: the same
  // crossing against a rigid target is another option set.
  auto rigid = crossing;
  for (auto& c : rigid.cases)
    c.spec.target = schema::TargetKind::Rigid;
  const ResultsIndex r(rigid);
  const std::string rigid_md = sweep_section(r, testing::study(), {});
  EXPECT_EQ(rigid_md.find("is reproduced near FKN"), std::string::npos) << rigid_md;
}

// Requirement: the convergence answer counts the AL/PM rows it speaks of (run on C, M and F)
// and says where all of them converge; with none converging everywhere it says so.
TEST(SweepSection, FknConvergenceCountsItsRows) {
  // One AL row per FKN on C, M and F: errors 2, 1, 0.5 % (converging), or 2, 9, 0.5 % (not).
  const auto row_at = [](double fkn, double m_error) {
    std::vector<CaseResult> out;
    const double errors[] = {2.0, m_error, 0.5};
    for (const MeshLevel m : {MeshLevel::C, MeshLevel::M, MeshLevel::F}) {
      out.push_back(swept_case(ProblemId::H_a, Element::Q4, Algorithm::AL, "fkn", fkn,
                               errors[static_cast<int>(m)], 5, true, m));
    }
    return out;
  };
  const auto section = [&](double m_error_at_1) {
    auto doc = document(row_at(1, m_error_at_1), {{"fkn", {1, 100}}});
    std::ranges::copy(row_at(100, 9.0), std::back_inserter(doc.cases));
    doc.rows = suites::make_row_verdicts(doc.cases);
    const ResultsIndex index(doc);
    return sweep_section(index, testing::study(), {});
  };
  const std::string md = section(1.0);
  EXPECT_NE(md.find("Of these rows, the 1 run on C, M and F all converge (c) at FKN = 1."),
            std::string::npos)
      << md;
  EXPECT_NE(section(9.0).find("the 1 run on C, M and F do not all converge (c) at any swept FKN"),
            std::string::npos)
      << section(9.0);
  // Convergence of cases that fail an interface check is said to be no evidence.
  auto doc = document(row_at(1, 1.0), {{"fkn", {1, 100}}});
  std::ranges::copy(row_at(100, 9.0), std::back_inserter(doc.cases));
  for (auto& c : doc.cases) {
    if (c.spec.overrides.at("fkn") == 1 && c.spec.mesh == MeshLevel::F)
      c.interface.emplace().max_tensile_over_p = 5.0;
  }
  doc.rows = suites::make_row_verdicts(doc.cases);
  const ResultsIndex index(doc);
  const std::string pulls = sweep_section(index, testing::study(), {});
  EXPECT_NE(pulls.find("all converge (c) at FKN = 1, where 1 of their 1 fine-mesh cases fail an "
                       "interface check"),
            std::string::npos)
      << pulls;
  // Two quantities read from one analysis are two rows but one fine-mesh case.
  for (auto& c : doc.cases) {
    auto second = c.quantities[0];
    second.quantity = Quantity::sigma_h;
    c.quantities.push_back(second);
  }
  doc.rows = suites::make_row_verdicts(doc.cases);
  const ResultsIndex two(doc);
  const std::string rows2 = sweep_section(two, testing::study(), {});
  EXPECT_NE(rows2.find("the 2 run on C, M and F all converge (c) at FKN = 1, where 1 of their 1 "
                       "fine-mesh cases fail an interface check"),
            std::string::npos)
      << rows2;
}

// Requirement: a swept case that fails an interface check is marked ✗ in the table and the
// pinball answer: its grade is not evidence.
TEST(SweepSection, MarksCasesThatAreNotCredible) {
  std::vector<CaseResult> cases;
  for (double pinball : {0.5, 1.0}) {
    cases.push_back(
        swept_case(ProblemId::H_p, Element::Q8, Algorithm::MPC, "pinball", pinball, -0.3, 3));
    cases.back().interface.emplace().max_tensile_over_p = pinball == 0.5 ? 160.0 : 0.0;
  }
  const auto doc = document(cases, {{"pinball", {0.5, 1.0}}});
  const ResultsIndex index(doc);
  const std::string md = sweep_section(index, testing::study(), {});
  EXPECT_NE(md.find("| −0.30 % e ✗, 3 it | −0.30 % e, 3 it |"), std::string::npos) << md;
  EXPECT_NE(md.find("−0.30 % ✗ at 0.5, −0.30 % at 1"), std::string::npos) << md;
}

// Requirement: the E ratio stops mattering where every larger ratio is within the study's
// resolution (0.01 points) of the error at the largest (0.02 points off is not settled); an FTOLN
// sweep where nothing moves names no curve, and says it cannot show FTOLN when no penetration
// reaches the smallest FTOLN swept; a key found only in the cases (not in run.sweep) is
// reported too.
TEST(SweepSection, ERatioSettlesAndFtolnSpread) {
  std::vector<CaseResult> cases;
  const double e[] = {-5.0, -0.52, -0.505, -0.50};
  const double ratio[] = {1e3, 1e4, 1e5, 1e6};
  for (int i = 0; i < 4; ++i)
    cases.push_back(
        swept_case(ProblemId::H_p, Element::Q4, Algorithm::LMP, "E_ratio", ratio[i], e[i], 9));
  for (double f : {0.01, 0.1}) {
    cases.push_back(swept_case(ProblemId::H_p, Element::Q8, Algorithm::AL, "ftoln", f, -0.25, 7));
    cases.back().interface.emplace().max_penetration_over_h = 1.5e-5;
  }
  const auto doc = document(cases, {{"E_ratio", {1e3, 1e4, 1e5, 1e6}}});
  const ResultsIndex index(doc);
  const std::string md = sweep_section(index, testing::study(), {});
  EXPECT_NE(md.find("from E ratio 100000 on, for every row swept"), std::string::npos) << md;
  EXPECT_NE(md.find("H_p sigma_c F Q4 LMP ss: from E ratio 100000 on (−0.50 % at 1e+06)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("### FTOLN, the penetration tolerance (ftoln)"), std::string::npos) << md;
  EXPECT_NE(md.find("no error changes by more than 0.01 percentage points (the largest change: 0)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("the largest penetration of these AL cases is 1.5e-05 h, below the smallest "
                    "FTOLN swept (0.01): AL never augmented"),
            std::string::npos)
      << md;
  // An error at round-off level keeps its digits and sign; it is not printed as +0.00 %.
  const auto exact = document(
      {swept_case(ProblemId::Pprime_p, Element::Q4, Algorithm::AL, "E_ratio", 1e3, 2e-10, 4),
       swept_case(ProblemId::Pprime_p, Element::Q4, Algorithm::AL, "E_ratio", 1e9, 1.3e-10, 4)},
      {{"E_ratio", {1e3, 1e9}}});
  const ResultsIndex exact_index(exact);
  const std::string exact_md = sweep_section(exact_index, testing::study(), {});
  EXPECT_NE(exact_md.find("(+1.3e-10 % at 1e+09)"), std::string::npos) << exact_md;
  EXPECT_EQ(exact_md.find("+0.00 %"), std::string::npos) << exact_md;
}

}  // namespace
}  // namespace cs::reports

namespace cs::reports {
namespace {

// Requirement: in a sweep figure an error exact to round-off is left out of the log plot and
// the notes say so, and the problem's default value of the key is marked "default" (or the
// notes say the results do not record it).
TEST(SweepFigure, RoundOffLeftOutAndDefaultMarked) {
  auto doc =
      document({swept_case(ProblemId::H_a, Element::Q4, Algorithm::AL, "fkn", 1, -6.0, 4),
                swept_case(ProblemId::H_a, Element::Q4, Algorithm::AL, "fkn", 10, 0.0, 6),
                swept_case(ProblemId::H_a, Element::Q4, Algorithm::AL, "fkn", 100, -0.5, 8, false)},
               {{"fkn", {1, 10, 100}}});
  const auto series_of_fkn = sweep_series(doc, "fkn");  // the panels point into it
  const auto panels = sweep_panels(series_of_fkn);
  Figure without;
  const Plot unmarked = sweep_plot(doc, "fkn", panels, without);
  ASSERT_EQ(unmarked.panels.size(), 1u);
  EXPECT_TRUE(unmarked.panels[0].marks.empty());
  ASSERT_EQ(without.notes.size(), 2u);
  EXPECT_NE(without.notes[0].find("1 error(s) below"), std::string::npos) << without.notes[0];
  EXPECT_NE(without.notes[1].find("do not record the default fkn"), std::string::npos);
  // The line through the two drawn points; filled symbol where converged, open where not.
  const auto& series = unmarked.panels[0].series;
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series[0].xy, (std::vector<std::pair<double, double>>{{1, 6.0}, {100, 0.5}}));
  EXPECT_EQ(series[1].xy.size(), 1u);
  EXPECT_EQ(series[2].xy.size(), 1u);

  doc.parameter_defaults[ProblemId::H_a]["fkn"] = 100;
  Figure with;
  const Plot marked = sweep_plot(doc, "fkn", panels, with);
  ASSERT_EQ(marked.panels[0].marks.size(), 1u);
  EXPECT_EQ(marked.panels[0].marks[0].x, 100);
  EXPECT_EQ(marked.panels[0].marks[0].label, "default");
  EXPECT_EQ(with.notes.size(), 1u);
}

// Requirement: the study's keys keep their plain file names, and keys that differ only in
// punctuation get files of their own (their figures are drawn side by side, so a shared file
// would be written twice at once).
TEST(SweepFigure, EachKeyHasAFileOfItsOwn) {
  EXPECT_EQ(sweep_figure_file("fkn"), "figures/sweep_fkn.png");
  EXPECT_EQ(sweep_figure_file("E_ratio"), "figures/sweep_E_ratio.png");
  EXPECT_EQ(sweep_figure_file("a.b"), "figures/sweep_a-2eb.png");
  std::set<std::string> files;
  for (const char* key : {"a.b", "a_b", "a-b", "a b", "a-2eb", "a\xff"})
    files.insert(sweep_figure_file(key));
  EXPECT_EQ(files.size(), 6u);
}

}  // namespace
}  // namespace cs::reports
