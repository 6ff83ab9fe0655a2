// The interference fits IF_p (shaft in a ring, plane strain) and IF_a (sphere in a shell,
// axisymmetric) against the Lame oracle, on the C and M meshes (fast), checked against facts
// independent of the solver:
//   - Lagrange multipliers: the mean pressure converges to the oracle's; with Q4 at the observed
//     order of the arc's faceting, 2 (the chord's sagitta is b dtheta^2 / 8);
//   - penalty: the normal penalty k = FKN E / h per unit area is a spring in series with the
//     bodies, whose stiffness is p / delta from the oracle, so the mean pressure is low by
//     kappa h / (1 + kappa h), kappa = p b / (E delta) (h over b): computed from the oracle and
//     the mesh, not from the solver;
//   - MPC ties the same nodal rows to g = 0 as LM (nothing opens): the same pressures;
//   - E is chosen so that the exact pressure is 1 (the normalizing pressure p).

#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "solver/mesh/mesh_sets.hpp"
#include "suites/problem_executor.hpp"
#include "support/tolerance.hpp"

namespace cs::suites {
namespace {

using cs::testing::Near;
using schema::Quantity;

CaseSpec fit_case(ProblemId problem, MeshLevel mesh, Element element, Algorithm a, ContactKind c,
                  std::map<std::string, double> overrides = {}) {
  return CaseSpec{.problem = problem,
                  .mesh = mesh,
                  .element = element,
                  .algorithm = a,
                  .contact = c,
                  .overrides = std::move(overrides)};
}

struct FitRun {
  CaseResult result;
  double p = 0.0;
  double kappa_h = 0.0;  ///< p h / (E delta): the penalty's relative compliance at FKN 1
};

/// The depth h of the ring's elements at the bore: corner-quadrilateral area over the bore side.
double bore_element_depth(const solver::Mesh& mesh) {
  const solver::ElementSide side = solver::edge_set(mesh, "block.contact").front();
  const auto& e = mesh.elements[side.element];
  double twice_area = 0.0;
  for (int k = 0; k < 4; ++k) {
    const auto& a = mesh.nodes[e[k]];
    const auto& b = mesh.nodes[e[(k + 1) % 4]];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  const auto nodes = mesh.side_nodes(side);
  return 0.5 * twice_area / (mesh.nodes[nodes[1]] - mesh.nodes[nodes[0]]).norm();
}

FitRun run(const CaseSpec& spec) {
  ProblemExecutor executor(spec);
  FitRun out{executor.run(spec), executor.setup().p, 0.0};
  const auto& setup = executor.setup();
  const auto it = spec.overrides.find("delta_over_b");
  const double delta_over_b = it != spec.overrides.end() ? it->second : 1e-3;
  const double E = setup.model.materials[0].youngs_modulus_E;
  out.kappa_h = setup.p / (E * delta_over_b) * bore_element_depth(setup.model.mesh);
  EXPECT_EQ(out.result.status, CaseStatus::converged) << case_id(spec) << out.result.reason;
  return out;
}

double error_of(const FitRun& r, Quantity q) {
  const QuantityResult* v = r.result.quantity(q);
  return v != nullptr ? v->error_percent : std::nan("");
}

class FitProblem : public ::testing::TestWithParam<ProblemId> {};

// Requirement: LM (LMP, ss and mortar) gives the oracle's mean pressure within 0.3 % on C and
// 0.1 % on M, and along the arc within 3.5 % (C) and 2 % (M); its Q4 error falls at the order of
// the faceting (1.7 to 2.3: 2 expected). The order is taken at delta/b = 1e-5: the sphere's error
// has a floor of about 0.4 delta/b (0.04 % at the default 1e-3) from the overlapped geometry,
// which the linear oracle does not model (measured: Q8 LMP ss, +0.039 % on F at 1e-3, +0.003 %
// at 1e-5).
TEST_P(FitProblem, LagrangeMultipliersConvergeToTheLamePressure) {
  for (const auto c : {ContactKind::ss, ContactKind::mortar}) {
    for (const auto element : {Element::Q4, Element::Q8}) {
      const std::map<std::string, double> small{{"delta_over_b", 1e-5}};
      const FitRun coarse =
          run(fit_case(GetParam(), MeshLevel::C, element, Algorithm::LMP, c, small));
      const FitRun medium =
          run(fit_case(GetParam(), MeshLevel::M, element, Algorithm::LMP, c, small));
      EXPECT_TRUE(Near(coarse.p, 1.0, {1e-12, 0.0}));  // E chosen so that p = 1
      EXPECT_LT(std::abs(error_of(coarse, Quantity::p_mean)), 0.3);
      EXPECT_LT(std::abs(error_of(medium, Quantity::p_mean)), 0.1);
      EXPECT_LT(std::abs(error_of(coarse, Quantity::p_arc)), 3.5);
      EXPECT_LT(std::abs(error_of(medium, Quantity::p_arc)), 2.0);
      if (element == Element::Q4) {
        const double order =
            std::log2(error_of(coarse, Quantity::p_mean) / error_of(medium, Quantity::p_mean));
        EXPECT_GT(order, 1.7) << case_id(coarse.result.spec);
        EXPECT_LT(order, 2.3) << case_id(coarse.result.spec);
      }
    }
  }
}

// Requirement: the penalty's mean pressure is low by exactly its series compliance,
// kappa h / (FKN (1 + kappa h / FKN)), to 0.02 percentage points with Q8 (whose own error is
// below 1e-3 % in plane strain and 0.1 % in the sphere: the tolerance there is 0.12 points), at
// FKN 1 and at the default FKN 100.
TEST_P(FitProblem, PenaltyIsASpringInSeries) {
  for (const double fkn : {1.0, 100.0}) {
    for (const auto mesh : {MeshLevel::C, MeshLevel::M}) {
      const std::map<std::string, double> set{{"fkn", fkn}};
      const FitRun pm =
          run(fit_case(GetParam(), mesh, Element::Q8, Algorithm::PM, ContactKind::ss, set));
      const double compliance = pm.kappa_h / fkn;
      const double predicted = -100.0 * compliance / (1.0 + compliance);
      const double tol = GetParam() == ProblemId::IF_p ? 0.02 : 0.12;
      EXPECT_TRUE(Near(error_of(pm, Quantity::p_mean), predicted, {0.0, tol}))
          << case_id(pm.result.spec) << " kappa h = " << pm.kappa_h;
    }
  }
}

// Requirement: MPC (ties g = 0 from the start) and LMP give the same pressures when the whole
// arc stays closed (round-off).
TEST_P(FitProblem, MpcClosesTheOverlapLikeLagrangeMultipliers) {
  const FitRun lm =
      run(fit_case(GetParam(), MeshLevel::C, Element::Q8, Algorithm::LMP, ContactKind::ns));
  const FitRun mpc =
      run(fit_case(GetParam(), MeshLevel::C, Element::Q8, Algorithm::MPC, ContactKind::ns));
  for (const auto q : {Quantity::p_mean, Quantity::p_arc})
    EXPECT_TRUE(Near(mpc.result.quantity(q)->value, lm.result.quantity(q)->value, {1e-9, 0.0}));
}

INSTANTIATE_TEST_SUITE_P(InterferenceFits, FitProblem,
                         ::testing::Values(ProblemId::IF_p, ProblemId::IF_a),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace cs::suites
