// The multiplier basis of weighted-gap rows (mortar; surface-to-surface with Lagrange multipliers
// or MPC): a row's weighted gap must measure penetration and its multiplier must be a force.
//
// Requirement: on an axisymmetric Q8 contact surface, (1) every weighted row's multiplier
// transmits itself as net normal force (the B row sums to 1 over the contact side's normal
// DOFs), including the corner node on the axis, whose Lagrange function has int N r dr = 0;
// (2) a surface that nowhere penetrates its target has no negative weighted gap, including the
// row at the end of a target beyond which the gap grows (int N_c g r dr < 0 there for the sign-
// changing Lagrange corner function); (3) the nodal contact forces of a solve sum to the load.
// Tolerances are round-off: each statement is exact for the discrete rows.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using contact_test::PatchSpec;
using cs::testing::Near;

/// The rows a discretization and Lagrange multipliers produce for `pair` on `model`.
const ConstraintSet& weighted_rows(ContactAnalysis& contact, ContactDiscretization d) {
  return contact.constraints(
      constraint_rows(contact_test::settings(d, ContactAlgorithm::LagrangeMultiplier)));
}

class MultiplierBasisTest : public ::testing::TestWithParam<ContactDiscretization> {};

TEST_P(MultiplierBasisTest, EveryMultiplierTransmitsItselfAsNetForce) {
  // An axisymmetric Q8 block on a rigid plane: the normal is +z everywhere, so a unit
  // multiplier of row j puts sum_b B(j, z_b) on the block's z DOFs.
  PatchSpec spec;
  spec.type = ElementType::Q8;
  spec.analysis = AnalysisType::Axisymmetric;
  const Model model = contact_test::patch_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::patch_pair(spec));
  const ConstraintSet& set = weighted_rows(contact, GetParam());
  ASSERT_TRUE(set.weighted);
  for (int j = 0; j < set.n_rows(); ++j) {
    double net = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(set.B, j); it; ++it)
      if (it.col() % 2 == 1)
        net += it.value();
    EXPECT_TRUE(Near(net, 1.0, {1e-12, 0.0}))  // round-off
        << "row " << j << " at r = " << set.rows[j].position.x() << " transmits " << net;
  }
}

TEST_P(MultiplierBasisTest, NoNegativeWeightedGapWithoutPenetration) {
  // The axisymmetric Q8 surface z = 0, 0 < r < 1 (4 elements), touching a rigid flat punch of
  // half-width 0.5 (a node): the gap is 0 on the punch and the distance to its corner beyond.
  PatchSpec spec;
  spec.type = ElementType::Q8;
  spec.analysis = AnalysisType::Axisymmetric;
  const Model model = contact_test::patch_model(spec);
  LinearStaticAnalysis elastic(model);
  const ContactPair pair{"block.bottom", SharpFlatPunch{{0.0, 0.0}, {0.0, 1.0}, 0.5}};
  ContactAnalysis contact(elastic, pair);
  const ConstraintSet& set = weighted_rows(contact, GetParam());
  for (int j = 0; j < set.n_rows(); ++j) {
    EXPECT_GE(set.g0[j], -1e-15)  // round-off of a zero gap
        << "row at r = " << set.rows[j].position.x() << ": weighted gap " << set.g0[j];
  }
}

TEST_P(MultiplierBasisTest, NodalForcesCarryTheLoadOnTheAxis) {
  // The patch test P_a with Q8: uniform p on 0 < r < a, so the interface carries p a^2 / 2 per
  // radian; the nodes' forces must sum to it (the axis node included).
  PatchSpec spec;
  spec.type = ElementType::Q8;
  spec.analysis = AnalysisType::Axisymmetric;
  const Model model = contact_test::patch_model(spec);
  for (ContactAlgorithm algorithm :
       {ContactAlgorithm::LagrangeMultiplier, ContactAlgorithm::Penalty}) {
    const ContactResult r = solve_contact(model, contact_test::patch_pair(spec),
                                          contact_test::settings(GetParam(), algorithm));
    ASSERT_TRUE(r.converged()) << r.reason;
    const double load = spec.p * spec.a * spec.a / 2.0;
    std::printf("[ info     ] %s %s: sum of nodal forces / load - 1 = %.2e\n",
                to_string(GetParam()), to_string(algorithm), r.total_normal_force / load - 1.0);
    EXPECT_TRUE(Near(r.total_normal_force, load, {1e-10, 0.0}));  // round-off
  }
}

INSTANTIATE_TEST_SUITE_P(WeightedRows, MultiplierBasisTest,
                         ::testing::Values(ContactDiscretization::Mortar,
                                           ContactDiscretization::SurfaceToSurface),
                         [](const ::testing::TestParamInfo<ContactDiscretization>& info) {
                           return std::string(info.param == ContactDiscretization::Mortar ? "mortar"
                                                                                          : "ss");
                         });

}  // namespace
}  // namespace cs::solver
