// The contact search (solver/contact/contact_search.hpp): a point that approaches the target
// during the iterations joins the search; a point that the reference geometry already puts
// deeper inside the target than the pinball is refused with the numbers.
//
// Requirement: with a pinball far too small for the contact zone (1e-4 h on Hertz: only the
// nodes next to x = 0 start as candidates), every algorithm except MPC converges, to the same
// solution as with a pinball that holds the whole surface from the start; a point that starts
// inside the target beyond the pinball still gets the refusal, naming the point, its starting
// gap, the pinball and its penetration.

#include <string>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_contact_search {
namespace {

using contact_test::HertzSpec;
using contact_test::PatchSpec;
using cs::testing::Near;

struct SearchCase {
  ContactDiscretization discretization;
  ContactAlgorithm algorithm;
};

std::string name(const ::testing::TestParamInfo<SearchCase>& info) {
  const char* d = info.param.discretization == ContactDiscretization::NodeToSurface ? "ns"
                  : info.param.discretization == ContactDiscretization::Mortar      ? "mortar"
                                                                                    : "ss";
  const char* a = info.param.algorithm == ContactAlgorithm::Penalty               ? "PM"
                  : info.param.algorithm == ContactAlgorithm::AugmentedLagrangian ? "AL"
                                                                                  : "LM";
  return std::string(d) + "_" + a;
}

class ContactSearchGrows : public ::testing::TestWithParam<SearchCase> {};

TEST_P(ContactSearchGrows, APointThatApproachesDuringTheIterationsJoinsTheSearch) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  ContactSettings s = contact_test::settings(GetParam().discretization, GetParam().algorithm);
  // Initial gaps grow as x^2 / 2R: a pinball of 1e-4 h keeps only the rows next to x = 0,
  // while the contact reaches x = a (4 elements): the rest begin to penetrate as the block
  // comes down.
  s.pinball = 1e-4;
  const ContactResult small = contact.solve(s);
  ASSERT_EQ(small.status, ContactStatus::Converged) << small.reason;
  s.pinball = 10.0;  // every row of the surface within reach from the start
  const ContactResult wide = contact.solve(s);
  ASSERT_EQ(wide.status, ContactStatus::Converged) << wide.reason;
  EXPECT_LT(small.n_candidates, wide.n_candidates) << "the search grew only as far as needed";
  // The same active-set system condensed over two candidate sets: equal to round-off, which
  // the 1e6 spread between the contact stiffness and the open rows' zero force leaves at 1e-9.
  const cs::testing::Tolerance roundoff{1e-9, 1e-12};
  EXPECT_TRUE(Near(small.peak_pressure, wide.peak_pressure, roundoff));
  EXPECT_TRUE(Near(small.total_normal_force, wide.total_normal_force, roundoff));
  EXPECT_TRUE(Near(small.contact_extent, wide.contact_extent, roundoff));
  ASSERT_EQ(small.displacement.size(), wide.displacement.size());
  const double scale = wide.displacement.cwiseAbs().maxCoeff();
  EXPECT_LE((small.displacement - wide.displacement).cwiseAbs().maxCoeff(), 1e-9 * scale);
}

INSTANTIATE_TEST_SUITE_P(
    Hertz, ContactSearchGrows,
    ::testing::Values(
        SearchCase{ContactDiscretization::NodeToSurface, ContactAlgorithm::Penalty},
        SearchCase{ContactDiscretization::NodeToSurface, ContactAlgorithm::AugmentedLagrangian},
        SearchCase{ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier},
        SearchCase{ContactDiscretization::SurfaceToSurface, ContactAlgorithm::Penalty},
        SearchCase{ContactDiscretization::SurfaceToSurface, ContactAlgorithm::LagrangeMultiplier},
        SearchCase{ContactDiscretization::Mortar, ContactAlgorithm::LagrangeMultiplier}),
    name);

/// The patch block (4 x 4 elements of depth h = 1/4) pressed onto a rigid plane tilted so that
/// it runs from z = 0.4 at x = 0 down to z = -0.05 at x = 1: the nodes at x = 0 and 1/4 start
/// more than one h inside the rigid side, those from x = 1/2 on within one h of the plane.
ContactResult tilted_plane_solve(ContactAlgorithm algorithm) {
  PatchSpec spec;
  const Model model = contact_test::patch_model(spec);
  const Eigen::Vector2d along(1.0, -0.45);
  const Eigen::Vector2d normal = Eigen::Vector2d(-along.y(), along.x()).normalized();
  ContactSettings s = contact_test::settings(ContactDiscretization::NodeToSurface, algorithm);
  return solve_contact(model, {"block.bottom", RigidPlane{{0.0, 0.4}, normal}}, s);
}

TEST(ContactSearch, APointStartingInsideTheTargetBeyondThePinballIsRefused) {
  for (ContactAlgorithm a : {ContactAlgorithm::Penalty, ContactAlgorithm::AugmentedLagrangian,
                             ContactAlgorithm::LagrangeMultiplier}) {
    const ContactResult r = tilted_plane_solve(a);
    EXPECT_EQ(r.status, ContactStatus::NotConverged);
    EXPECT_EQ(r.failure, ContactFailure::ContactBeyondPinball);
    // The deepest node, (0, 0), starts 0.4 cos(theta) = 0.3655 = 1.46 h inside the plane.
    EXPECT_NE(r.reason.find("(0, 0)"), std::string::npos) << r.reason;
    EXPECT_NE(r.reason.find("starts 1.46 h inside"), std::string::npos) << r.reason;
    EXPECT_NE(r.reason.find("pinball (1 h)"), std::string::npos) << r.reason;
    EXPECT_EQ(r.reason.find('\n'), std::string::npos) << "one line";
  }
}

TEST(ContactSearch, MultipointConstraintsIgnorePointsBeyondThePinball) {
  // MPC ties the rows found within the pinball at the start and nothing else, by definition
  // (solver/contact/multipoint_constraint.hpp): the tilted plane's deep nodes are not its
  // concern, and the search neither grows nor refuses.
  const ContactResult r = tilted_plane_solve(ContactAlgorithm::MultipointConstraint);
  EXPECT_EQ(r.status, ContactStatus::Converged) << r.reason;
}

}  // namespace
}  // namespace cs::solver::test_contact_search
