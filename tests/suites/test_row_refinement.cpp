// A row with the fourth mesh VF: the study's C-M-F verdicts stay as they were (graded on F),
// and the M-F-VF verdicts appear beside them (schema::RefinementVerdict), in results.json too.

#include <cmath>

#include <gtest/gtest.h>

#include "schema/results_file.hpp"
#include "suites/row_verdict.hpp"
#include "support/tolerance.hpp"

namespace cs::suites {
namespace {

using cs::testing::Near;

CaseResult hertz_case_of_error(MeshLevel mesh, double error_percent) {
  const double exact = 4.0 / M_PI;
  CaseResult r;
  r.spec = CaseSpec{.problem = ProblemId::H_p,
                    .mesh = mesh,
                    .element = Element::Q4,
                    .algorithm = Algorithm::MPC,
                    .contact = ContactKind::ss,
                    .overrides = {}};
  r.status = CaseStatus::converged;
  QuantityResult q;
  q.quantity = Quantity::sigma_c;
  q.exact = exact;
  q.value = exact * (1.0 + error_percent / 100.0);
  q.error_percent = error_percent;
  r.quantities.push_back(q);
  return r;
}

// Requirement: errors 4, 6, 3, 1.5 % on C, M, F, VF: not converging over C-M-F (it grows from
// C to M), converging over M-F-VF with the order log2(3/1.5) = 1 from F to VF and an M-F-VF
// estimate of order 1; the grade is still F's (g), and results.json keeps all of it.
TEST(RowRefinement, FourMeshesGiveBothVerdictsSideBySide) {
  const std::vector<CaseResult> cases{
      hertz_case_of_error(MeshLevel::C, 4.0), hertz_case_of_error(MeshLevel::M, 6.0),
      hertz_case_of_error(MeshLevel::F, 3.0), hertz_case_of_error(MeshLevel::VF, 1.5)};
  const auto rows = make_row_verdicts(cases);
  ASSERT_EQ(rows.size(), 1u);
  const RowVerdict& row = rows[0];
  ASSERT_TRUE(row.converging.has_value());
  EXPECT_FALSE(*row.converging);
  EXPECT_EQ(row.graded_mesh, MeshLevel::F);
  EXPECT_EQ(row.grade, schema::Grade::g);
  ASSERT_TRUE(row.refinement.has_value());
  const schema::RefinementVerdict& vf = *row.refinement;
  EXPECT_TRUE(Near(*vf.error, 1.5, {1e-12, 0}));
  EXPECT_TRUE(Near(*vf.pair_order, 1.0, {1e-12, 0}));  // machine precision
  EXPECT_TRUE(*vf.converging);
  ASSERT_TRUE(vf.estimate && vf.estimate->asymptotic);
  EXPECT_TRUE(Near(*vf.estimate->observed_order, 1.0, {1e-9, 0}));  // values carry round-off
  EXPECT_TRUE(Near(*vf.estimate->richardson, 4.0 / M_PI, {1e-9, 0}));

  const nlohmann::json j = schema::to_json(row);
  EXPECT_EQ(j["refinement"]["converging_M_F_VF"], true);
  EXPECT_EQ(j["values"].size(), 3u);  // C, M, F as before; VF in "refinement"
  const RowVerdict back = schema::row_from_json(j, "test");
  ASSERT_TRUE(back.refinement.has_value());
  EXPECT_EQ(back.refinement->converging, vf.converging);
  EXPECT_EQ(back.refinement->error, vf.error);
  EXPECT_EQ(back.refinement->estimate->observed_order, vf.estimate->observed_order);
}

// Requirement: rows without VF have no refinement record (the study's three meshes only).
TEST(RowRefinement, ThreeMeshesHaveNoRefinementRecord) {
  const auto rows = make_row_verdicts({hertz_case_of_error(MeshLevel::C, 4.0),
                                       hertz_case_of_error(MeshLevel::M, 2.0),
                                       hertz_case_of_error(MeshLevel::F, 1.0)});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_FALSE(rows[0].refinement.has_value());
  EXPECT_FALSE(schema::to_json(rows[0]).contains("refinement"));
}

}  // namespace
}  // namespace cs::suites
