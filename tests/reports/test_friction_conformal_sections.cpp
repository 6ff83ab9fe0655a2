// The friction and conformal-contact sections, on results documents built in memory (rows only:
// the sections read the rows' fine-mesh values, errors and grades), with known numbers.
//
// Requirements:
//   - conformal: every option's fine-mesh mean-pressure error and arc deviation are shown; the
//     worst and best options by |arc deviation| are found from the rows; the LM ss/mortar mean
//     pressure is judged against 1 % from the rows;
//   - friction: LMP beside PLM with their difference; the largest difference is found and
//     worded, and equal pairs are counted as equal (below 0.01 percentage points);
//   - a document without such problems gives no section (the hand-made study sample).

#include <string>

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "report_test_support.hpp"
#include "reports/tables/conformal_section.hpp"
#include "reports/tables/friction_section.hpp"
#include "suites/problem_catalog.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::Element;
using schema::ProblemId;
using schema::Quantity;

/// A complete baseline row with values 1 + e/100 (exact 1) and the errors e on C, M, F.
schema::RowVerdict row(ProblemId problem, Quantity q, Element element, Algorithm a, ContactKind c,
                       std::array<double, 3> errors, double exact = 1.0) {
  schema::RowVerdict r;
  r.spec.problem = problem;
  r.spec.element = element;
  r.spec.algorithm = a;
  r.spec.contact = c;
  r.quantity = q;
  r.id = schema::case_key(r.spec) + "/" + std::string(schema::to_string(q));
  for (std::size_t m = 0; m < 3; ++m) {
    r.errors[m] = errors[m];
    r.values[m] = exact * (1.0 + errors[m] / 100.0);
  }
  r.grade = grading::grade_of_error(errors[2]);
  r.graded_mesh = schema::MeshLevel::F;
  r.converging = std::abs(errors[2]) < std::abs(errors[0]);
  return r;
}

schema::ResultsDocument conformal_document() {
  schema::ResultsDocument doc;
  doc.problems.push_back(suites::problem_descriptor(ProblemId::IF_p).record);
  const auto add = [&](Element e, Algorithm a, ContactKind c, double mean, double arc) {
    doc.rows.push_back(row(ProblemId::IF_p, Quantity::p_mean, e, a, c, {4 * mean, 2 * mean, mean}));
    doc.rows.push_back(row(ProblemId::IF_p, Quantity::p_arc, e, a, c, {4 * arc, 2 * arc, arc}));
  };
  add(Element::Q8, Algorithm::LMP, ContactKind::ns, -0.02, 35.0);
  add(Element::Q8, Algorithm::LMP, ContactKind::ss, 0.3, -0.4);
  add(Element::Q4, Algorithm::PLM, ContactKind::mortar, -0.6, 0.05);
  add(Element::Q4, Algorithm::PM, ContactKind::ss, -3.0, -3.2);
  add(Element::Q8, Algorithm::PLM, ContactKind::ss, 0.3, -0.055);  // ties the best, 0.005 off
  return doc;
}

TEST(ConformalSection, FindsTheWorstAndBestArcOptionsAndJudgesTheLmMean) {
  const schema::ResultsDocument doc = conformal_document();
  const ResultsIndex index(doc);
  const auto arc = arc_range(index, ProblemId::IF_p);
  ASSERT_TRUE(arc.has_value());
  const ArcExtreme *worst = &arc->worst, *best = &arc->best;
  EXPECT_DOUBLE_EQ(worst->deviation_percent, 35.0);
  EXPECT_EQ(worst->element, Element::Q8);
  EXPECT_EQ(worst->option.label(), "LMP ns");
  EXPECT_DOUBLE_EQ(best->deviation_percent, 0.05);
  EXPECT_EQ(best->option.label(), "PLM mortar");
  const std::string md = conformal_section(index);
  // The tie of magnitudes has both signs: its range, never one signed value for both.
  EXPECT_NE(md.find("the smallest −0.06 % … +0.05 % (Q4 PLM mortar, Q8 PLM ss)"), std::string::npos)
      << md;
  EXPECT_NE(md.find("every option's largest deviation lies within −3.20 % … +35.0 %"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("The largest is +35.0 % (Q8 LMP ns)"), std::string::npos) << md;
  EXPECT_NE(md.find("## Conformal contact"), std::string::npos);
  EXPECT_NE(md.find("### IF<sub>p</sub>"), std::string::npos);
  // LM ss/mortar worst mean: -0.6 % (Q4 PLM mortar), within 1 %; PM (-3 %) is not LM.
  EXPECT_NE(md.find("the largest error of the mean pressure is −0.60 % (within 1 %)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| Q8 | ns | — | — | −0.02 % / +35.0 % (e, c / u, c) | — | — |"),
            std::string::npos)
      << md;
  EXPECT_EQ(friction_section(index), "");
}

TEST(FrictionSection, ComparesLmpWithPlm) {
  schema::ResultsDocument doc;
  doc.problems.push_back(suites::problem_descriptor(ProblemId::CM_p).record);
  for (const auto c : {ContactKind::ss, ContactKind::ns, ContactKind::mortar}) {
    doc.rows.push_back(
        row(ProblemId::CM_p, Quantity::c_over_a, Element::Q4, Algorithm::PLM, c, {8, 4, 2}));
    doc.rows.push_back(row(ProblemId::CM_p, Quantity::c_over_a, Element::Q4, Algorithm::LMP, c,
                           {8, 4,
                            c == ContactKind::mortar ? 2.005
                            : c == ContactKind::ns   ? -3.506  // 0.006 from ss's 5.5: a tie
                                                     : -3.5}));
  }
  const ResultsIndex index(doc);
  const LmpPlmDifference d = lmp_plm_difference(index, ProblemId::CM_p);
  EXPECT_EQ(d.n_pairs, 3);
  EXPECT_EQ(d.n_equal, 1);  // 0.005 points apart: equal
  EXPECT_NEAR(d.points, 5.506, 1e-12);
  EXPECT_EQ(d.contact, ContactKind::ns);
  EXPECT_EQ(d.largest_at.size(), 2u);  // ss and ns tie within 0.01 points: both named
  const std::string md = friction_section(index);
  EXPECT_NE(md.find("## Friction"), std::string::npos);
  EXPECT_NE(md.find("on 1 of 3 pairs; the largest difference is 5.51 percentage points"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find(" Q4 ss; "), std::string::npos) << md;
  EXPECT_NE(md.find(" Q4 ns)"), std::string::npos) << md;
  EXPECT_EQ(conformal_section(index), "");
  // LMP ns moves 7.506 points from M (+4 %) to F (-3.506 %): the 5.506-point gap to PLM is
  // within that noise, and the section says these meshes do not resolve it; no pair differs
  // beyond its own noise.
  EXPECT_NEAR(d.largest_noise, 7.506, 1e-12);
  EXPECT_EQ(d.n_beyond_noise, 0);
  EXPECT_NE(md.find("within what one refinement changes in either row (7.51 points), so these "
                    "meshes do not resolve it; 0 of 3 pairs differ by more than their own noise"),
            std::string::npos)
      << md;
  // With LMP at -3 % on M, it moves 0.5 points: the gap is beyond the pair's noise (2 points, PLM's
  // move), and the section does not call it unresolved.
  for (auto& r : doc.rows) {
    if (r.spec.algorithm == Algorithm::LMP && r.spec.contact != ContactKind::mortar)
      r.errors[1] = -3.0;
  }
  const ResultsIndex moved(doc);
  const LmpPlmDifference resolved = lmp_plm_difference(moved, ProblemId::CM_p);
  EXPECT_NEAR(resolved.largest_noise, 2.0, 1e-12);
  EXPECT_EQ(resolved.n_beyond_noise, 2);
  EXPECT_EQ(friction_section(moved).find("do not resolve it"), std::string::npos);
}

// Requirement: a fine-mesh value without an error (an exact value of zero) stands alone in the
// LMP/PLM table; no NaN is printed.
TEST(FrictionSection, AValueWithoutAnErrorPrintsNoNan) {
  schema::ResultsDocument doc;
  doc.problems.push_back(suites::problem_descriptor(ProblemId::CM_p).record);
  for (const auto a : {Algorithm::LMP, Algorithm::PLM}) {
    auto r = row(ProblemId::CM_p, Quantity::c_over_a, Element::Q4, a, ContactKind::ss, {8, 4, 2});
    r.errors[2].reset();
    doc.rows.push_back(r);
  }
  const ResultsIndex index(doc);
  const std::string md = friction_section(index);
  EXPECT_NE(md.find("| 1.0200 | 1.0200 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("nan"), std::string::npos) << md;
}

TEST(FrictionAndConformalSections, AbsentFromTheStudySample) {
  const testing::Loaded data(testing::sample_json());
  EXPECT_EQ(friction_section(data.index), "");
  EXPECT_EQ(conformal_section(data.index), "");
}

}  // namespace
}  // namespace cs::reports
