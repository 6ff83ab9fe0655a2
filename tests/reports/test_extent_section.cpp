// The domain-extent section's facts: the error at the study's extent split into the block's
// part and the discretization's (from Richardson limits per extent), the half-space extent found
// by the 0.05 % rule, and the "S, half-space" grades beside the study geometry's. Checked on a
// small document whose numbers are chosen so each figure is known.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "reports/findings/extent_section.hpp"
#include "schema/results_file.hpp"

namespace cs::reports {
namespace {

constexpr double kExact = 10.0;

schema::CaseSpec spec_at(schema::Algorithm algorithm, double extent, bool block_normal = false) {
  schema::CaseSpec s;
  s.problem = schema::ProblemId::S_1;
  s.element = schema::Element::Q8;
  s.algorithm = algorithm;
  s.contact = schema::ContactKind::ss;
  if (extent != 1.0)
    s.overrides["extent"] = extent;
  if (block_normal)
    s.overrides["half_space_gap"] = 1.0;
  return s;
}

/// A row with values C, M, F, graded on F, converging, with a Richardson limit.
void add_row(schema::ResultsDocument& doc, schema::Algorithm algorithm, double extent,
             std::array<double, 3> values, double limit, bool block_normal = false) {
  schema::RowVerdict row;
  row.spec = spec_at(algorithm, extent, block_normal);
  row.quantity = schema::Quantity::sigma_c;
  row.id = schema::case_key(row.spec) + "/sigma_c";
  for (std::size_t m = 0; m < 3; ++m) {
    row.values[m] = values[m];
    row.errors[m] = 100.0 * (values[m] / kExact - 1.0);
    schema::CaseResult c;
    c.spec = row.spec;
    c.spec.mesh = static_cast<schema::MeshLevel>(m);
    c.status = schema::CaseStatus::converged;
    schema::QuantityResult q;
    q.quantity = schema::Quantity::sigma_c;
    q.value = values[m];
    q.exact = kExact;
    q.error_percent = *row.errors[m];
    q.grade = grading::grade_of_error(q.error_percent);
    c.quantities.push_back(q);
    doc.cases.push_back(c);
  }
  row.grade = grading::grade_of_error(*row.errors[2]);
  row.graded_mesh = schema::MeshLevel::F;
  row.converging = true;
  row.estimate = schema::ErrorEstimate{true, 2.0, limit, 0.1, ""};
  doc.rows.push_back(row);
}

schema::ResultsDocument extent_document() {
  schema::ResultsDocument doc;
  schema::ProblemRecord p;
  p.id = schema::ProblemId::S_1;
  p.description = "Steuermann";
  p.exact_source = "Eq. 31";
  p.quantities = {{schema::Quantity::sigma_c, "peak", "peak", "10", "main"}};
  doc.problems.push_back(p);
  using A = schema::Algorithm;
  // LMP: limits 9.90, 9.96, 9.99, 9.995: the block costs 0.95 % at extent 1; the F values
  // change by 0.5 %, 0.3 %, then 0.04 % (under 0.05 %) from extent 4 to 8.
  add_row(doc, A::LMP, 1.0, {9.80, 9.85, 9.875}, 9.90);
  add_row(doc, A::LMP, 2.0, {9.85, 9.90, 9.924}, 9.96);
  add_row(doc, A::LMP, 4.0, {9.88, 9.93, 9.9538}, 9.99);
  add_row(doc, A::LMP, 8.0, {9.88, 9.93, 9.957782}, 9.995);
  // AL at the study's extent and the widest: u -> e.
  add_row(doc, A::AL, 1.0, {8.0, 8.5, 8.9}, 9.3);
  add_row(doc, A::AL, 8.0, {9.5, 9.8, 9.95}, 10.05);
  return doc;
}

// Requirement: the F error at the study's extent splits into the block's part and the
// discretization's; the half-space extent is the first from which no F value changes by 0.05 %;
// the half-space grades are given at the widest extent, beside the study geometry's.
TEST(ExtentSection, SplitsTheErrorAndFindsTheHalfSpaceExtent) {
  const schema::ResultsDocument doc = extent_document();
  const ResultsIndex index(doc);
  const std::vector<ExtentFacts> facts = extent_facts(index);
  ASSERT_EQ(facts.size(), 1u);
  const ExtentFacts& f = facts[0];
  // LMP Q8: F error at extent 1 is -1.25 %; block (9.90 - 9.995)/10 = -0.95 %; discretization
  // (9.875 - 9.90)/10 = -0.25 %; at extent 8 the limit is -0.05 % from exact. Exact arithmetic
  // on 4-digit data: 1e-9 points.
  ASSERT_EQ(f.splits.size(), 2u);
  EXPECT_NEAR(f.splits[0].f_error, -1.25, 1e-9);
  EXPECT_NEAR(f.splits[0].block, -0.95, 1e-9);
  EXPECT_NEAR(f.splits[0].discretization, -0.25, 1e-9);
  EXPECT_NEAR(f.splits[0].remaining, -0.05, 1e-9);
  EXPECT_EQ(f.splits[0].widest, 8.0);
  // 9.957782 / 9.9538 - 1 = 0.040 % < 0.05 %: extent 4.
  ASSERT_TRUE(f.half_space && f.change_after_half_space);
  EXPECT_EQ(*f.half_space, 4.0);
  EXPECT_NEAR(*f.change_after_half_space, 0.040, 5e-4);
  EXPECT_EQ(f.grades_extent, 8.0);
  const std::string md = extent_section(index);
  EXPECT_EQ(md.rfind("## The block's extent", 0), 0u) << md;
  // The series table: one cell per column, the quantity first.
  EXPECT_NE(md.find("| " + std::string(schema::label(schema::Quantity::sigma_c)) +
                    " | Q8 | LMP ss | 2 | 9.8500 (−1.50 %) | 9.9000 (−1.00 %) | 9.9240 (−0.76 %) | "
                    "9.9600 (−0.40 %) | −0.36 % | +0.50 % (from 1) |\n"),
            std::string::npos)
      << md;
  // The half-space statement says how many series it rests on: LMP alone runs at 4 and 8.
  EXPECT_EQ(f.half_space_series, 1);
  EXPECT_EQ(f.n_series, 2);
  EXPECT_NE(md.find("(0.040 % at most, over the 1 of 2 series run at two or more extents from "
                    "there on)"),
            std::string::npos)
      << md;
  // AL: u at the study's extent (-11 %), e at the widest (-0.5 %).
  EXPECT_NE(md.find("| Q8 | AL ss | −11.0 % | u, c | −0.50 % | e, c |"), std::string::npos) << md;
}

// Requirement: rows with the half-space gap (extent and half_space_gap=1) are graded beside the
// same option's target-normal rows at that extent, against the same exact value; an option run
// only one way has no line.
TEST(ExtentSection, GradesTheHalfSpaceGapBesideTheTargetNormal) {
  schema::ResultsDocument doc = extent_document();
  // LMP at extent 8 with the block's normal: +0.286, -0.025, -0.0015 % (e, c).
  add_row(doc, schema::Algorithm::LMP, 8.0, {10.0286, 9.9975, 9.99985}, 10.0, true);
  const ResultsIndex index(doc);
  const std::string md = extent_section(index);
  EXPECT_EQ(extent_facts(index)[0].gap_extent, 8.0);
  // target's normal at extent 8: 9.88, 9.93, 9.957782 -> -1.20, -0.70, -0.42 % (g, c).
  EXPECT_NE(md.find("| Q8 | LMP ss | −1.20 %, −0.70 %, −0.42 % | e, c | +0.29 %, −0.02 %, −1.5e-03 "
                    "% | e, c |"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("| Q8 | AL ss | −5.00 %"), std::string::npos) << md;  // AL: no such row
}

// Requirement: one option run further out (LMP at 16) does not move the half-space grades off the
// widest extent every option was run at (8), so no option's grade is left out.
TEST(ExtentSection, GradesAtTheWidestExtentOfMostOptions) {
  schema::ResultsDocument doc = extent_document();
  add_row(doc, schema::Algorithm::LMP, 16.0, {9.88, 9.93, 9.9580}, 9.996);
  const ResultsIndex index(doc);
  EXPECT_EQ(extent_facts(index)[0].grades_extent, 8.0);
  const std::string md = extent_section(index);
  EXPECT_NE(md.find("| Q8 | AL ss | −11.0 % | u, c | −0.50 % | e, c |"), std::string::npos) << md;
}

// Requirement: a grade whose F case fails an interface check is marked ✗ here as in Tables 2′
// (not evidence), and the legend says what the mark means.
TEST(ExtentSection, MarksGradesThatAreNotEvidence) {
  schema::ResultsDocument doc = extent_document();
  for (auto& c : doc.cases) {
    if (c.spec.algorithm == schema::Algorithm::AL && c.spec.overrides.contains("extent") &&
        c.spec.mesh == schema::MeshLevel::F)
      c.interface.emplace().force_balance = 0.2;  // the contact carries 20 % too much load
  }
  const ResultsIndex index(doc);
  const std::string md = extent_section(index);
  EXPECT_NE(md.find("| Q8 | AL ss | −11.0 % | u, c | −0.50 % | e, c ✗ |"), std::string::npos) << md;
  EXPECT_NE(md.find("✗: the F case fails an interface check"), std::string::npos) << md;
}

TEST(ExtentSection, SaysSoWhenNoExtentIsWideEnough) {
  schema::ResultsDocument doc;
  schema::ProblemRecord p;
  p.id = schema::ProblemId::S_1;
  p.quantities = {{schema::Quantity::sigma_c, "peak", "peak", "10", "main"}};
  doc.problems.push_back(p);
  add_row(doc, schema::Algorithm::LMP, 1.0, {9.8, 9.85, 9.875}, 9.9);
  add_row(doc, schema::Algorithm::LMP, 2.0, {9.85, 9.9, 9.924}, 9.96);
  const ResultsIndex index(doc);
  const ExtentFacts f = extent_facts(index)[0];
  EXPECT_FALSE(f.half_space || f.grades_extent);
  ASSERT_TRUE(f.last_change);
  EXPECT_EQ(f.second_widest, 1.0);
  EXPECT_EQ(f.widest, 2.0);
  EXPECT_NEAR(*f.last_change, 0.496, 5e-4);  // 9.924 / 9.875 - 1
}

TEST(ExtentSection, AHalfSpaceExtentHoldsForEveryLaterExtent) {
  // F values 9.9500, 9.9520 (+0.02 %), 9.9800 (+0.28 %), 9.9810 (+0.01 %): a small first step
  // does not make extent 1 a half-space; only from extent 4 on do all steps stay under 0.05 %.
  schema::ResultsDocument doc;
  schema::ProblemRecord p;
  p.id = schema::ProblemId::S_1;
  p.quantities = {{schema::Quantity::sigma_c, "peak", "peak", "10", "main"}};
  doc.problems.push_back(p);
  add_row(doc, schema::Algorithm::LMP, 1.0, {9.90, 9.94, 9.9500}, 9.96);
  add_row(doc, schema::Algorithm::LMP, 2.0, {9.90, 9.94, 9.9520}, 9.96);
  add_row(doc, schema::Algorithm::LMP, 4.0, {9.93, 9.97, 9.9800}, 9.99);
  add_row(doc, schema::Algorithm::LMP, 8.0, {9.93, 9.97, 9.9810}, 9.99);
  const ResultsIndex index(doc);
  const ExtentFacts f = extent_facts(index)[0];
  EXPECT_EQ(f.half_space, 4.0);
  EXPECT_NEAR(f.change_after_half_space.value_or(1.0), 0.010, 5e-4);
}

TEST(ExtentSection, EmptyWithoutExtentRows) {
  schema::ResultsDocument doc;
  const ResultsIndex index(doc);
  EXPECT_TRUE(extent_section(index).empty());
  EXPECT_TRUE(in_extent_study(spec_at(schema::Algorithm::LMP, 2.0)));
  EXPECT_FALSE(in_extent_study(spec_at(schema::Algorithm::LMP, 1.0)));
}

}  // namespace
}  // namespace cs::reports
