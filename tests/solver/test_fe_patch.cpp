// Patch tests: constant-strain states on distorted meshes are reproduced to machine precision
// (1e-10 relative) by Q4 and Q8, in plane strain and in axisymmetry (with nodes on the axis),
// with the boundary given as prescribed displacements and as consistent tractions.

#include <string>

#include <gtest/gtest.h>

#include "solver/linear_static.hpp"
#include "solver/stress_recovery.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_fe_patch {
namespace {

using cs::testing::Near;

struct PatchCase {
  ElementType type;
  AnalysisType analysis;
};

std::string label(const PatchCase& c) {
  return std::string(c.type == ElementType::Q4 ? "Q4" : "Q8") +
         (c.analysis == AnalysisType::PlaneStrain ? "PlaneStrain" : "Axisymmetric");
}

std::string name(const ::testing::TestParamInfo<PatchCase>& info) {
  return label(info.param);
}

void PrintTo(const PatchCase& c, std::ostream* os) {
  *os << label(c);
}

class FePatchTest : public ::testing::TestWithParam<PatchCase> {
 protected:
  /// A distorted 4 x 3 block [0, 2] x [0, 1.5] (the left edge r = 0 is the axis in axisymmetry).
  Model distorted_model() const {
    Model model;
    model.mesh = test::block(GetParam().type, {0.0, 0.0}, {2.0, 1.5}, 4, 3);
    test::distort_interior(model.mesh, 0.3, 0.5);
    model.analysis = GetParam().analysis;
    model.materials = {{200.0, 0.3}};
    return model;
  }
  bool axisymmetric() const { return GetParam().analysis == AnalysisType::Axisymmetric; }
};

/// The exact linear field: plane strain u = a + A x (general); axisymmetric u_r = c r,
/// u_z = d z + e (the linear fields with constant strain in axisymmetry).
Eigen::Vector2d exact_u(bool axi, const Eigen::Vector2d& x) {
  if (axi)
    return {2e-3 * x.x(), -1e-3 * x.y() + 4e-4};
  return {1e-4 + 2e-3 * x.x() + 7e-4 * x.y(), -3e-4 - 5e-4 * x.x() - 1e-3 * x.y()};
}

/// Its constant strain (eps_x|r, eps_z, gamma_xz|rz, eps_y|theta).
Eigen::Vector4d exact_strain(bool axi) {
  if (axi)
    return {2e-3, -1e-3, 0.0, 2e-3};
  return {2e-3, -1e-3, 7e-4 - 5e-4, 0.0};
}

void expect_exact(const Model& model, const LinearStaticResult& result, bool axi) {
  ASSERT_TRUE(result.ok()) << result.outcome.reason;
  double scale = 0.0;
  for (const auto& x : model.mesh.nodes)
    scale = std::max(scale, exact_u(axi, x).cwiseAbs().maxCoeff());
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Eigen::Vector2d u = exact_u(axi, model.mesh.nodes[n]);
    // machine precision (the 1e-10 relative, relative to the largest displacement)
    EXPECT_TRUE(Near(result.displacement[2 * n], u.x(), {0.0, 1e-10 * scale})) << "node " << n;
    EXPECT_TRUE(Near(result.displacement[2 * n + 1], u.y(), {0.0, 1e-10 * scale})) << "node " << n;
  }
  const Eigen::Vector4d sigma = elasticity_matrix(model.materials[0]) * exact_strain(axi);
  const double s_scale = sigma.cwiseAbs().maxCoeff();
  for (StressRecoveryMethod method :
       {StressRecoveryMethod::GaussPoint, StressRecoveryMethod::ExtrapolatedAveraged}) {
    const StressField field = recover_stresses(model, result.displacement, {method});
    EXPECT_EQ(field.method, method);
    std::vector<Stress> values;
    for (const auto& gp : field.gauss_points)
      values.push_back(gp.stress);
    for (int n = 0; n < model.mesh.n_nodes(); ++n) {
      if (field.has_node(n, 0))
        values.push_back(field.at_node(n));
    }
    ASSERT_FALSE(values.empty());
    for (const Stress& s : values) {
      for (int c = 0; c < 4; ++c) {
        // machine precision, relative to the largest stress component
        EXPECT_TRUE(Near(s.vector()[c], sigma[c], {0.0, 1e-10 * s_scale})) << "component " << c;
      }
    }
  }
}

// Requirement: with the exact linear field prescribed on the whole boundary, every interior
// node and every stress (Gauss point and extrapolated nodal) is exact.
TEST_P(FePatchTest, DisplacementBoundaryReproducesLinearField) {
  Model model = distorted_model();
  const bool axi = axisymmetric();
  for (const char* edge : {"left", "right", "bottom", "top"}) {
    for (Component c : {Component::X, Component::Z}) {
      model.prescribe(NodeSelection::node_set(edge), c, [axi, c](const Eigen::Vector2d& x) {
        return exact_u(axi, x)[static_cast<int>(c)];
      });
    }
  }
  expect_exact(model, solve_linear_static(model), axi);
}

// Requirement: the constant stress state loaded by its consistent boundary tractions (and held
// by the minimal supports) is reproduced exactly: the edge-load integration (with the r weight
// in axisymmetry) is consistent with the stiffness.
TEST_P(FePatchTest, TractionBoundaryReproducesConstantStress) {
  Model model = distorted_model();
  const bool axi = axisymmetric();
  const Eigen::Vector4d s = elasticity_matrix(model.materials[0]) * exact_strain(axi);
  const double sx = s[0], sz = s[1], txz = s[2];
  model.loads.add_traction("right", constant_field(Eigen::Vector2d(sx, txz)));
  model.loads.add_traction("top", constant_field(Eigen::Vector2d(txz, sz)));
  if (axi) {
    // r = 0 is the axis (u_r = 0); the bottom is a roller at z = 0 with the field's u_z there.
    model.fix(NodeSelection::node_set("left"), Component::R);
    model.fix(NodeSelection::node_set("bottom"), Component::Z, exact_u(true, {0, 0}).y());
  } else {
    model.loads.add_traction("left", constant_field(Eigen::Vector2d(-sx, -txz)));
    model.loads.add_traction("bottom", constant_field(Eigen::Vector2d(-txz, -sz)));
    // Minimal supports at (0, 0) and (2, 0), with the exact field's values there.
    const int origin = model.mesh.node_sets.at("bottom").front();
    const int far = model.mesh.node_sets.at("bottom").back();
    const Eigen::Vector2d u0 = exact_u(false, model.mesh.nodes[origin]);
    const Eigen::Vector2d u1 = exact_u(false, model.mesh.nodes[far]);
    model.fix(NodeSelection::list({origin}, "origin"), Component::X, u0.x());
    model.fix(NodeSelection::list({origin}, "origin"), Component::Z, u0.y());
    model.fix(NodeSelection::list({far}, "far corner"), Component::Z, u1.y());
  }
  const LinearStaticResult result = solve_linear_static(model);
  expect_exact(model, result, axi);
  // The reactions balance the applied loads (tractions only in axisymmetry on right/top).
  ASSERT_TRUE(result.ok());
  const double reaction_z = [&] {
    double sum = 0.0;
    for (int n = 0; n < model.mesh.n_nodes(); ++n)
      sum += result.reaction[2 * n + 1];
    return sum;
  }();
  // axisymmetric: top traction sigma_z over int r dr = 2 (r from 0 to 2); plane: balanced
  const double expected = axi ? -sz * 2.0 : 0.0;
  EXPECT_TRUE(Near(reaction_z, expected, {1e-10, 1e-12 * std::abs(sz)}));  // machine precision
}

INSTANTIATE_TEST_SUITE_P(AllElementsAndAnalyses, FePatchTest,
                         ::testing::Values(PatchCase{ElementType::Q4, AnalysisType::PlaneStrain},
                                           PatchCase{ElementType::Q8, AnalysisType::PlaneStrain},
                                           PatchCase{ElementType::Q4, AnalysisType::Axisymmetric},
                                           PatchCase{ElementType::Q8, AnalysisType::Axisymmetric}),
                         name);

}  // namespace
}  // namespace cs::solver::test_fe_patch
