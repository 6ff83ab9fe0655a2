// The error estimator (grading/richardson.hpp) on real finite-element sequences whose exact
// answer and order are known: Lame's thick cylinder under internal pressure (the bore's radial
// displacement, Q4 nodal values converge at O(h^2)), and the suite's Hertz problem against its
// oracle (4/pi). The observed order, the Richardson limit and the GCI must tell the truth about
// the fine mesh's error.

#include <cmath>

#include <gtest/gtest.h>

#include "grading/richardson.hpp"
#include "solver/linear_static.hpp"
#include "solver/test_fe_support.hpp"
#include "suites/problem_executor.hpp"
#include "support/tolerance.hpp"

namespace cs::suites {
namespace {

// Lame (Timoshenko & Goodier, sec. 28): inner radius a = 1, outer b = 2, p = 1, E = 1000,
// nu = 0.3; u_r(a) = (1 + nu)/E ((1 - 2 nu) A a + B / a), A = p a^2/(b^2 - a^2), B = A b^2.
constexpr double kInner = 1.0, kOuter = 2.0, kE = 1000.0, kNu = 0.3;
constexpr double kA = kInner * kInner / (kOuter * kOuter - kInner * kInner);
constexpr double kExactBore =
    (1 + kNu) / kE * ((1 - 2 * kNu) * kA * kInner + kA * kOuter * kOuter / kInner);

/// u_r at the bore of the axisymmetric slice [a, b] x [0, 0.25], n x 2 Q4 elements.
double bore_displacement(int n) {
  using namespace solver;
  Model model;
  model.analysis = AnalysisType::Axisymmetric;
  model.materials = {{kE, kNu}};
  model.mesh = test::block(ElementType::Q4, {kInner, 0.0}, {kOuter - kInner, 0.25}, n, 2, "cyl");
  model.fix(NodeSelection::node_set("bottom"), Component::Z);
  model.fix(NodeSelection::node_set("top"), Component::Z);
  model.loads.add_pressure("left", 1.0);
  const LinearStaticResult result = solve_linear_static(model);
  EXPECT_TRUE(result.ok()) << result.outcome.reason;
  for (int node = 0; node < model.mesh.n_nodes(); ++node) {
    const Eigen::Vector2d x = model.mesh.nodes[node];
    if (std::abs(x.x() - kInner) < 1e-12 && std::abs(x.y()) < 1e-12)
      return result.displacement_at(node).x();
  }
  ADD_FAILURE() << "no node at the bore";
  return NAN;
}

// Requirement: from three Q4 meshes (n = 8, 16, 32) the estimator finds the order 2 of linear
// elements' nodal displacements (within 0.05: the next term is O(h^3), 1/8 of the leading
// one at n = 8), a Richardson limit ten times closer to Lame's exact value than the fine value,
// and a GCI that bounds the fine value's true error.
TEST(RowEstimatesFe, LameBoreDisplacementHasOrderTwoAndItsLimit) {
  const double c = bore_displacement(8), m = bore_displacement(16), f = bore_displacement(32);
  const schema::ErrorEstimate e = grading::error_estimate(c, m, f);
  ASSERT_TRUE(e.asymptotic) << e.note;
  EXPECT_NEAR(*e.observed_order, 2.0, 0.05);
  const double fine_error = std::abs(f - kExactBore);
  EXPECT_LT(std::abs(*e.richardson - kExactBore), 0.1 * fine_error);
  EXPECT_GE(*e.gci_percent, 100.0 * fine_error / std::abs(f));
  std::printf("    Lame bore u_r: p = %.4f, fine error %.3e, Richardson error %.3e, GCI %.3e %%\n",
              *e.observed_order, fine_error / kExactBore,
              std::abs(*e.richardson - kExactBore) / kExactBore, *e.gci_percent);
}

double hertz_sigma_c(MeshLevel mesh) {
  const CaseSpec spec{.problem = ProblemId::H_p,
                      .mesh = mesh,
                      .element = Element::Q8,
                      .algorithm = Algorithm::LMP,
                      .contact = ContactKind::mortar,
                      .overrides = {}};
  ProblemExecutor executor(spec);
  const CaseResult r = executor.run(spec);
  EXPECT_EQ(r.status, CaseStatus::converged) << r.reason;
  return r.quantities.at(0).value;  // sigma_c = -sigma_z(0,0)/p
}

// Requirement: on the suite's own Hertz problem (H_p, Q8, Lagrange multipliers, mortar, C M F)
// the estimate agrees with the oracle 4/pi: an order near 2 (observed 2.05; the contact edge
// may lower it, so only above 1.5 is required), and a Richardson limit closer to 4/pi than the
// F value is, within 0.05 % of it. Measured: F is 0.043 % below 4/pi, the limit 0.030 %: the
// discrete sequence converges to a model whose answer differs from Hertz's by about 0.03 %
// (a stiff, not rigid, indenter of finite size in a truncated half-space), which is why the
// GCI (0.016 %, a bound on discretization error only) is not asserted to bound the F error.
TEST(RowEstimatesFe, HertzEstimateAgreesWithTheOracle) {
  const double exact = 4.0 / M_PI;
  const double c = hertz_sigma_c(MeshLevel::C), m = hertz_sigma_c(MeshLevel::M),
               f = hertz_sigma_c(MeshLevel::F);
  const schema::ErrorEstimate e = grading::error_estimate(c, m, f);
  std::printf("    H_p Q8 LMP mortar sigma_c: %.6f %.6f %.6f; %s p = %.3f, R = %.6f, GCI %.3g %%\n",
              c, m, f, e.asymptotic ? "asymptotic" : e.note.c_str(), e.observed_order.value_or(NAN),
              e.richardson.value_or(NAN), e.gci_percent.value_or(NAN));
  ASSERT_TRUE(e.asymptotic) << e.note;
  EXPECT_GT(*e.observed_order, 1.5);
  EXPECT_LT(std::abs(*e.richardson - exact), std::abs(f - exact));
  EXPECT_LT(std::abs(*e.richardson - exact) / exact, 5e-4);
}

}  // namespace
}  // namespace cs::suites
