// Load steps (solver/contact/load_step.hpp, ContactAnalysis::solve_steps).
//
// Requirements: superpose() scales and adds load cases exactly (the external load vector of the
// sum is the sum of the scaled vectors to round-off); solve_steps() applies each step before
// solving it, returns one result per step, and stops after the first step that does not
// converge; a step's friction history is the next step's start.

#include <memory>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using cs::testing::Near;

TEST(LoadSteps, SuperposeScalesAndAddsLoadCases) {
  contact_test::HertzSpec spec;
  spec.n = 8;
  Model model = contact_test::hertz_model(spec);  // McEwen tractions on two edges
  const LoadCase a = model.loads;
  LoadCase b;
  b.add_pressure("block.top", 2.0);
  b.add_point_force(NodeSelection::node_set("block.right"), Eigen::Vector2d(0.5, -1.0));
  b.add_body_force(constant_field(Eigen::Vector2d(0.0, 3.0)));
  LinearStaticAnalysis elastic(model);
  const Eigen::VectorXd fa = elastic.external_load(a);
  const Eigen::VectorXd fb = elastic.external_load(b);
  const Eigen::VectorXd sum = elastic.external_load(superpose({{1.0, a}, {-0.25, b}}));
  const Eigen::VectorXd expected = fa - 0.25 * fb;
  for (Eigen::Index k = 0; k < sum.size(); ++k)
    EXPECT_TRUE(Near(sum[k], expected[k], {1e-14, 1e-14 * expected.cwiseAbs().maxCoeff()}));
  EXPECT_EQ(superpose({}).tractions.size(), 0u);
}

TEST(LoadSteps, StepsRunInOrderAndStopAtTheFirstFailure) {
  const contact_test::FrictionPatchSpec s;
  auto load = std::make_shared<contact_test::FrictionLoad>();
  const Model model = contact_test::friction_patch_model(s, load);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::friction_patch_pair());
  std::vector<double> applied;
  const std::vector<LoadStep> steps{
      {"p", [&] { applied.push_back(load->p = 1.0); }},
      {"tau", [&] { applied.push_back(load->tau_top = load->tau_sides = 0.1); }},
      {"more tau", [&] { applied.push_back(load->tau_top = load->tau_sides = 0.2); }},
  };
  const ContactSettings settings = contact_test::friction_settings(
      ContactDiscretization::Mortar, ContactAlgorithm::LagrangeMultiplier, 0.3,
      TangentialEnforcement::LagrangeMultiplier);
  std::vector<ContactResult> path = contact.solve_steps(settings, steps);
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(applied, (std::vector<double>{1.0, 0.1, 0.2}));
  for (const ContactResult& r : path)
    EXPECT_TRUE(r.converged()) << r.reason;
  // The third step starts from the second's state: its slip increments are measured from it.
  for (std::size_t i = 0; i < path[2].nodes.size(); ++i) {
    const ContactNodeResult& n = path[2].nodes[i];
    EXPECT_TRUE(Near(n.slip - n.slip_increment, path[1].nodes[i].slip, {1e-12, 1e-20}));
  }
  // A shear above mu p on a block held in x by friction alone has no equilibrium: the second
  // step cannot converge, and the third is not run.
  *load = {};
  applied.clear();
  const std::vector<LoadStep> failing{
      {"p", [&] { load->p = 1.0; }},
      {"slide", [&] { load->tau_top = load->tau_sides = 0.4; }},  // > mu p = 0.3
      {"never", [&] { applied.push_back(-1.0); }},
  };
  path = contact.solve_steps(settings, failing);
  ASSERT_EQ(path.size(), 2u);
  EXPECT_TRUE(path[0].converged()) << path[0].reason;
  EXPECT_FALSE(path[1].converged());
  EXPECT_TRUE(path[1].friction_history.empty());
  EXPECT_TRUE(applied.empty());  // the step after the failure was not applied
}

}  // namespace
}  // namespace cs::solver
