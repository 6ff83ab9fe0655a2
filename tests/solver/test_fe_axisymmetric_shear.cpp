// Why there is no axisymmetric frictional patch test (FP_a), computed: a frictional patch test
// needs a uniform state with a shear traction tau on the interface. In plane strain the uniform
// shear u_x = 0, u_z = gamma x (tau_xz = G gamma everywhere) is an equilibrium state, and the FE
// solution with those displacements prescribed on the boundary reproduces it at every interior
// node to round-off. In the r-z plane the same field u_r = 0, u_z = gamma r has the same strains
// (gamma_rz = gamma, e_theta = u_r / r = 0) but is not in equilibrium: the axial equation
// d tau_rz/dr + d sigma_z/dz + tau_rz/r = 0 leaves tau_rz / r = G gamma / r != 0, so the FE
// solution departs from it. The sliding variant (|tau| = mu p everywhere, p uniform) asks for
// the same uniform |tau_rz| = mu p > 0, which also contradicts tau_rz(0, z) = 0 on the axis
// (tau_rz is odd in r): it has no uniform exact state either.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/linear_static.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/structured_block.hpp"
#include "support/tolerance.hpp"

namespace cs::solver {
namespace {

constexpr double kGamma = 1e-3;

/// The largest |u_z - gamma x| over the interior nodes of a block 0.5 < x < 1.5 (the axisymmetric
/// block kept off the axis, where the tau/r term is finite) with u_x = 0 and u_z = gamma x
/// prescribed on its whole boundary, over gamma times the block size.
double interior_departure(AnalysisType analysis, ElementType type) {
  BlockSpec block;
  block.type = type;
  block.origin = {0.5, 0.0};
  block.size = {1.0, 1.0};
  block.nx = block.nz = 8;
  Model model;
  model.mesh = make_block(block);
  model.analysis = analysis;
  model.materials = {Material{1.0, 0.25}};
  for (const char* side : {"left", "right", "bottom", "top"}) {
    model.fix(NodeSelection::node_set(side), Component::X);
    model.prescribe(NodeSelection::node_set(side), Component::Z,
                    [](const Eigen::Vector2d& x) { return kGamma * x.x(); });
  }
  LinearStaticAnalysis fe(model);
  const LinearStaticResult r = fe.solve();
  EXPECT_TRUE(r.ok());
  double worst = 0.0;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const Eigen::Vector2d u = r.displacement_at(n);
    worst = std::max({worst, std::abs(u.x()), std::abs(u.y() - kGamma * model.mesh.nodes[n].x())});
  }
  return worst / kGamma;
}

// Requirement: the uniform shear state is reproduced in plane strain (round-off: linear fields
// are in the Q4 and Q8 spaces) and is not an axisymmetric equilibrium state (the interior moves
// by more than 1e-3 of gamma times the size: the tau/r term, G gamma / r ~ G gamma over the
// block, loads it at order one, far above round-off).
TEST(AxisymmetricShear, UniformShearIsNoEquilibriumStateInTheRzPlane) {
  for (const auto type : {ElementType::Q4, ElementType::Q8}) {
    EXPECT_LT(interior_departure(AnalysisType::PlaneStrain, type), 1e-10);
    const double axi = interior_departure(AnalysisType::Axisymmetric, type);
    EXPECT_GT(axi, 1e-3);
    RecordProperty(type == ElementType::Q4 ? "axi_departure_q4" : "axi_departure_q8",
                   std::to_string(axi));
  }
}

}  // namespace
}  // namespace cs::solver
