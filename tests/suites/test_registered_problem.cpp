// A problem defined outside the battery takes its oracle, its descriptor and one registration
// line: it then runs through the engine, is graded, and is named in case ids and results.json
// like a built-in problem, with no edit anywhere else.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "oracles/patch_test.hpp"
#include "schema/results_file.hpp"
#include "suites/executor_factory.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/problems/problem_builders.hpp"
#include "suites/row_verdict.hpp"
#include "suites/runner.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

using schema::Quantity;

// The oracle: a slab pressed by a uniform pressure p onto a flat stiff indenter is in the
// uniform state sigma_z = -p (the study's Eq. 6), so -sigma_z/p = 1 at every surface node.
double uniform_pressure_exact(double p) {
  return -oracles::patch_test_plane_stress({p}, {0.0, 0.0}).sigma_z / p;
}

// The builder: the unit slab of the patch family (4 x 4 elements at C, see the descriptor),
// pressure p on its back face, the indenter held at its back face.
ProblemSetup build_uniform_patch(const CaseSpec& spec, const Parameters& params) {
  StudyMeshSpec mesh;
  mesh.problem = spec.problem;
  mesh.level = spec.mesh;
  mesh.element = to_solver(spec.element);
  mesh.a = 1.0;
  const solver::RigidProfile rigid = solver::RigidPlane{{0.0, 0.0}, {0.0, 1.0}};
  ProblemSetup setup = problems::start_setup(spec, params, mesh, rigid);
  setup.model.loads.add_pressure(study_sets::kBlockFarZ, setup.p);
  setup.model.fix(solver::NodeSelection::node_set(study_sets::kIndenterLoad), solver::Component::Z);
  const double exact = uniform_pressure_exact(setup.p);
  setup.exact_pressure_over_p = [exact](double x) { return x <= 1.0 ? exact : 0.0; };
  setup.quantities.push_back({Quantity::sigma_z_max, SamplePoint::MaxOnSurface,
                              StressComponent::SigmaZ, exact, std::nullopt});
  return setup;
}

// The descriptor: every fact, as the built-in problems' files give theirs.
ProblemDescriptor uniform_patch_descriptor() {
  return {{ProblemId{},  // register_problem sets the id
           "uniform-pressure patch (a registered problem)",
           "plane-strain uniform-pressure patch",
           /*axisymmetric=*/false,
           /*singular=*/false,
           "",
           "uniform state (Eq. 6)",
           {{Quantity::sigma_z_max, "−σ<sub>z</sub><sup>max</sup>/p", "-sigma_z^max/p", "", ""}}},
          problems::study_parameters({}),
          build_uniform_patch,
          schema::Situation::matched_patch,
          schema::LengthScale::contact_half_width_a,
          /*relative_cost=*/0.25,
          {MeshFamily::patch, 1.0, 4, 0},
          {"", ""}};
}

ProblemId uniform_patch() {
  static const ProblemId id = register_problem("U_p", uniform_patch_descriptor());  // the line
  return id;
}

CaseSpec uniform_case(MeshLevel mesh) {
  return {.problem = uniform_patch(),
          .mesh = mesh,
          .element = Element::Q4,
          .algorithm = Algorithm::LMP,
          .contact = ContactKind::ss};
}

// Requirement: the registered problem has an id of the registered range and is named like a
// built-in one: in case ids, by the parser, and in the catalogue's list of every problem.
TEST(RegisteredProblem, IsNamedLikeABuiltInOne) {
  const ProblemId id = uniform_patch();
  EXPECT_GE(static_cast<int>(id), schema::kFirstRegisteredProblem);
  EXPECT_EQ(to_string(id), "U_p");
  EXPECT_EQ(schema::parse<ProblemId>("U_p"), id);
  EXPECT_EQ(case_id(uniform_case(MeshLevel::C)), "U_p/C/Q4/LMP/ss");
  EXPECT_EQ(schema::parse_case_id("U_p/C/Q4/LMP/ss"), uniform_case(MeshLevel::C));
  EXPECT_EQ(problem_descriptor(id).record.id, id);
  EXPECT_EQ(all_problems().back(), id);
  EXPECT_EQ(problem_descriptor(id).record.situation, schema::Situation::matched_patch);
}

// Requirement: a name already taken, or one that would break a case id, is refused.
TEST(RegisteredProblem, RefusesATakenOrMalformedName) {
  uniform_patch();
  EXPECT_THROW(register_problem("U_p", uniform_patch_descriptor()), schema::SchemaError);
  EXPECT_THROW(register_problem("H_p", uniform_patch_descriptor()), schema::SchemaError);
  EXPECT_THROW(register_problem("U/p", uniform_patch_descriptor()), schema::SchemaError);
  EXPECT_THROW(problem_descriptor(static_cast<ProblemId>(255)), SuiteInputError);
}

// Requirement: its cases run through the normal runner and are graded against its oracle: the
// uniform state is reproduced to round-off on matched nodes (LMP ss, as P_p), so every mesh is
// graded e with an error below 1e-8 % (machine precision times the condition of a 4x4..16x16
// slab), and the C/M/F row is converging; its mesh comes from its layout (4 x 4 at C).
TEST(RegisteredProblem, RunsThroughTheRunnerAndIsGraded) {
  std::vector<CaseSpec> cases;
  for (MeshLevel m : schema::kStudyMeshes)
    cases.push_back(uniform_case(m));
  RunnerOptions options;
  options.jobs = 1;
  const auto results = run_cases(cases, executor_factory(), options);
  ASSERT_EQ(results.size(), 3U);
  for (const auto& r : results) {
    ASSERT_EQ(r.status, CaseStatus::converged) << case_id(r.spec) << ": " << r.reason;
    ASSERT_EQ(r.quantities.size(), 1U);
    const auto& q = r.quantities.front();
    EXPECT_EQ(q.exact, 1.0);
    EXPECT_LT(std::abs(q.error_percent), 1e-8) << case_id(r.spec);
    EXPECT_EQ(q.grade, schema::Grade::e);
  }
  EXPECT_DOUBLE_EQ(results.front().element_size_h, 0.25);  // 4 elements across a at C
  const auto rows = make_row_verdicts(results);
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_EQ(rows.front().grade, schema::Grade::e);
  EXPECT_EQ(rows.front().converging, std::optional<bool>(true));

  // Its record goes to results.json and reads back with its name and facts.
  schema::ResultsDocument doc;
  doc.problems = problem_records(results);
  doc.cases = results;
  doc.rows = rows;
  const auto back = schema::results_from_json(schema::to_json(doc), "test");
  ASSERT_EQ(back.problems.size(), 1U);
  EXPECT_EQ(back.problems.front().id, uniform_patch());
  EXPECT_EQ(back.problems.front().length_scale, schema::LengthScale::contact_half_width_a);
  EXPECT_EQ(back.cases.front().spec, results.front().spec);
}

}  // namespace
}  // namespace cs::suites
