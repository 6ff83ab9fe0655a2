// A Signorini problem with a known solution: an elastic column (nu = 0, so its fields do not
// depend on x) under a uniform body force q pulling it towards a rigid plane a gap delta below
// its base, hanging from its top z = H (held in z) or floating.
//
// Exact (E u'' = q, u_z(H) = 0):
//   open   (delta > sag = q H^2 / (2E)): base gap delta - sag, no pressure;
//   closed (delta < sag):                base on the plane, pressure q H / 2 - E delta / H;
//   floating (no support at the top):    base on the plane, pressure q H (the whole weight).
// The discrete solutions are nodally exact (Q4 and Q8), so Lagrange multipliers must reproduce
// them to round-off, for every discretization, in plane strain and axisymmetry.

#include <cstdio>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using cs::testing::Near;

struct SignoriniCase {
  ElementType type;
  AnalysisType analysis;
  ContactDiscretization discretization;
};

constexpr double kE = 1000.0, kH = 2.0, kWidth = 1.0, kQ = 3.0;

Model column(const SignoriniCase& c, bool hanging) {
  Model model;
  model.mesh =
      merge_bodies({contact_test::block_mesh(c.type, 0.0, 0.0, kWidth, kH, 3, 6, "column")});
  model.analysis = c.analysis;
  model.materials.push_back({kE, 0.0});
  model.fix(NodeSelection::node_set("column.left"), Component::X);
  if (hanging)
    model.fix(NodeSelection::node_set("column.top"), Component::Z);
  model.loads.add_body_force(constant_field(Eigen::Vector2d(0.0, -kQ)));
  return model;
}

ContactResult solve_column(const SignoriniCase& c, bool hanging, double delta) {
  const Model model = column(c, hanging);
  ContactSettings s =
      contact_test::settings(c.discretization, ContactAlgorithm::LagrangeMultiplier);
  s.pinball = 100.0;  // the plane may start far below the base
  return solve_contact(model, {"column.bottom", RigidPlane{{0.0, -delta}, {0.0, 1.0}}}, s);
}

class ContactSignoriniTest : public ::testing::TestWithParam<SignoriniCase> {};

TEST_P(ContactSignoriniTest, OpenHangingColumn) {
  const double sag = kQ * kH * kH / (2.0 * kE);
  const double delta = 1.5 * sag;
  const ContactResult r = solve_column(GetParam(), true, delta);
  ASSERT_TRUE(r.converged()) << r.reason;
  for (const ContactNodeResult& n : r.nodes) {
    EXPECT_FALSE(n.closed);
    EXPECT_EQ(n.pressure, 0.0);
    EXPECT_TRUE(Near(n.gap, delta - sag, {1e-10, 0.0}));  // round-off
  }
}

TEST_P(ContactSignoriniTest, ClosedHangingColumn) {
  const double sag = kQ * kH * kH / (2.0 * kE);
  const double delta = 0.4 * sag;
  const ContactResult r = solve_column(GetParam(), true, delta);
  ASSERT_TRUE(r.converged()) << r.reason;
  const double p = kQ * kH / 2.0 - kE * delta / kH;
  for (const ContactNodeResult& n : r.nodes) {
    EXPECT_TRUE(n.closed);
    EXPECT_TRUE(Near(n.pressure, p, {1e-10, 0.0}));       // round-off
    EXPECT_TRUE(Near(n.gap, 0.0, {0.0, 1e-12 * delta}));  // zero penetration
  }
}

TEST_P(ContactSignoriniTest, FloatingColumnFallsOntoThePlane) {
  const double delta = 0.01;
  const ContactResult r = solve_column(GetParam(), false, delta);
  ASSERT_TRUE(r.converged()) << r.reason;
  for (const ContactNodeResult& n : r.nodes) {
    EXPECT_TRUE(n.closed);
    EXPECT_TRUE(Near(n.pressure, kQ * kH, {1e-10, 0.0}));  // round-off
    EXPECT_TRUE(Near(r.displacement[2 * n.node + 1], -delta, {1e-10, 0.0}));
  }
}

TEST_P(ContactSignoriniTest, ChangedSupportAndLoadReuseTheFactorization) {
  // One ContactAnalysis, the top moved and the load doubled in between: the answer equals a
  // fresh analysis, and the factorization is reused (only loads and gaps change).
  const double sag = kQ * kH * kH / (2.0 * kE);
  Model model = column(GetParam(), true);
  ContactSettings s =
      contact_test::settings(GetParam().discretization, ContactAlgorithm::LagrangeMultiplier);
  s.pinball = 100.0;
  const ContactPair pair{"column.bottom", RigidPlane{{0.0, -0.6 * sag}, {0.0, 1.0}}};
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, pair);
  const ContactResult first = contact.solve(s);  // closed: 0.6 sag < sag
  ASSERT_TRUE(first.converged()) << first.reason;
  for (PrescribedDisplacement& p : model.prescribed) {
    if (p.component == Component::Z)
      p.value = constant_field(0.5 * sag);  // top moves up
  }
  model.loads.body_forces[0].force_density = constant_field(Eigen::Vector2d(0.0, -2.0 * kQ));
  elastic.update_prescribed_values();
  const ContactResult second = contact.solve(s);
  ASSERT_TRUE(second.converged()) << second.reason;
  EXPECT_TRUE(second.timings.condensation_reused);
  const ContactResult fresh = solve_contact(model, pair, s);
  ASSERT_TRUE(fresh.converged()) << fresh.reason;
  EXPECT_LE((second.displacement - fresh.displacement).norm(),
            1e-12 * fresh.displacement.norm());  // round-off
  // Exact: u(H) = sag / 2, u(0) = -0.6 sag with the load 2q: p = 2q H / 2 - E (1.1 sag) / H.
  const double p = kQ * kH - kE * 1.1 * sag / kH;
  for (const ContactNodeResult& n : second.nodes) {
    EXPECT_TRUE(Near(n.pressure, p, {1e-10, 0.0}));
  }
}

INSTANTIATE_TEST_SUITE_P(
    All, ContactSignoriniTest,
    ::testing::Values(
        SignoriniCase{ElementType::Q4, AnalysisType::PlaneStrain,
                      ContactDiscretization::NodeToSurface},
        SignoriniCase{ElementType::Q8, AnalysisType::PlaneStrain,
                      ContactDiscretization::SurfaceToSurface},
        SignoriniCase{ElementType::Q4, AnalysisType::Axisymmetric, ContactDiscretization::Mortar},
        SignoriniCase{ElementType::Q8, AnalysisType::Axisymmetric,
                      ContactDiscretization::NodeToSurface},
        SignoriniCase{ElementType::Q8, AnalysisType::PlaneStrain, ContactDiscretization::Mortar}),
    [](const auto& info) {
      return std::string(info.param.type == ElementType::Q4 ? "Q4_" : "Q8_") +
             (info.param.analysis == AnalysisType::PlaneStrain ? "plane_" : "axi_") +
             to_string(info.param.discretization);
    });

}  // namespace
}  // namespace cs::solver
