// The similarity transformation of a model (solver/model_scaling.hpp), one rule at a time: a
// distorted Q8 block loaded by ONE kind of load (or driven by one prescribed displacement), in
// plane strain and in axisymmetry, solved as built and scaled by (L, S); the scaled model's
// displacement must be L times the original's and its nodal stresses S times, node by node.
// A rule left out (e.g. a point force scaled by S only) leaves the load of that case off by a
// factor L and fails it. The rigid profiles' lengths are checked against their gap function.

#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "solver/contact/rigid_profile.hpp"
#include "solver/linear_static.hpp"
#include "solver/model_error.hpp"
#include "solver/model_scaling.hpp"
#include "solver/stress_recovery.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

namespace cs::solver {
namespace {

using Eigen::Vector2d;

enum class Drive { Traction, Pressure, PointForce, BodyForce, PrescribedDisplacement };

struct ScalingCase {
  Drive drive;
  AnalysisType analysis;
  std::string name;
};

/// The block 0.5 < x < 1.5, 0 < z < 1 (off the axis in axisymmetry), interior distorted; the
/// bottom held in z, the bottom-left node in x; loaded (or driven) by `drive` alone, with
/// fields that vary in space so that a field read at x' instead of x' / L is wrong too.
Model driven_block(Drive drive, AnalysisType analysis) {
  Model model;
  model.mesh = test::block(ElementType::Q8, {0.5, 0.0}, {1.0, 1.0}, 3, 3);
  test::distort_interior(model.mesh, 0.2, 1.0 / 3.0);
  model.analysis = analysis;
  model.materials = {Material{200.0, 0.3}};
  model.fix(NodeSelection::node_set("bottom"), Component::Z);
  const int corner = model.mesh.node_sets.at("bottom").front();
  switch (drive) {
    case Drive::Traction:
      model.loads.add_traction(
          "right", [](const Vector2d& x) { return Vector2d(-1.0 - x.y(), 0.5 * x.y() * x.y()); });
      break;
    case Drive::Pressure:
      model.loads.add_pressure("top", [](const Vector2d& x) { return 2.0 + x.x() * x.x(); });
      break;
    case Drive::PointForce:
      model.loads.add_point_force(NodeSelection::node_set("top"), Vector2d(0.3, -1.0));
      break;
    case Drive::BodyForce:
      model.loads.add_body_force([](const Vector2d& x) { return Vector2d(x.y(), -1.0 - x.x()); });
      break;
    case Drive::PrescribedDisplacement:
      model.prescribe(NodeSelection::node_set("top"), Component::Z,
                      [](const Vector2d& x) { return -1e-3 * (1.0 + x.x() * x.x()); });
      break;
  }
  model.fix(NodeSelection::list({corner}, "bottom-left corner"), Component::X);
  return model;
}

void PrintTo(const ScalingCase& c, std::ostream* os) {
  *os << c.name;
}

class ModelScalingRule : public ::testing::TestWithParam<ScalingCase> {};

// Requirement: with every length times L and moduli and loads times S, the displacement is L
// times and the nodal stress S times the original's, at every node, for each kind of load
// alone, to 1e-10 of the largest value (round-off of a well-conditioned 80-DOF solve; the
// factors are not powers of two, so the scaled model is not bit-identical).
TEST_P(ModelScalingRule, DisplacementsScaleWithLAndStressesWithS) {
  const Model model = driven_block(GetParam().drive, GetParam().analysis);
  const LinearStaticResult base = solve_linear_static(model);
  ASSERT_TRUE(base.ok()) << base.outcome.reason;
  const StressField base_stress = recover_stresses(model, base.displacement);
  for (const ModelScaling s : {ModelScaling{1e3, 2.1e5}, ModelScaling{1e-3, 7e10}}) {
    const Model big = scaled(model, s);
    const LinearStaticResult r = solve_linear_static(big);
    ASSERT_TRUE(r.ok()) << r.outcome.reason;
    const StressField stress = recover_stresses(big, r.displacement);
    const double u_scale = test::max_abs(base.displacement);
    double sigma_scale = 0.0;
    for (int n = 0; n < model.mesh.n_nodes(); ++n)
      sigma_scale = std::max(sigma_scale, base_stress.at_node(n).vector().cwiseAbs().maxCoeff());
    ASSERT_GT(u_scale, 0.0);
    const testing::Tolerance u_tol{0.0, 1e-10 * u_scale};
    const testing::Tolerance sigma_tol{0.0, 1e-10 * sigma_scale};
    for (int n = 0; n < model.mesh.n_nodes(); ++n) {
      ASSERT_NE(big.mesh.nodes[n].x(), model.mesh.nodes[n].x());  // the model did change
      for (int c = 0; c < 2; ++c) {
        ASSERT_TRUE(testing::Near(r.displacement[2 * n + c] / s.length_L,
                                  base.displacement[2 * n + c], u_tol))
            << "node " << n << " component " << c << " L = " << s.length_L;
      }
      const Eigen::Vector4d expected = base_stress.at_node(n).vector();
      const Eigen::Vector4d actual = stress.at_node(n).vector() / s.stress_S;
      for (int k = 0; k < 4; ++k) {
        ASSERT_TRUE(testing::Near(actual[k], expected[k], sigma_tol))
            << "node " << n << " stress component " << k << " S = " << s.stress_S;
      }
    }
  }
}

std::vector<ScalingCase> scaling_cases() {
  std::vector<ScalingCase> out;
  const std::pair<Drive, const char*> drives[] = {{Drive::Traction, "Traction"},
                                                  {Drive::Pressure, "Pressure"},
                                                  {Drive::PointForce, "PointForce"},
                                                  {Drive::BodyForce, "BodyForce"},
                                                  {Drive::PrescribedDisplacement, "Prescribed"}};
  for (const auto& [drive, name] : drives) {
    out.push_back({drive, AnalysisType::PlaneStrain, fmt::format("{}Plane", name)});
    out.push_back({drive, AnalysisType::Axisymmetric, fmt::format("{}Axi", name)});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryLoad, ModelScalingRule, ::testing::ValuesIn(scaling_cases()),
                         [](const auto& info) { return info.param.name; });

// Requirement: a factor that is zero, negative, infinite or NaN is refused with one line naming
// the factor.
TEST(ModelScaling, RefusesFactorsThatAreNotPositiveAndFinite) {
  const Model model = driven_block(Drive::Pressure, AnalysisType::PlaneStrain);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {0.0, -1.0, nan, inf}) {
    for (const auto& [s, name] : {std::pair{ModelScaling{bad, 1.0}, "length factor L"},
                                  std::pair{ModelScaling{1.0, bad}, "stress factor S"}}) {
      try {
        (void)scaled(model, s);
        ADD_FAILURE() << name << " = " << bad << " accepted";
      } catch (const ModelError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(name), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      }
    }
  }
}

// Requirement: a rigid profile with its lengths scaled by L has, at L x, L times the gap of the
// original at x, the same normal and L times its closest point (to round-off), for every
// profile kind; points on every branch of each profile (faces, arcs, corners, sides).
TEST(ModelScaling, RigidProfileGapsScaleWithL) {
  const RigidProfile profiles[] = {
      RigidPlane{{0.2, -0.1}, {0.0, 1.0}},
      RigidCircle{{0.0, -3.0}, 3.0},
      RoundedFlatPunch{{0.0, 0.0}, {0.0, 1.0}, 1.0, 1.0 / 3.0},
      SharpFlatPunch{{0.0, 0.0}, {0.0, 1.0}, 1.0},
  };
  const Vector2d points[] = {{0.0, 0.05}, {0.9, 0.02}, {1.1, -0.05}, {1.3, -0.4}, {2.0, 0.1}};
  const double L = 1e-3;
  for (const RigidProfile& profile : profiles) {
    const RigidProfile small = scale_lengths(profile, L);
    for (const Vector2d& x : points) {
      const ProfilePoint a = closest_point(profile, x), b = closest_point(small, L * x);
      const std::string where = fmt::format("{} at ({}, {})", describe(profile), x.x(), x.y());
      EXPECT_TRUE(testing::Near(b.gap / L, a.gap, {1e-12, 1e-15})) << where;  // round-off
      EXPECT_TRUE(testing::Near(b.normal.x(), a.normal.x(), {0.0, 1e-12})) << where;
      EXPECT_TRUE(testing::Near(b.normal.y(), a.normal.y(), {0.0, 1e-12})) << where;
      EXPECT_TRUE(testing::Near(b.closest.x() / L, a.closest.x(), {1e-12, 1e-15})) << where;
      EXPECT_TRUE(testing::Near(b.closest.y() / L, a.closest.y(), {1e-12, 1e-15})) << where;
    }
  }
}

}  // namespace
}  // namespace cs::solver
