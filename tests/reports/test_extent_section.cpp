// The domain-extent section: the error at the study's extent split into the block's part and
// the discretization's (from Richardson limits per extent), the half-space extent found by the
// 0.05 % rule, and the "S, half-space" grades beside the study geometry's. Checked on a small
// document whose numbers are chosen so each figure is known.

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

TEST(ExtentSection, SplitsTheErrorAndFindsTheHalfSpaceExtent) {
  const schema::ResultsDocument doc = extent_document();
  const ResultsIndex index(doc);
  const std::string md = extent_section(index);
  ASSERT_FALSE(md.empty());
  EXPECT_EQ(md.rfind("## The block's extent", 0), 0u) << md;
  // LMP Q8: F error at extent 1 is -1.25 %; block (9.90 - 9.995)/10 = -0.95 %; discretization
  // (9.875 - 9.90)/10 = -0.25 %; at extent 8 the limit is -0.05 % from exact.
  EXPECT_NE(md.find(std::string(schema::label(schema::Quantity::sigma_c)) +
                    " Q8 LMP ss: F-mesh error at the study's extent −1.25 %; of it the block "
                    "accounts for −0.95 %"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("the discretization for −0.25 %"), std::string::npos) << md;
  EXPECT_NE(md.find("at extent 8 the limit is −0.05 % from the exact value"), std::string::npos)
      << md;
  // 9.957782 / 9.9538 - 1 = 0.040 % < 0.05 %: extent 4.
  EXPECT_NE(md.find("From extent 4 on, no fine-mesh value changes by 0.05 % or more (0.040 %"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("half-space\": each option graded at extent 8"), std::string::npos) << md;
  // The series table: one cell per column, the quantity first.
  EXPECT_NE(md.find("| " + std::string(schema::label(schema::Quantity::sigma_c)) +
                    " | Q8 | LMP ss | 2 | 9.8500 (−1.50 %) | 9.9000 (−1.00 %) | 9.9240 (−0.76 %) | "
                    "9.9600 (−0.40 %) | −0.36 % | +0.50 % |\n"),
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
  EXPECT_NE(md.find("\"S(1), half-space gap\": at extent 8"), std::string::npos) << md;
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
  const std::string md = extent_section(index);
  EXPECT_NE(md.find("half-space\": each option graded at extent 8 (the widest extent run with the "
                    "most options"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| Q8 | AL ss | −11.0 % | u, c | −0.50 % | e, c |"), std::string::npos) << md;
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
  const std::string md = extent_section(index);
  EXPECT_NE(md.find("Between the two widest extents run, 1 and 2, a fine-mesh value still changes "
                    "by 0.496 %"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("half-space\": each option"), std::string::npos) << md;
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
  const std::string md = extent_section(index);
  EXPECT_NE(md.find("From extent 4 on, no fine-mesh value changes by 0.05 % or more (0.010 %"),
            std::string::npos)
      << md;
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
