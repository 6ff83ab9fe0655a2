// Manufactured solutions with body force: observed orders of convergence of Q4 and Q8 in the
// L2 norm of the displacement (2 and 3) and in the energy norm (1 and 2), fitted over four
// meshes, in plane strain and in axisymmetry (domain touching the axis).
//
// Plane strain, on [0, 1]^2: u_x = sin(a x) cos(b z), u_z = cos(a x) sin(b z), for which
//   sigma_x = A cos cos, sigma_z = B cos cos, tau_xz = -C sin sin,
//   A = (lambda + 2 mu) a + lambda b, B = lambda a + (lambda + 2 mu) b, C = mu (a + b),
// and the body force b = -div sigma is b_x = (A a + C b) sin(a x) cos(b z),
// b_z = (C a + B b) cos(a x) sin(b z).
// Axisymmetric, on [0, 1]^2 in (r, z): u_r = sin(a r) cos(b z), u_z = cos(a r) sin(b z); the
// body force b_r = -(d sigma_r/dr + d tau_rz/dz + (sigma_r - sigma_theta)/r),
// b_z = -(d tau_rz/dr + d sigma_z/dz + tau_rz/r) is evaluated from the exact stress by central
// differences (step 1e-5: error ~1e-10, far below the discretization errors measured).
// The exact displacement is prescribed on the whole boundary (u_r = 0 on the axis).

#include <cmath>

#include <gtest/gtest.h>

#include "solver/elements/element_stiffness.hpp"
#include "solver/elements/gauss_rule.hpp"
#include "solver/linear_static.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_fe_manufactured {
namespace {

using cs::testing::Near;

constexpr double kA = 2.1;  // wave numbers: not aligned with the mesh, no symmetry
constexpr double kB = 1.7;

struct Exact {
  AnalysisType analysis;
  Material material{100.0, 0.3};

  Eigen::Vector2d u(const Eigen::Vector2d& x) const {
    return {std::sin(kA * x.x()) * std::cos(kB * x.y()),
            std::cos(kA * x.x()) * std::sin(kB * x.y())};
  }
  Eigen::Vector4d strain(const Eigen::Vector2d& x) const {
    const double r = x.x(), z = x.y();
    const double hoop = analysis == AnalysisType::Axisymmetric ? u(x).x() / r : 0.0;
    return {kA * std::cos(kA * r) * std::cos(kB * z), kB * std::cos(kA * r) * std::cos(kB * z),
            -(kA + kB) * std::sin(kA * r) * std::sin(kB * z), hoop};
  }
  Eigen::Vector4d stress(const Eigen::Vector2d& x) const {
    return elasticity_matrix(material) * strain(x);
  }
  Eigen::Vector2d body_force(const Eigen::Vector2d& x) const {
    const double h = 1e-5;
    const Eigen::Vector2d dr(h, 0.0), dz(0.0, h);
    const Eigen::Vector4d ds_dr = (stress(x + dr) - stress(x - dr)) / (2 * h);
    const Eigen::Vector4d ds_dz = (stress(x + dz) - stress(x - dz)) / (2 * h);
    Eigen::Vector2d div(ds_dr[0] + ds_dz[2], ds_dr[2] + ds_dz[1]);
    if (analysis == AnalysisType::Axisymmetric) {
      const Eigen::Vector4d s = stress(x);
      div += Eigen::Vector2d((s[0] - s[3]) / x.x(), s[2] / x.x());
    }
    return -div;
  }
};

struct Errors {
  double h = 0.0;
  double l2 = 0.0;      ///< relative L2 error of the displacement
  double energy = 0.0;  ///< relative energy-norm error
};

Errors solve_and_measure(ElementType type, AnalysisType analysis, int n) {
  const Exact exact{analysis};
  Model model;
  model.mesh = test::block(type, {0, 0}, {1, 1}, n, n);
  model.analysis = analysis;
  model.materials = {exact.material};
  model.quadrature.body_force_points = 5;  // smooth non-polynomial body force
  for (const char* edge : {"left", "right", "bottom", "top"}) {
    for (int c = 0; c < 2; ++c) {
      model.prescribe(NodeSelection::node_set(edge), static_cast<Component>(c),
                      [exact, c](const Eigen::Vector2d& x) { return exact.u(x)[c]; });
    }
  }
  model.loads.add_body_force([exact](const Eigen::Vector2d& x) { return exact.body_force(x); });
  const LinearStaticResult result = solve_linear_static(model);
  EXPECT_TRUE(result.ok()) << result.outcome.reason;

  // Norms by 5 x 5 Gauss quadrature per element (exact to the discretization error's order).
  const Eigen::Matrix4d D = elasticity_matrix(exact.material);
  const GaussRule2D& rule = gauss_rule_2d(5);
  double e_l2 = 0, u_l2 = 0, e_en = 0, u_en = 0;
  for (int e = 0; e < model.mesh.n_elements(); ++e) {
    const ElementGeometry g = element_geometry(model.mesh, analysis, e);
    ElementVector u_e(2 * g.n_nodes);
    for (int a = 0; a < g.n_nodes; ++a) {
      u_e(2 * a) = result.displacement[2 * model.mesh.elements[e][a]];
      u_e(2 * a + 1) = result.displacement[2 * model.mesh.elements[e][a] + 1];
    }
    for (int q = 0; q < rule.size(); ++q) {
      const PointKinematics k = point_kinematics(g, rule.points[q]);
      const double w = rule.weights[q] * k.measure();
      Eigen::Vector2d u_h = Eigen::Vector2d::Zero();
      for (int a = 0; a < g.n_nodes; ++a)
        u_h += k.shape.N(a) * u_e.segment<2>(2 * a);
      const Eigen::Vector2d u = exact.u(k.position);
      const Eigen::Vector4d eps = exact.strain(k.position);
      const Eigen::Vector4d d_eps = k.B * u_e - eps;
      e_l2 += w * (u_h - u).squaredNorm();
      u_l2 += w * u.squaredNorm();
      e_en += w * d_eps.dot(D * d_eps);
      u_en += w * eps.dot(D * eps);
    }
  }
  return {1.0 / n, std::sqrt(e_l2 / u_l2), std::sqrt(e_en / u_en)};
}

struct RateCase {
  ElementType type;
  AnalysisType analysis;
  std::vector<int> divisions;
  double l2_order;
  double energy_order;
};

void PrintTo(const RateCase& c, std::ostream* os) {
  *os << (c.type == ElementType::Q4 ? "Q4 " : "Q8 ") << to_string(c.analysis);
}

class FeManufacturedSolution : public ::testing::TestWithParam<RateCase> {};

// Requirement: observed orders (least-squares slope over four meshes) within 0.15 of the
// theoretical ones: L2 p + 1, energy p (p = 1 for Q4, 2 for Q8).
TEST_P(FeManufacturedSolution, ObservedOrdersOfConvergence) {
  const RateCase& c = GetParam();
  std::vector<double> h, l2, energy;
  for (int n : c.divisions) {
    const Errors e = solve_and_measure(c.type, c.analysis, n);
    h.push_back(e.h);
    l2.push_back(e.l2);
    energy.push_back(e.energy);
  }
  const double l2_order = test::observed_order(h, l2);
  const double energy_order = test::observed_order(h, energy);
  RecordProperty("l2_order", std::to_string(l2_order));
  RecordProperty("energy_order", std::to_string(energy_order));
  std::printf("    %s %s: L2 errors %.3e .. %.3e, order %.3f; energy %.3e .. %.3e, order %.3f\n",
              c.type == ElementType::Q4 ? "Q4" : "Q8", to_string(c.analysis), l2.front(), l2.back(),
              l2_order, energy.front(), energy.back(), energy_order);
  // asymptotic rates: +-0.15 covers the pre-asymptotic curvature of the coarsest mesh
  EXPECT_TRUE(Near(l2_order, c.l2_order, {0.0, 0.15}));
  EXPECT_TRUE(Near(energy_order, c.energy_order, {0.0, 0.15}));
}

std::string rate_name(const ::testing::TestParamInfo<RateCase>& info) {
  return std::string(info.param.type == ElementType::Q4 ? "Q4" : "Q8") +
         (info.param.analysis == AnalysisType::PlaneStrain ? "PlaneStrain" : "Axisymmetric");
}

INSTANTIATE_TEST_SUITE_P(
    Q4AndQ8, FeManufacturedSolution,
    ::testing::Values(
        RateCase{ElementType::Q4, AnalysisType::PlaneStrain, {4, 8, 16, 32}, 2.0, 1.0},
        RateCase{ElementType::Q8, AnalysisType::PlaneStrain, {2, 4, 8, 16}, 3.0, 2.0},
        RateCase{ElementType::Q4, AnalysisType::Axisymmetric, {4, 8, 16, 32}, 2.0, 1.0},
        RateCase{ElementType::Q8, AnalysisType::Axisymmetric, {2, 4, 8, 16}, 3.0, 2.0}),
    rate_name);

}  // namespace
}  // namespace cs::solver::test_fe_manufactured
