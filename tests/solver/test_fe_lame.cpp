// Lame's thick-walled cylinder under internal pressure, axisymmetric and plane strain: the
// displacements and the nodal (extrapolated, averaged) stresses converge to the exact ones at
// their observed rates.
//
// Inner radius a = 1, outer b = 2, internal pressure p = 1, E = 1000, nu = 0.3, no axial
// strain (plane strain; in the axisymmetric model u_z = 0 on both ends of the slice). Exact
// (Timoshenko & Goodier, Theory of Elasticity, sec. 28):
//   sigma_r = A - B / r^2, sigma_theta = A + B / r^2, sigma_z = nu (sigma_r + sigma_theta),
//   A = p a^2 / (b^2 - a^2), B = p a^2 b^2 / (b^2 - a^2),
//   u_r = (1 + nu) / E ((1 - 2 nu) A r + B / r).
// Axisymmetric model: the (r, z) slice [a, b] x [0, 0.25], n x 2 elements (two rows, so that
// patch recovery has interior nodes), pressure on "left".
// Plane strain model: a quarter annulus (mapped block, n radial x 2n circumferential), u_z = 0
// on the x axis, u_x = 0 on the z axis, pressure on the inner arc.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "solver/linear_static.hpp"
#include "solver/stress_recovery.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_fe_lame {
namespace {

using cs::testing::Near;

constexpr double kInner = 1.0, kOuter = 2.0, kPressure = 1.0, kE = 1000.0, kNu = 0.3;
constexpr double kA = kPressure * kInner * kInner / (kOuter * kOuter - kInner * kInner);
constexpr double kBB = kA * kOuter * kOuter;

double sigma_r(double r) {
  return kA - kBB / (r * r);
}
double sigma_theta(double r) {
  return kA + kBB / (r * r);
}
double u_r(double r) {
  return (1 + kNu) / kE * ((1 - 2 * kNu) * kA * r + kBB / r);
}

Model lame_model(ElementType type, AnalysisType analysis, int n) {
  Model model;
  model.analysis = analysis;
  model.materials = {{kE, kNu}};
  if (analysis == AnalysisType::Axisymmetric) {
    model.mesh = test::block(type, {kInner, 0.0}, {kOuter - kInner, 0.25}, n, 2, "cylinder");
    model.fix(NodeSelection::node_set("bottom"), Component::Z);
    model.fix(NodeSelection::node_set("top"), Component::Z);
  } else {
    MappedBlockSpec spec;
    spec.type = type;
    spec.u = uniform_coordinates(n);
    spec.v = uniform_coordinates(2 * n);
    spec.map = [](double u, double v) {
      const double r = kInner + u * (kOuter - kInner);
      const double theta = 0.5 * std::numbers::pi * v;
      return Eigen::Vector2d(r * std::cos(theta), r * std::sin(theta));
    };
    spec.body_name = "cylinder";
    model.mesh = make_mapped_block(spec);
    model.fix(NodeSelection::node_set("bottom"), Component::Z);  // theta = 0: the x axis
    model.fix(NodeSelection::node_set("top"), Component::X);     // theta = 90 deg: the z axis
  }
  model.loads.add_pressure("left", kPressure);
  return model;
}

struct LameErrors {
  double u = 0.0;       ///< max relative error of u_r over all nodes
  double stress = 0.0;  ///< max error of nodal sigma_r, sigma_theta, sigma_z over the inner
                        ///< surface, relative to the peak sigma_theta(a)
};

LameErrors measure(ElementType type, AnalysisType analysis, int n, StressRecoveryMethod method,
                   Q8Extrapolation rule) {
  const Model model = lame_model(type, analysis, n);
  const LinearStaticResult result = solve_linear_static(model);
  EXPECT_TRUE(result.ok()) << result.outcome.reason;
  LameErrors err;
  for (int node = 0; node < model.mesh.n_nodes(); ++node) {
    const Eigen::Vector2d x = model.mesh.nodes[node];
    const double r = analysis == AnalysisType::Axisymmetric ? x.x() : x.norm();
    const Eigen::Vector2d u = result.displacement_at(node);
    const double ur = analysis == AnalysisType::Axisymmetric ? u.x() : u.dot(x) / r;
    err.u = std::max(err.u, std::abs(ur - u_r(r)) / u_r(kInner));
  }
  const StressField field = recover_stresses(model, result.displacement, {method, rule});
  const double peak = sigma_theta(kInner);
  for (const SurfaceStressSample& s : surface_stresses(model, field, "left")) {
    double sr = s.stress.sigma_x, st = s.stress.sigma_out;
    if (analysis == AnalysisType::PlaneStrain) {
      // polar components from the Cartesian ones
      const double c = s.position.x() / kInner, z = s.position.y() / kInner;
      sr = c * c * s.stress.sigma_x + z * z * s.stress.sigma_z + 2 * c * z * s.stress.tau_xz;
      st = z * z * s.stress.sigma_x + c * c * s.stress.sigma_z - 2 * c * z * s.stress.tau_xz;
    }
    const double s_axial =
        analysis == AnalysisType::Axisymmetric ? s.stress.sigma_z : s.stress.sigma_out;
    err.stress = std::max({err.stress, std::abs(sr - sigma_r(kInner)) / peak,
                           std::abs(st - sigma_theta(kInner)) / peak,
                           std::abs(s_axial - 2 * kNu * kA) / peak});
  }
  return err;
}

struct LameCase {
  ElementType type;
  AnalysisType analysis;
  StressRecoveryMethod method;
  Q8Extrapolation rule;     ///< for ExtrapolatedAveraged
  double min_stress_order;  ///< lower bound on the observed order of the surface stress error
  double max_fine_error;    ///< bound on the finest mesh's surface stress error
};

void PrintTo(const LameCase& c, std::ostream* os) {
  *os << (c.type == ElementType::Q4 ? "Q4 " : "Q8 ") << to_string(c.analysis) << " "
      << to_string(c.method) << " " << to_string(c.rule);
}

constexpr auto kExtrapolated = StressRecoveryMethod::ExtrapolatedAveraged;
constexpr auto kPatch = StressRecoveryMethod::PatchRecovered;

class FeLameCylinder : public ::testing::TestWithParam<LameCase> {};

// Requirement: displacements and inner-surface nodal stresses converge to Lame's solution, at
// observed orders (fitted over n = 4, 8, 16, 32 radial elements) of at least p + 1 for the
// nodal displacement (observed: 2 for Q4, 4 for Q8: nodal superconvergence) and about p for
// the nodal stresses on the loaded surface, to small errors on the finest mesh.
TEST_P(FeLameCylinder, ConvergesToExactStresses) {
  const LameCase& c = GetParam();
  std::vector<double> h, eu, es;
  for (int n : {4, 8, 16, 32}) {
    const LameErrors e = measure(c.type, c.analysis, n, c.method, c.rule);
    h.push_back(1.0 / n);
    eu.push_back(e.u);
    es.push_back(e.stress);
  }
  const double p = c.type == ElementType::Q4 ? 1.0 : 2.0;
  const double u_order = test::observed_order(h, eu);
  const double s_order = test::observed_order(h, es);
  std::printf(
      "    %s %s %s %s: u error %.2e -> %.2e (order %.2f); surface stress error %.2e -> "
      "%.2e (order %.2f)\n",
      c.type == ElementType::Q4 ? "Q4" : "Q8", to_string(c.analysis), to_string(c.method),
      to_string(c.rule), eu.front(), eu.back(), u_order, es.front(), es.back(), s_order);
  // nodal displacements converge at least at the L2 rate p + 1 (less 0.15 pre-asymptotic)
  EXPECT_GT(u_order, p + 1 - 0.15);
  EXPECT_GT(s_order, c.min_stress_order);
  EXPECT_LT(es.back(), c.max_fine_error);
}

std::string lame_name(const ::testing::TestParamInfo<LameCase>& info) {
  const LameCase& c = info.param;
  std::string name = std::string(c.type == ElementType::Q4 ? "Q4" : "Q8") +
                     (c.analysis == AnalysisType::PlaneStrain ? "PlaneStrain" : "Axisymmetric");
  if (c.method == StressRecoveryMethod::PatchRecovered)
    return name + "PatchRecovered";
  if (c.type == ElementType::Q8)
    name += c.rule == Q8Extrapolation::Full3x3 ? "Full3x3" : "Reduced2x2";
  return name;
}

// Bounds: Q4 nodal stresses at a loaded boundary converge at O(h) (the element's constant
// radial strain, extrapolated, misses 0.5 h |d sigma/dr|: ~2.5% of the peak at h = 1/32;
// observed order 0.91, 4.2%); Q8 at O(h^2) (observed 1.86 to 1.90, pre-asymptotic from
// n = 4; 4e-4 to 7e-4 at n = 32). Superconvergent patch recovery: Q4 at O(h^2) (observed 1.77
// to 1.86, 1.7e-3 at n = 32: 25 times smaller), Q8 at O(h^2.7) (3.6e-5 to 7.1e-5: 6 to 10
// times smaller). Order bounds leave 0.1 below the observed, error bounds 40%.
INSTANTIATE_TEST_SUITE_P(
    Q4AndQ8, FeLameCylinder,
    ::testing::Values(LameCase{ElementType::Q4, AnalysisType::Axisymmetric, kExtrapolated,
                               Q8Extrapolation::Full3x3, 0.8, 6e-2},
                      LameCase{ElementType::Q8, AnalysisType::Axisymmetric, kExtrapolated,
                               Q8Extrapolation::Full3x3, 1.75, 1e-3},
                      LameCase{ElementType::Q8, AnalysisType::Axisymmetric, kExtrapolated,
                               Q8Extrapolation::Reduced2x2, 1.75, 6e-4},
                      LameCase{ElementType::Q4, AnalysisType::PlaneStrain, kExtrapolated,
                               Q8Extrapolation::Full3x3, 0.8, 6e-2},
                      LameCase{ElementType::Q8, AnalysisType::PlaneStrain, kExtrapolated,
                               Q8Extrapolation::Full3x3, 1.75, 1e-3},
                      LameCase{ElementType::Q8, AnalysisType::PlaneStrain, kExtrapolated,
                               Q8Extrapolation::Reduced2x2, 1.75, 7e-4},
                      LameCase{ElementType::Q4, AnalysisType::Axisymmetric, kPatch,
                               Q8Extrapolation::Reduced2x2, 1.65, 2.4e-3},
                      LameCase{ElementType::Q8, AnalysisType::Axisymmetric, kPatch,
                               Q8Extrapolation::Reduced2x2, 2.55, 5e-5},
                      LameCase{ElementType::Q4, AnalysisType::PlaneStrain, kPatch,
                               Q8Extrapolation::Reduced2x2, 1.75, 2.5e-3},
                      LameCase{ElementType::Q8, AnalysisType::PlaneStrain, kPatch,
                               Q8Extrapolation::Reduced2x2, 2.55, 1e-4}),
    lame_name);

}  // namespace
}  // namespace cs::solver::test_fe_lame
