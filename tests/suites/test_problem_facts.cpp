// The facts every built-in descriptor declares agree with each other and with what the other
// parts of the descriptor say: a wrong situation or layout would put a problem under the wrong
// advice or mesh it as another problem.

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "suites/problem_catalog.hpp"
#include "suites/study_meshes.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

using schema::Situation;

// Requirement: a problem is singular exactly when its situation is the sharp punch, frictional
// exactly when its situation is friction, and its record carries the descriptor's situation and
// length scale (what results.json records).
TEST(ProblemFacts, SituationAgreesWithTheRecord) {
  for (ProblemId id : values<ProblemId>()) {
    const ProblemDescriptor& d = problem_descriptor(id);
    EXPECT_EQ(d.record.singular, d.situation == Situation::flat_punch) << to_string(id);
    EXPECT_EQ(is_frictional(id), d.situation == Situation::frictional) << to_string(id);
    EXPECT_EQ(d.record.situation, d.situation) << to_string(id);
    EXPECT_EQ(d.record.length_scale, d.length_scale) << to_string(id);
    EXPECT_EQ(d.record.id, id);
  }
}

// Requirement: the study's problems, and only they, have a Table 1 count; the Steuermann
// problems are the ones over the punch half-width b, meshed by the Steuermann family and the
// dearest to run; every cost is positive.
TEST(ProblemFacts, LayoutAndCostAgreeWithTheStudy) {
  const auto study = study_problems();
  for (ProblemId id : values<ProblemId>()) {
    const ProblemDescriptor& d = problem_descriptor(id);
    const bool in_study = std::find(study.begin(), study.end(), id) != study.end();
    EXPECT_EQ(d.mesh_layout.table1_elements > 0, in_study) << to_string(id);
    EXPECT_EQ(table1_elements(id, MeshLevel::M), 4 * d.mesh_layout.table1_elements);
    const bool steuermann = d.mesh_layout.family == MeshFamily::steuermann;
    EXPECT_EQ(steuermann, d.situation == Situation::rounded_punch) << to_string(id);
    EXPECT_EQ(steuermann, d.length_scale == schema::LengthScale::punch_half_width_b);
    EXPECT_GT(d.relative_cost, 0.0) << to_string(id);
    EXPECT_EQ(d.relative_cost > 1.0, steuermann) << to_string(id);
  }
}

// Requirement: a problem that builds its own mesh is refused by the study-mesh generator with
// a message naming it, rather than meshed as another problem.
TEST(ProblemFacts, OwnLayoutIsNotMeshedAsAnotherProblem) {
  StudyMeshSpec spec;
  spec.problem = ProblemId::IF_p;
  try {
    build_study_mesh(spec);
    FAIL() << "IF_p was meshed by build_study_mesh";
  } catch (const SuiteInputError& e) {
    EXPECT_NE(std::string(e.what()).find("IF_p"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cs::suites
