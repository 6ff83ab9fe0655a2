// The linear static solve: CHOLMOD supernodal (METIS) and SimplicialLDLT agree, one
// factorization serves many right-hand sides and value changes reuse the symbolic analysis,
// singular and indefinite systems are reported as such (naming the unrestrained body), and
// reactions balance the loads.

#include <string>

#include <gtest/gtest.h>

#include "solver/linear_solver.hpp"
#include "solver/linear_static.hpp"
#include "solver/mesh/mesh_merge.hpp"
#include "solver/rigid_body_modes.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

namespace cs::solver {
namespace {

using cs::testing::Near;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// A 2 x 1 cantilever of Q8 elements, clamped on the left, loaded on the right and the top.
Model cantilever(int nx = 8, int nz = 4, ElementType type = ElementType::Q8) {
  Model model;
  model.mesh = test::block(type, {0, 0}, {2, 1}, nx, nz, "beam");
  model.materials = {{1000.0, 0.3}};
  model.fix(NodeSelection::node_set("left"), Component::X);
  model.fix(NodeSelection::node_set("left"), Component::Z);
  model.loads.add_traction("right", constant_field(Eigen::Vector2d(0.5, -2.0)));
  model.loads.add_pressure("top", 1.5);
  return model;
}

// Requirement: CHOLMOD supernodal (with METIS, as selected and reported by CHOLMOD) and
// Eigen's SimplicialLDLT give the same displacements.
TEST(FeLinearSolver, CholmodAndSimplicialLdltAgree) {
  const Model model = cantilever(16, 8);
  LinearStaticOptions cholmod;
  cholmod.linear_solver.ordering = FillReducingOrdering::Metis;
  LinearStaticOptions ldlt;
  ldlt.linear_solver.kind = LinearSolverKind::EigenSimplicialLDLT;
  const LinearStaticResult a = solve_linear_static(model, cholmod);
  const LinearStaticResult b = solve_linear_static(model, ldlt);
  ASSERT_TRUE(a.ok()) << a.outcome.reason;
  ASSERT_TRUE(b.ok()) << b.outcome.reason;
  EXPECT_EQ(a.factorization.ordering, "METIS (node graph)");
  EXPECT_TRUE(a.factorization.supernodal);
  EXPECT_FALSE(b.factorization.supernodal);
  const double scale = test::max_abs(a.displacement);
  EXPECT_GT(scale, 0.0);
  // two backward-stable factorizations of a matrix with condition ~1e4: ~1e-12 relative
  EXPECT_LT((a.displacement - b.displacement).cwiseAbs().maxCoeff(), 1e-10 * scale);
}

// Requirement: the fill-reducing ordering is selectable and the one CHOLMOD used is reported
// (the choice between AMD and METIS at large sizes is shown by bench/fe_core.cpp).
TEST(FeLinearSolver, OrderingIsSelectableAndReported) {
  const Model model = cantilever(12, 6);
  const std::pair<FillReducingOrdering, std::string> cases[] = {
      {FillReducingOrdering::Automatic, "AMD"},  // small system: AMD's fill is low
      {FillReducingOrdering::Metis, "METIS (node graph)"},
      {FillReducingOrdering::CholmodDefault, "AMD"},
      {FillReducingOrdering::Nesdis, "NESDIS"},
      {FillReducingOrdering::Amd, "AMD"}};
  for (const auto& [ordering, expected] : cases) {
    LinearStaticOptions options;
    options.linear_solver.ordering = ordering;
    const LinearStaticResult r = solve_linear_static(model, options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.factorization.ordering, expected);
    EXPECT_GT(r.factorization.nnz_factor, r.factorization.nnz_matrix);
  }
  LinearStaticOptions best;
  best.linear_solver.ordering = FillReducingOrdering::Best;
  const LinearStaticResult r = solve_linear_static(model, best);
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r.factorization.ordering.empty());
}

// Requirement: many load cases are solved with one analysis and one factorization (a matrix
// right-hand side), with the same results as separate solves.
TEST(FeLinearSolver, OneFactorizationForManyRightHandSides) {
  const Model model = cantilever();
  std::vector<LoadCase> cases(5);
  for (int i = 0; i < 5; ++i) {
    cases[i].add_traction("right", constant_field(Eigen::Vector2d(0.1 * i, 1.0 - i)));
    cases[i].add_point_force(NodeSelection::node_set("top"), Eigen::Vector2d(0.0, -0.01 * i));
  }
  LinearStaticAnalysis analysis(model);
  const std::vector<LinearStaticResult> together = analysis.solve(cases);
  ASSERT_EQ(together.size(), 5u);
  EXPECT_EQ(analysis.linear_solver().info().analyze_count, 1);
  EXPECT_EQ(analysis.linear_solver().info().factorize_count, 1);
  for (int i = 0; i < 5; ++i) {
    Model single = model;
    single.loads = cases[i];
    const LinearStaticResult alone = solve_linear_static(single);
    ASSERT_TRUE(together[i].ok());
    const double scale = test::max_abs(alone.displacement);
    // same factor; multi-column (BLAS-3) vs single-column solves differ by round-off only
    EXPECT_LT((together[i].displacement - alone.displacement).cwiseAbs().maxCoeff(),
              1e-12 * scale + 1e-300);
  }
}

// Requirement: changed values with the same pattern (here E doubled) reuse the symbolic
// analysis: one analysis, two factorizations, displacements halved.
TEST(FeLinearSolver, ValueChangesReuseTheSymbolicAnalysis) {
  Model model = cantilever();
  LinearStaticAnalysis analysis(model);
  const LinearStaticResult first = analysis.solve();
  ASSERT_TRUE(first.ok());
  model.materials[0].youngs_modulus_E *= 2.0;
  analysis.assemble();
  const LinearStaticResult second = analysis.solve();
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(analysis.linear_solver().info().analyze_count, 1);
  EXPECT_EQ(analysis.linear_solver().info().factorize_count, 2);
  const double scale = test::max_abs(first.displacement);
  EXPECT_LT((second.displacement - 0.5 * first.displacement).cwiseAbs().maxCoeff(),
            1e-12 * scale);  // round-off
  EXPECT_GE(second.timings.factorize_s, 0.0);
  EXPECT_EQ(second.timings.analyze_s, 0.0);
}

// Requirement: an added term P (e.g. a contact penalty) is factorized with K_ff in the reduced
// space; solve_reduced then solves (K_ff + P) u = f.
TEST(FeLinearSolver, FactorizeWithAnExtraTermInTheReducedSpace) {
  const Model model = cantilever();
  LinearStaticAnalysis analysis(model);
  analysis.assemble();
  const int n = analysis.dof_map().n_free();
  Eigen::SparseMatrix<double> P(n, n);
  const int corner = model.mesh.node_sets.at("right").back();  // top right corner
  const int eq = analysis.dof_map().equation(corner, Component::Z);
  ASSERT_GE(eq, 0);
  P.insert(eq, eq) = 1e4;
  P.makeCompressed();
  ASSERT_TRUE(analysis.factorize_with(P).ok());
  const Eigen::VectorXd f = analysis.reduced_load(model.loads);
  const Eigen::VectorXd u = analysis.solve_reduced(f);
  const Eigen::SparseMatrix<double> A = analysis.stiffness().K_ff + P;
  const Eigen::VectorXd residual = A.selfadjointView<Eigen::Lower>() * u - f;
  EXPECT_LT(residual.norm(), 1e-10 * f.norm());  // backward-stable solve
  // the same term again: pattern unchanged, no new analysis
  ASSERT_TRUE(analysis.factorize_with(P).ok());
  EXPECT_EQ(analysis.linear_solver().info().analyze_count, 1);
  // solve() then factorizes K_ff alone again: the plain elastic solution
  const LinearStaticResult plain = analysis.solve();
  const LinearStaticResult reference = solve_linear_static(model);
  ASSERT_TRUE(plain.ok());
  EXPECT_LT((plain.displacement - reference.displacement).cwiseAbs().maxCoeff(),
            1e-12 * test::max_abs(reference.displacement));  // round-off
}

// Requirement: reactions are K u - f at prescribed DOFs and balance the applied loads.
TEST(FeLinearSolver, ReactionsBalanceTheLoads) {
  for (AnalysisType analysis : {AnalysisType::PlaneStrain, AnalysisType::Axisymmetric}) {
    Model model = cantilever();
    model.analysis = analysis;
    if (analysis == AnalysisType::Axisymmetric) {
      for (auto& x : model.mesh.nodes)
        x.x() += 1.0;  // r in [1, 3]
    }
    const LinearStaticResult r = solve_linear_static(model);
    ASSERT_TRUE(r.ok()) << r.outcome.reason;
    LinearStaticAnalysis a(model);
    const Eigen::VectorXd f = a.external_load(model.loads);
    for (int c = 0; c < 2; ++c) {
      double applied = 0.0, reaction = 0.0;
      for (int node = 0; node < model.mesh.n_nodes(); ++node) {
        applied += f[2 * node + c];
        reaction += r.reaction[2 * node + c];
      }
      if (analysis == AnalysisType::PlaneStrain || c == 1) {
        // global equilibrium (axisymmetric: axially only) to round-off
        EXPECT_TRUE(Near(reaction, -applied, {1e-9, 1e-12}));
      }
    }
    for (int node = 0; node < model.mesh.n_nodes(); ++node) {
      if (a.dof_map().is_free(2 * node)) {
        EXPECT_EQ(r.reaction[2 * node], 0.0);
      }
    }
  }
}

// Requirement: a model without constraints is reported singular, naming the body; no NaN.
TEST(FeSingularModel, NoConstraintsNamesTheBody) {
  Model model = cantilever();
  model.prescribed.clear();
  const LinearStaticResult r = solve_linear_static(model);
  EXPECT_EQ(r.status(), SolveStatus::Singular);
  EXPECT_TRUE(contains(r.outcome.reason, "body 'beam'")) << r.outcome.reason;
  EXPECT_TRUE(contains(r.outcome.reason, "translation in x")) << r.outcome.reason;
  EXPECT_EQ(r.displacement.size(), 0);
}

// Requirement: of two separate bodies, the one left unconstrained is named (and only it).
TEST(FeSingularModel, UnconstrainedSecondBodyIsNamed) {
  Model model;
  Mesh block = test::block(ElementType::Q4, {0, 0}, {1, 1}, 4, 4, "block");
  Mesh indenter = test::block(ElementType::Q4, {0.2, 1.0}, {0.5, 0.5}, 2, 2, "indenter");
  model.mesh = merge_bodies({block, indenter});
  model.materials = {{1.0, 0.3}, {1e6, 0.3}};
  model.fix(NodeSelection::node_set("block.bottom"), Component::Z);
  model.fix(NodeSelection::node_set("block.left"), Component::X);
  model.fix(NodeSelection::node_set("indenter.left"), Component::X);  // z is still free
  const LinearStaticResult r = solve_linear_static(model);
  EXPECT_EQ(r.status(), SolveStatus::Singular);
  EXPECT_TRUE(contains(r.outcome.reason, "body 'indenter'")) << r.outcome.reason;
  EXPECT_TRUE(contains(r.outcome.reason, "translation in z")) << r.outcome.reason;
  EXPECT_FALSE(contains(r.outcome.reason, "'block'")) << r.outcome.reason;
  // the contact pair couples the bodies: then the group is held
  LinearStaticAnalysis analysis(model);
  EXPECT_TRUE(find_unrestrained_bodies(model, analysis.dof_map(), {{0, 1}}).empty());
}

// Requirement: a pin alone leaves the rotation free; a roller alone a translation; in
// axisymmetry only the axial translation is a rigid mode.
TEST(FeSingularModel, NamesTheFreeMode) {
  Model pinned = cantilever();
  pinned.prescribed.clear();
  pinned.fix(NodeSelection::list({0}, "pin"), Component::X);
  pinned.fix(NodeSelection::list({0}, "pin"), Component::Z);
  LinearStaticResult r = solve_linear_static(pinned);
  EXPECT_EQ(r.status(), SolveStatus::Singular);
  EXPECT_TRUE(contains(r.outcome.reason, "rotation")) << r.outcome.reason;

  Model roller = cantilever();
  roller.prescribed.clear();
  roller.fix(NodeSelection::node_set("bottom"), Component::Z);
  r = solve_linear_static(roller);
  EXPECT_EQ(r.status(), SolveStatus::Singular);
  EXPECT_TRUE(contains(r.outcome.reason, "translation in x")) << r.outcome.reason;
  EXPECT_FALSE(contains(r.outcome.reason, "rotation")) << r.outcome.reason;

  Model axi = cantilever();
  axi.analysis = AnalysisType::Axisymmetric;
  axi.prescribed.clear();
  axi.fix(NodeSelection::node_set("left"), Component::R);  // the axis; z free
  r = solve_linear_static(axi);
  EXPECT_EQ(r.status(), SolveStatus::Singular);
  EXPECT_TRUE(contains(r.outcome.reason, "translation in z")) << r.outcome.reason;
  axi.fix(NodeSelection::node_set("bottom"), Component::Z);
  EXPECT_TRUE(solve_linear_static(axi).ok());
}

// Requirement: without the structural check the factorization itself reports the singular
// matrix (non-positive or vanishing pivot), as a status with a reason and no displacement.
TEST(FeSingularModel, FactorizationReportsSingularMatrixWithoutTheCheck) {
  Model model = cantilever();
  model.prescribed.clear();
  for (LinearSolverKind kind :
       {LinearSolverKind::CholmodSupernodal, LinearSolverKind::EigenSimplicialLDLT}) {
    LinearStaticOptions options;
    options.check_rigid_body_modes = false;
    options.linear_solver.kind = kind;
    const LinearStaticResult r = solve_linear_static(model, options);
    EXPECT_TRUE(r.status() == SolveStatus::Singular ||
                r.status() == SolveStatus::NotPositiveDefinite)
        << to_string(r.status());
    EXPECT_FALSE(r.outcome.reason.empty());
    EXPECT_EQ(r.displacement.size(), 0);
  }
}

// Requirement: an indefinite matrix is NotPositiveDefinite with the failed equation.
TEST(FeLinearSolver, IndefiniteMatrixIsReported) {
  Eigen::SparseMatrix<double> A(3, 3);
  A.insert(0, 0) = 2.0;
  A.insert(1, 1) = -1.0;
  A.insert(2, 2) = 3.0;
  A.insert(2, 0) = 0.5;
  A.makeCompressed();
  for (LinearSolverKind kind :
       {LinearSolverKind::CholmodSupernodal, LinearSolverKind::EigenSimplicialLDLT}) {
    LinearSolver solver({kind});
    const SolveOutcome out = solver.compute(A);
    EXPECT_EQ(out.status, SolveStatus::NotPositiveDefinite) << to_string(kind);
    EXPECT_EQ(out.failed_equation, 1) << to_string(kind);
    EXPECT_FALSE(solver.is_factorized());
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(3);
    EXPECT_THROW(solver.solve(b), std::logic_error);
  }
}

}  // namespace
}  // namespace cs::solver
