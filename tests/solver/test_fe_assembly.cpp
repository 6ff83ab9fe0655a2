// Assembly on one core or two: the element matrices of a step are computed in two halves, the
// second on a borrowed core when one is idle, and added in element order; the scatter map is
// built in two halves the same way. Nothing may depend on where they ran.

#include <optional>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include "solver/linear_static.hpp"
#include "solver/material.hpp"
#include "solver/model_error.hpp"
#include "solver/spare_cores.hpp"
#include "support/same_bits.hpp"
#include "test_fe_support.hpp"

namespace cs::solver::test_fe_assembly {
namespace {

using cs::testing::expect_same_bits;

/// A distorted Q8 block, 7 x 6.5, of 70 x 65 elements (4,550: two whole steps and a part),
/// fixed on its left edge (K_cg has rows) or free.
Model distorted_block(bool fixed = true) {
  Model model;
  model.mesh = test::block(ElementType::Q8, {0.0, 0.0}, {7.0, 6.5}, 70, 65);
  test::distort_interior(model.mesh, 0.3, 0.1);
  model.materials = {{200.0, 0.3}};
  if (fixed) {
    model.fix(NodeSelection::node_set("left"), Component::X);
    model.fix(NodeSelection::node_set("left"), Component::Z);
  }
  return model;
}

/// The stiffness of `model` assembled with `spare` cores lent for the analysis's lifetime.
StiffnessMatrices assembled(const Model& model, int spare) {
  const CoreLoan loan(spare);
  LinearStaticAnalysis analysis(model);
  analysis.assemble();
  return analysis.stiffness();
}

// Requirement (issue 27): K_ff and K_cg are the same to the bit whether a core was idle or
// not. Fails if a half's matrices are added out of element order, a step's boundary drops or
// repeats an element, or a half of the scatter map is left unset.
TEST(Assembly, IsTheSameOnOneCoreOrTwo) {
  const Model model = distorted_block();
  ASSERT_GT(model.mesh.n_elements(), 2 * 2048);
  const StiffnessMatrices one = assembled(model, 0);
  const StiffnessMatrices two = assembled(model, 1);
  expect_same_bits(one.K_ff, two.K_ff);
  expect_same_bits(one.K_cg, two.K_cg);
}

// Requirement: every element is added once. For the uniform strain u = (eps x, 0) of the free
// block, u^T K u is the strain energy twice, eps^2 D_00 times the block's area (plane strain,
// unit thickness), which every element reproduces exactly: an element dropped or added twice
// moves it by 1/4,550 of the whole, far above round-off.
TEST(Assembly, EveryElementIsAddedOnce) {
  const Model model = distorted_block(false);
  const CoreLoan loan(1);
  LinearStaticAnalysis analysis(model);
  analysis.assemble();
  const Eigen::SparseMatrix<double>& K = analysis.stiffness().K_ff;
  const double eps = 1e-3;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(K.rows());
  for (int n = 0; n < model.mesh.n_nodes(); ++n)
    u[analysis.dof_map().equation(n, Component::X)] = eps * model.mesh.nodes[n].x();
  const Eigen::VectorXd Ku = K.selfadjointView<Eigen::Lower>() * u;
  const double D00 = elasticity_matrix(model.materials[0])(0, 0);
  EXPECT_NEAR(u.dot(Ku), eps * eps * D00 * 7.0 * 6.5, 1e-10 * eps * eps * D00 * 7.0 * 6.5);
}

/// The message of the ModelError that assembling `model` with `spare` cores lent throws.
std::optional<std::string> assembly_error(const Model& model, int spare) {
  try {
    assembled(model, spare);
  } catch (const ModelError& e) {
    return e.what();
  }
  return std::nullopt;
}

// Requirement: an inverted element in either half is named alike on one core or two; with one
// in each half, the first (the one the serial loop meets first) is named.
TEST(Assembly, AnInvertedElementIsNamedAlikeOnOneCoreOrTwo) {
  Model model = distorted_block();
  auto invert = [&model](int e) {
    auto& nodes = model.mesh.elements[e];
    std::swap(nodes[1], nodes[3]);  // corners clockwise: det J < 0
  };
  invert(3000);  // the second half of the second step
  const auto late = assembly_error(model, 0);
  ASSERT_TRUE(late.has_value());
  EXPECT_EQ(assembly_error(model, 1), late);
  invert(2100);  // the first half of the same step
  const auto early = assembly_error(model, 0);
  ASSERT_TRUE(early.has_value());
  EXPECT_NE(early, late);
  EXPECT_EQ(assembly_error(model, 1), early);
}

}  // namespace
}  // namespace cs::solver::test_fe_assembly
