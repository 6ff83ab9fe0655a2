// Unit tests of the element layer: Gauss rules, Q4/Q8 shape functions, element stiffness,
// consistent edge loads, materials.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "solver/edge_loads.hpp"
#include "solver/elements/element_stiffness.hpp"
#include "solver/elements/gauss_rule.hpp"
#include "solver/elements/shape_functions.hpp"
#include "solver/elements/side_geometry.hpp"
#include "solver/material.hpp"
#include "solver/model_error.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

namespace cs::solver {
namespace {

using cs::testing::Near;

// Requirement: an n-point Gauss rule integrates x^k exactly for k <= 2n - 1.
TEST(FeGaussRule, IntegratesPolynomialsOfDegreeTwoNMinusOneExactly) {
  for (int n = 1; n <= kMaxGaussPoints; ++n) {
    const GaussRule1D& g = gauss_rule_1d(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0;
      for (int q = 0; q < n; ++q)
        sum += g.weights[q] * std::pow(g.points[q], k);
      const double exact = k % 2 == 1 ? 0.0 : 2.0 / (k + 1);
      // round-off: sums of n terms of size <= 2
      EXPECT_TRUE(Near(sum, exact, {1e-13, 1e-14})) << "n = " << n << ", k = " << k;
    }
  }
  EXPECT_THROW(gauss_rule_1d(0), std::invalid_argument);
  EXPECT_THROW(gauss_rule_1d(kMaxGaussPoints + 1), std::invalid_argument);
}

// Requirement: the 2D rule is the tensor product, xi fastest, weights summing to 4.
TEST(FeGaussRule, TensorProductOrdering) {
  const GaussRule2D& r = gauss_rule_2d(3);
  ASSERT_EQ(r.size(), 9);
  EXPECT_DOUBLE_EQ(r.points[1].x(), 0.0);
  EXPECT_DOUBLE_EQ(r.points[1].y(), gauss_rule_1d(3).points[0]);
  double sum = 0.0;
  for (double w : r.weights)
    sum += w;
  EXPECT_TRUE(Near(sum, 4.0, {1e-15, 0.0}));  // round-off
}

class FeShapeFunctions : public ::testing::TestWithParam<ElementType> {};

// Requirement: N_a(node b) = delta_ab; sum N_a = 1 and sum N_a x_a = x (linear completeness)
// anywhere; derivatives agree with central differences.
TEST_P(FeShapeFunctions, KroneckerPartitionOfUnityAndDerivatives) {
  const ElementType type = GetParam();
  const int n = nodes_per_element(type);
  for (int b = 0; b < n; ++b) {
    const ShapeValues s = shape_functions(type, node_natural_coordinates(type, b));
    for (int a = 0; a < n; ++a) {
      EXPECT_TRUE(Near(s.N(a), a == b ? 1.0 : 0.0, {0.0, 1e-15}));  // exact arithmetic
    }
  }
  const Eigen::Vector2d p(0.3, -0.7);
  const ShapeValues s = shape_functions(type, p);
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  for (int a = 0; a < n; ++a)
    x += s.N(a) * node_natural_coordinates(type, a);
  EXPECT_TRUE(Near(s.N.head(n).sum(), 1.0, {1e-15, 0.0}));  // round-off
  EXPECT_TRUE(Near(x.x(), p.x(), {1e-15, 1e-16}));
  EXPECT_TRUE(Near(x.y(), p.y(), {1e-15, 1e-16}));
  const double h = 1e-6;
  for (int d = 0; d < 2; ++d) {
    Eigen::Vector2d dp = Eigen::Vector2d::Zero();
    dp[d] = h;
    const ShapeValues plus = shape_functions(type, p + dp);
    const ShapeValues minus = shape_functions(type, p - dp);
    for (int a = 0; a < n; ++a) {
      const double fd = (plus.N(a) - minus.N(a)) / (2 * h);
      // central difference: truncation O(h^2) ~ 1e-12, cancellation ~ 1e-10
      EXPECT_TRUE(Near(s.dN_dxi(a, d), fd, {0.0, 1e-9}));
    }
  }
}

// Requirement: side shape functions restrict the element's to its sides.
TEST_P(FeShapeFunctions, SideShapeFunctionsAreTheTraceOfTheElementOnes) {
  const ElementType type = GetParam();
  Mesh mesh = test::block(type, {0, 0}, {1, 1}, 1, 1);
  for (int side = 0; side < 4; ++side) {
    const auto nodes = mesh.side_nodes({0, side});
    for (double t : {-1.0, -0.4, 0.2, 1.0}) {
      const ShapeValues s = shape_functions(type, side_point_natural_coordinates(side, t));
      const SideShapeValues ss = side_shape_functions(type, t);
      for (int k = 0; k < ss.n; ++k) {
        int a = 0;
        while (mesh.elements[0][a] != nodes[k])
          ++a;
        EXPECT_TRUE(Near(ss.N[k], s.N(a), {0.0, 1e-15}));  // exact identity
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Q4AndQ8, FeShapeFunctions,
                         ::testing::Values(ElementType::Q4, ElementType::Q8));

ElementGeometry distorted_element(ElementType type, AnalysisType analysis) {
  ElementGeometry g;
  g.type = type;
  g.analysis = analysis;
  g.n_nodes = nodes_per_element(type);
  g.x[0] = {0.2, 0.1};
  g.x[1] = {1.3, 0.0};
  g.x[2] = {1.1, 0.9};
  g.x[3] = {0.3, 1.2};
  for (int s = 0; s < 4 && type == ElementType::Q8; ++s) {
    g.x[4 + s] = 0.5 * (g.x[s] + g.x[(s + 1) % 4]);
  }
  g.body_name = "test";
  return g;
}

// Requirement: K_e is symmetric positive semi-definite with exactly the rigid-body modes as
// null space: 3 in plane strain (translations, rotation), 1 in axisymmetry (axial translation).
TEST(FeElementStiffness, SymmetricWithRigidBodyNullSpace) {
  const Material steel{210e3, 0.3};
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    for (AnalysisType analysis : {AnalysisType::PlaneStrain, AnalysisType::Axisymmetric}) {
      const ElementGeometry g = distorted_element(type, analysis);
      ElementMatrix K;
      element_stiffness(g, elasticity_matrix(steel), default_gauss_points(type), K);
      EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
      const Eigen::MatrixXd K_dense = K;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K_dense);
      const double largest = eig.eigenvalues().maxCoeff();
      int zero = 0;
      for (int i = 0; i < K.rows(); ++i) {
        EXPECT_GT(eig.eigenvalues()[i], -1e-12 * largest);
        if (eig.eigenvalues()[i] < 1e-10 * largest)
          ++zero;
      }
      EXPECT_EQ(zero, analysis == AnalysisType::PlaneStrain ? 3 : 1)
          << "type " << nodes_per_element(type) << ", " << to_string(analysis);
    }
  }
}

// Requirement: an inverted element is a ModelError naming the element and its body.
TEST(FeElementStiffness, InvertedElementNamesElementAndBody) {
  ElementGeometry g = distorted_element(ElementType::Q4, AnalysisType::PlaneStrain);
  std::swap(g.x[1], g.x[3]);  // clockwise
  g.element = 17;
  ElementMatrix K;
  try {
    element_stiffness(g, elasticity_matrix({1.0, 0.3}), 2, K);
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("element 17 of body 'test'"), std::string::npos)
        << e.what();
  }
}

// Requirement: uniform pressure on an edge gives nodal forces summing to p * length (plane
// strain) and p * int r ds (axisymmetric, per radian) along the inward normal; Q8 corner/mid
// split 1/6, 2/3, 1/6 (plane strain).
TEST(FeEdgeLoads, UniformPressureResultantAndConsistentSplit) {
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    for (AnalysisType analysis : {AnalysisType::PlaneStrain, AnalysisType::Axisymmetric}) {
      Model model;
      model.mesh = test::block(type, {1.0, 0.0}, {2.0, 1.0}, 3, 1);
      model.analysis = analysis;
      model.materials = {{1.0, 0.3}};
      Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * model.mesh.n_nodes());
      add_edge_pressure(model, {"top", constant_field(5.0), 0}, f);
      double fz = 0.0, fx = 0.0;
      for (int n = 0; n < model.mesh.n_nodes(); ++n) {
        fx += f[2 * n];
        fz += f[2 * n + 1];
      }
      // top edge from r = 1 to 3: length 2, int r ds = (9 - 1) / 2 = 4
      const double expected = analysis == AnalysisType::PlaneStrain ? -5.0 * 2.0 : -5.0 * 4.0;
      EXPECT_TRUE(Near(fz, expected, {1e-14, 0.0}));  // round-off
      EXPECT_TRUE(Near(fx, 0.0, {0.0, 1e-14}));
      if (type == ElementType::Q8 && analysis == AnalysisType::PlaneStrain) {
        const auto side = model.mesh.edge_sets.at("top").front();
        const auto nodes = model.mesh.side_nodes(side);
        const double length = 2.0 / 3.0;
        // the first corner is shared with no other side (end of the edge): 1/6
        EXPECT_TRUE(Near(f[2 * nodes[2] + 1], -5.0 * length * 2.0 / 3.0, {1e-14, 0.0}));
      }
    }
  }
}

// Requirement: the outward normal of every side of a counter-clockwise element points out.
TEST(FeSideGeometry, OutwardNormals) {
  Mesh mesh = test::block(ElementType::Q8, {0, 0}, {2, 1}, 1, 1);
  const Eigen::Vector2d expected[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (int s = 0; s < 4; ++s) {
    const SidePoint p = side_point(mesh, {0, s}, 0.3);
    EXPECT_TRUE(Near(p.outward_normal.x(), expected[s].x(), {0.0, 1e-15}));
    EXPECT_TRUE(Near(p.outward_normal.y(), expected[s].y(), {0.0, 1e-15}));
  }
}

// Requirement: E > 0 and 0 <= nu < 0.5, else a ModelError naming the body.
TEST(FeMaterial, ValidatesModulusAndPoissonsRatio) {
  EXPECT_NO_THROW(validate(Material{1.0, 0.0}, "b"));
  EXPECT_NO_THROW(validate(Material{1.0, 0.4999}, "b"));
  EXPECT_THROW(validate(Material{0.0, 0.3}, "b"), ModelError);
  EXPECT_THROW(validate(Material{-1.0, 0.3}, "b"), ModelError);
  EXPECT_THROW(validate(Material{NAN, 0.3}, "b"), ModelError);
  EXPECT_THROW(validate(Material{1.0, 0.5}, "b"), ModelError);
  EXPECT_THROW(validate(Material{1.0, -0.1}, "b"), ModelError);
  try {
    validate(Material{1.0, 0.5}, "indenter");
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("'indenter'"), std::string::npos);
  }
  // plane strain sigma_y = nu (sigma_x + sigma_z) from row 3 of D with eps_y = 0
  const Material m{3.0, 0.25};
  const Eigen::Vector4d s = elasticity_matrix(m) * Eigen::Vector4d(1e-3, -2e-3, 5e-4, 0.0);
  EXPECT_TRUE(Near(s[3], 0.25 * (s[0] + s[1]), {1e-14, 0.0}));
}

}  // namespace
}  // namespace cs::solver
