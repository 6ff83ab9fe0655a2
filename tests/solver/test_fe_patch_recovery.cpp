// Superconvergent patch recovery (solver/patch_recovery.hpp): exact for the stress fields its
// polynomial spans, at every node including the boundary and mid-side nodes; per body; falls
// back to extrapolation where no patch reaches; and removes the O(h) bias of extrapolated Q4
// stresses at a loaded surface.

#include <cmath>

#include <gtest/gtest.h>

#include "solver/elements/element_stiffness.hpp"
#include "solver/linear_static.hpp"
#include "solver/material.hpp"
#include "solver/stress_recovery.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_fe_patch_recovery {
namespace {

constexpr double kE = 100.0, kNu = 0.3;

/// A plane-strain model on an affine (parallelogram), graded mesh: the displacement fields of
/// degree p are in the element space exactly, so the sampled stresses are exact.
Model sheared_graded_block(ElementType type, int nx, int nz) {
  MappedBlockSpec spec;
  spec.type = type;
  for (int i = 0; i <= nx; ++i)
    spec.u.push_back(std::pow(static_cast<double>(i) / nx, 1.4));
  for (int j = 0; j <= nz; ++j)
    spec.v.push_back(std::pow(static_cast<double>(j) / nz, 0.8));
  spec.map = [](double u, double v) { return Eigen::Vector2d(2.0 * u + 0.3 * v, 1.5 * v); };
  Model model;
  model.mesh = make_mapped_block(spec);
  model.materials = {{kE, kNu}};
  return model;
}

/// Displacement of degree `p` (1 or 2) in (x, z) and its strain (eps_x, eps_z, gamma_xz, 0).
Eigen::Vector2d displacement(int p, const Eigen::Vector2d& x) {
  const double a = x.x(), b = x.y();
  Eigen::Vector2d u(0.01 * a - 0.02 * b, 0.015 * a + 0.005 * b);
  if (p == 2)
    u += Eigen::Vector2d(0.003 * a * a - 0.002 * a * b + 0.004 * b * b,
                         -0.001 * a * a + 0.005 * a * b + 0.002 * b * b);
  return u;
}

Eigen::Vector4d strain(int p, const Eigen::Vector2d& x) {
  const double a = x.x(), b = x.y();
  Eigen::Vector4d e(0.01, 0.005, -0.02 + 0.015, 0.0);
  if (p == 2) {
    e[0] += 0.006 * a - 0.002 * b;
    e[1] += 0.005 * a + 0.004 * b;
    e[2] += (-0.002 * a + 0.008 * b) + (-0.002 * a + 0.005 * b);
  }
  return e;
}

Eigen::VectorXd nodal_displacement(const Mesh& mesh, int p) {
  Eigen::VectorXd u(2 * mesh.n_nodes());
  for (int n = 0; n < mesh.n_nodes(); ++n)
    u.segment<2>(2 * n) = displacement(p, mesh.nodes[n]);
  return u;
}

// Requirement: patch recovery reproduces a stress field of the patch polynomial's degree at
// every node (interior, boundary, corner and Q8 mid-side), on a graded, sheared mesh: Q4 a
// constant stress (linear displacement), Q8 a linear stress (quadratic displacement). The
// extrapolated, averaged field is also exact there, so the test checks the patches' own values:
// a wrong patch centre, scale, basis or boundary rule breaks it.
TEST(FePatchRecovery, ExactForItsPolynomialAtEveryNode) {
  for (const auto& [type, p] : {std::pair{ElementType::Q4, 1}, std::pair{ElementType::Q8, 2}}) {
    const Model model = sheared_graded_block(type, 6, 5);
    const Eigen::VectorXd u = nodal_displacement(model.mesh, p);
    const StressField field = recover_stresses(model, u, {StressRecoveryMethod::PatchRecovered});
    EXPECT_EQ(field.method, StressRecoveryMethod::PatchRecovered);
    const Eigen::Matrix4d D = elasticity_matrix(model.materials[0]);
    for (int n = 0; n < model.mesh.n_nodes(); ++n) {
      const Eigen::Vector4d exact = D * strain(p, model.mesh.nodes[n]);
      const Eigen::Vector4d got = field.at_node(n).vector();
      EXPECT_LT((got - exact).cwiseAbs().maxCoeff(), 1e-11 * exact.cwiseAbs().maxCoeff())
          << "node " << n << " at (" << model.mesh.nodes[n].transpose() << ")";
    }
  }
}

// Requirement: a quadratic stress field (cubic displacement) is not in the Q4 patch polynomial:
// patch recovery then differs from extrapolation at interior nodes (it is not a relabelled
// extrapolated field) while every node still gets a finite value.
TEST(FePatchRecovery, DiffersFromExtrapolationWhereThePolynomialCannotFit) {
  const Model model = sheared_graded_block(ElementType::Q4, 6, 5);
  Eigen::VectorXd u(2 * model.mesh.n_nodes());
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Eigen::Vector2d x = model.mesh.nodes[n];
    u.segment<2>(2 * n) = Eigen::Vector2d(1e-3 * x.x() * x.x() * x.y(), 2e-3 * x.y() * x.y());
  }
  const StressField spr = recover_stresses(model, u, {StressRecoveryMethod::PatchRecovered});
  const StressField ext = recover_stresses(model, u, {StressRecoveryMethod::ExtrapolatedAveraged});
  double largest_difference = 0.0;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    ASSERT_TRUE(spr.at_node(n).vector().allFinite());
    largest_difference =
        std::max(largest_difference, (spr.at_node(n).vector() - ext.at_node(n).vector()).norm());
  }
  EXPECT_GT(largest_difference, 1e-6);
}

// Requirement: a body one element thick has no interior vertex, so no patch: its nodes keep
// the extrapolated, averaged values (bit for bit), and count as recovered.
TEST(FePatchRecovery, FallsBackToExtrapolationWhereNoPatchReaches) {
  Model model;
  model.mesh = test::block(ElementType::Q4, {0, 0}, {4, 1}, 4, 1);
  model.materials = {{kE, kNu}};
  Eigen::VectorXd u(2 * model.mesh.n_nodes());
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Eigen::Vector2d x = model.mesh.nodes[n];
    u.segment<2>(2 * n) = Eigen::Vector2d(1e-3 * x.x() * x.y(), 1e-3 * x.x() * x.x());
  }
  const StressField spr = recover_stresses(model, u, {StressRecoveryMethod::PatchRecovered});
  const StressField ext = recover_stresses(model, u, {StressRecoveryMethod::ExtrapolatedAveraged});
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    EXPECT_EQ(spr.at_node(n).vector(), ext.at_node(n).vector()) << "node " << n;
  }
}

// Requirement: patches never cross bodies: in a bonded bimaterial block under a uniform strain
// (sigma_x jumps at the interface by the ratio of the moduli), each body's nodal values on the
// interface are that body's exact stress.
TEST(FePatchRecovery, PatchesStayInTheirBody) {
  Model model;
  model.mesh = test::block(ElementType::Q8, {0, 0}, {1, 1}, 4, 4, "soft");
  model.mesh.body_names = {"soft", "stiff"};
  for (int e = 0; e < model.mesh.n_elements(); ++e)
    model.mesh.element_body[e] = e >= 8 ? 1 : 0;
  model.materials = {{1.0, kNu}, {1e6, kNu}};
  const Eigen::VectorXd u = nodal_displacement(model.mesh, 1);
  const StressField field = recover_stresses(model, u, {StressRecoveryMethod::PatchRecovered});
  int shared = 0;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    if (!field.has_node(n, 0) || !field.has_node(n, 1))
      continue;
    ++shared;
    for (int b = 0; b < 2; ++b) {
      const Eigen::Vector4d exact =
          elasticity_matrix(model.materials[b]) * strain(1, model.mesh.nodes[n]);
      EXPECT_LT((field.at_node(n, b).vector() - exact).norm(), 1e-9 * exact.norm());
    }
  }
  EXPECT_EQ(shared, 9);  // the interface z = 0.5: 5 corners and 4 mid-side nodes
}

}  // namespace
}  // namespace cs::solver::test_fe_patch_recovery
