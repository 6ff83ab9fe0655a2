// Stress recovery: the method is recorded, nodal averaging never crosses bodies, stresses along
// a surface come in path order, and surface paths follow their edge sets.

#include <cmath>
#include <string>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "solver/linear_static.hpp"
#include "solver/stress_recovery.hpp"
#include "solver/surface_path.hpp"
#include "support/tolerance.hpp"
#include "test_fe_support.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_fe_stress_recovery {
namespace {

using cs::testing::Near;

constexpr double kNu = 0.3;
constexpr double kEpsX = 1e-3;
constexpr double kEpsZ = -kNu / (1.0 - kNu) * kEpsX;  // sigma_z = 0 in plane strain

/// A 4 x 4 block whose lower half is body "soft" (E = 1) and upper half "stiff" (E = 1000),
/// bonded (the interface nodes are shared), under the uniform strain of uniaxial stress
/// sigma_x prescribed on its boundary: equilibrium holds across the interface (sigma_z =
/// tau_xz = 0 in both bodies) while sigma_x jumps by the ratio of the moduli.
Model bonded_bimaterial(ElementType type, double stiff_E = 1000.0) {
  Model model;
  model.mesh = test::block(type, {0, 0}, {1, 1}, 4, 4, "soft");
  model.mesh.body_names = {"soft", "stiff"};
  for (int e = 0; e < model.mesh.n_elements(); ++e) {
    model.mesh.element_body[e] = e >= 8 ? 1 : 0;  // rows 2, 3 (z > 0.5)
  }
  model.materials = {{1.0, kNu}, {stiff_E, kNu}};
  for (const char* edge : {"left", "right", "bottom", "top"}) {
    model.prescribe(NodeSelection::node_set(edge), Component::X,
                    [](const Eigen::Vector2d& x) { return kEpsX * x.x(); });
    model.prescribe(NodeSelection::node_set(edge), Component::Z,
                    [](const Eigen::Vector2d& x) { return kEpsZ * x.y(); });
  }
  return model;
}

// Requirement: nodes shared by two bodies get one nodal stress per body (no averaging across
// bodies): each equals that body's exact stress D_b eps, also with the study's stiffness
// ratio of indenter to block, 1e6.
TEST(FeStressRecovery, NoAveragingAcrossBodies) {
  for (const auto& [type, stiff_E] :
       {std::pair{ElementType::Q4, 1e3}, std::pair{ElementType::Q8, 1e3},
        std::pair{ElementType::Q4, 1e6}, std::pair{ElementType::Q8, 1e6}}) {
    const Model model = bonded_bimaterial(type, stiff_E);
    const LinearStaticResult r = solve_linear_static(model);
    ASSERT_TRUE(r.ok()) << r.outcome.reason;
    const StressField field = recover_stresses(model, r.displacement);
    EXPECT_EQ(field.method, StressRecoveryMethod::ExtrapolatedAveraged);
    const Eigen::Vector4d eps(kEpsX, kEpsZ, 0.0, 0.0);
    int shared = 0;
    for (int n = 0; n < model.mesh.n_nodes(); ++n) {
      for (int b = 0; b < 2; ++b) {
        if (!field.has_node(n, b))
          continue;
        const Eigen::Vector4d exact = elasticity_matrix(model.materials[b]) * eps;
        for (int c = 0; c < 4; ++c) {
          // uniform strain: exact to machine precision (the patch tests' 1e-10; observed
          // below 1e-12 even at the ratio 1e6), relative to the body's stress
          EXPECT_TRUE(Near(field.at_node(n, b).vector()[c], exact[c],
                           {0.0, 1e-10 * exact.cwiseAbs().maxCoeff()}));
        }
      }
      if (field.has_node(n, 0) && field.has_node(n, 1)) {
        ++shared;
        EXPECT_THROW(field.at_node(n), std::out_of_range);
      }
    }
    EXPECT_EQ(shared, type == ElementType::Q4 ? 5 : 9);  // the interface z = 0.5
  }
}

// Requirement: stresses along an edge set come ordered by arc length, from the end with the
// smaller x: nodal values for ExtrapolatedAveraged, one Gauss row per side for GaussPoint.
TEST(FeStressRecovery, AlongASurfaceInPathOrder) {
  Model model;
  model.mesh = test::block(ElementType::Q8, {0, 0}, {3, 1}, 6, 2);
  model.materials = {{10.0, 0.25}};
  model.fix(NodeSelection::node_set("bottom"), Component::Z);
  model.fix(NodeSelection::node_set("left"), Component::X);
  model.loads.add_pressure("top", [](const Eigen::Vector2d& x) { return 1.0 + x.x(); });
  const LinearStaticResult r = solve_linear_static(model);
  ASSERT_TRUE(r.ok());

  const StressField nodal = recover_stresses(model, r.displacement);
  const auto top = surface_stresses(model, nodal, "top");
  ASSERT_EQ(top.size(), 13u);  // 6 Q8 sides: 7 corners + 6 mid-side nodes
  for (std::size_t i = 0; i < top.size(); ++i) {
    EXPECT_TRUE(Near(top[i].position.x(), 0.25 * i, {0.0, 1e-12}));  // exact node positions
    EXPECT_TRUE(Near(top[i].arc_length, 0.25 * i, {0.0, 1e-12}));
    EXPECT_GE(top[i].node, 0);
    // the normal stress at the surface follows the applied pressure (within the extrapolation
    // error of a coarse mesh)
    EXPECT_TRUE(Near(top[i].stress.sigma_z, -(1.0 + top[i].position.x()), {0.1, 0.0}));
  }

  const StressField gauss =
      recover_stresses(model, r.displacement, {StressRecoveryMethod::GaussPoint});
  EXPECT_EQ(gauss.method, StressRecoveryMethod::GaussPoint);
  EXPECT_EQ(gauss.gauss_points.size(), 12u * 9u);
  EXPECT_THROW(gauss.at_node(0), std::out_of_range);
  const auto row = surface_stresses(model, gauss, "top");
  ASSERT_EQ(row.size(), 6u * 3u);  // the 3 Gauss points nearest each side
  for (std::size_t i = 1; i < row.size(); ++i) {
    EXPECT_GT(row[i].arc_length, row[i - 1].arc_length);
    EXPECT_GT(row[i].position.x(), row[i - 1].position.x());
    EXPECT_EQ(row[i].node, -1);
  }
}

// Requirement: recovering one surface alone (recover_surface_stresses) gives exactly the values,
// bit for bit, that the whole-mesh recovery gives on that surface, for every method and element,
// on surfaces inside one body and across two (a two-body block under a displacement no patch
// polynomial fits, so every patch, boundary rule and average is exercised). Exact equality, no
// tolerance: the restricted recovery must add the same terms in the same order.
TEST(FeStressRecovery, OneSurfaceAloneMatchesTheWholeField) {
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    Model model;
    model.mesh = test::block(type, {0, 0}, {2, 1}, 8, 6, "soft");
    model.mesh.body_names = {"soft", "stiff"};
    for (int e = 0; e < model.mesh.n_elements(); ++e)
      model.mesh.element_body[e] = e >= 24 ? 1 : 0;  // rows 3 to 5
    model.materials = {{1.0, kNu}, {50.0, 0.2}};
    Eigen::VectorXd u(2 * model.mesh.n_nodes());
    for (int n = 0; n < model.mesh.n_nodes(); ++n) {
      const Eigen::Vector2d& x = model.mesh.nodes[n];
      u.segment<2>(2 * n) << std::sin(1.3 * x.x() + x.y() * x.y()), std::cos(2.0 * x.x() * x.y());
    }
    for (StressRecoveryMethod method :
         {StressRecoveryMethod::ExtrapolatedAveraged, StressRecoveryMethod::PatchRecovered,
          StressRecoveryMethod::GaussPoint}) {
      for (Q8Extrapolation rule : {Q8Extrapolation::Reduced2x2, Q8Extrapolation::Full3x3}) {
        const StressRecoveryOptions options{method, rule};
        const StressField whole = recover_stresses(model, u, options);
        for (const std::string edge : {"top", "bottom", "left", "right"}) {
          const auto expected = surface_stresses(model, whole, edge);
          const auto got = recover_surface_stresses(model, u, options, edge);
          const std::string what = fmt::format("{} {} {} {}", static_cast<int>(type),
                                               to_string(method), to_string(rule), edge);
          ASSERT_EQ(got.size(), expected.size()) << what;
          for (std::size_t i = 0; i < got.size(); ++i) {
            EXPECT_EQ(got[i].node, expected[i].node) << what;
            EXPECT_EQ(got[i].element, expected[i].element) << what;
            EXPECT_EQ(got[i].body, expected[i].body) << what;
            EXPECT_EQ(got[i].arc_length, expected[i].arc_length) << what;
            EXPECT_TRUE(got[i].stress.vector() == expected[i].stress.vector()) << what << " " << i;
          }
        }
      }
    }
  }
}

// Requirement: surface paths follow chains, open (from the smaller end) or closed, and fall
// back to sorting for sets that are not one chain.
TEST(FeSurfacePath, ChainsLoopsAndFallback) {
  Mesh mesh = test::block(ElementType::Q4, {0, 0}, {2, 1}, 2, 1);
  const SurfacePath top = surface_path(mesh, "top");  // sides run right to left
  EXPECT_TRUE(top.is_chain);
  EXPECT_FALSE(top.closed);
  ASSERT_EQ(top.nodes.size(), 3u);
  EXPECT_EQ(top.positions.front().x(), 0.0);
  EXPECT_EQ(top.positions.back().x(), 2.0);
  EXPECT_TRUE(top.reversed[0]);

  auto& loop = mesh.edge_sets["boundary"];
  for (const char* edge : {"bottom", "right", "top", "left"}) {
    loop.insert(loop.end(), mesh.edge_sets.at(edge).begin(), mesh.edge_sets.at(edge).end());
  }
  const SurfacePath closed = surface_path(mesh, "boundary");
  EXPECT_TRUE(closed.is_chain);
  EXPECT_TRUE(closed.closed);
  EXPECT_EQ(closed.nodes.size(), 6u);
  EXPECT_TRUE(Near(closed.arc_length.back(), 5.0, {1e-14, 0.0}));  // 6 minus the closing side

  mesh.edge_sets["two pieces"] = {mesh.edge_sets.at("left")[0], mesh.edge_sets.at("right")[0]};
  const SurfacePath pieces = surface_path(mesh, "two pieces");
  EXPECT_FALSE(pieces.is_chain);
  EXPECT_EQ(pieces.nodes.size(), 4u);
  EXPECT_EQ(pieces.positions.front().x(), 0.0);
  EXPECT_EQ(pieces.positions.back().x(), 2.0);
}

}  // namespace
}  // namespace cs::solver::test_fe_stress_recovery
