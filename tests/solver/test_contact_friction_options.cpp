// Friction options: mu = 0 leaves every frictionless analysis bit for bit as it was, and bad
// friction input is a ContactError with a one-line message naming the cause.
//
// Requirements:
//   - with mu = 0, for every discretization x algorithm, on a Hertz model (rigid cylinder, Q4;
//     meshed indenter, Q8) and a two-body patch model: solve() with the friction fields set to
//     anything valid, solve() with a friction history, and solve_steps() give the displacement,
//     the pressures, the gaps and the iteration counts of the default frictionless settings
//     exactly (bit equality), also after frictional solves on the same ContactAnalysis (their
//     factorization is a separate one);
//   - mu < 0, NaN, infinite, mu > 10, friction with MPC, tangential multipliers without the
//     Lagrange multiplier algorithm, FKT or FTOLT <= 0 and a friction history of other rows
//     are rejected before anything is solved.

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "solver/contact/contact_error.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

/// Bit equality of two vectors (NaN-safe and signed-zero-exact).
bool bit_equal(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}

bool bit_equal(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

/// Every number a frictionless result reports, compared bit for bit.
void expect_bit_identical(const ContactResult& a, const ContactResult& b, const std::string& what) {
  ASSERT_EQ(a.status, b.status) << what;
  EXPECT_TRUE(bit_equal(a.displacement, b.displacement)) << what;
  EXPECT_EQ(a.active_set_iterations, b.active_set_iterations) << what;
  EXPECT_EQ(a.augmentations, b.augmentations) << what;
  EXPECT_TRUE(bit_equal(a.residual, b.residual)) << what;
  EXPECT_TRUE(bit_equal(a.peak_pressure, b.peak_pressure)) << what;
  EXPECT_TRUE(bit_equal(a.contact_extent, b.contact_extent)) << what;
  ASSERT_EQ(a.nodes.size(), b.nodes.size()) << what;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_TRUE(bit_equal(a.nodes[i].pressure, b.nodes[i].pressure)) << what << " node " << i;
    EXPECT_TRUE(bit_equal(a.nodes[i].gap, b.nodes[i].gap)) << what << " node " << i;
    EXPECT_EQ(a.nodes[i].closed, b.nodes[i].closed) << what << " node " << i;
    EXPECT_EQ(b.nodes[i].shear, 0.0) << what;  // no friction results without friction
    EXPECT_EQ(b.nodes[i].friction, FrictionState::Open) << what;
  }
  EXPECT_TRUE(b.friction_history.empty()) << what;
}

/// The frictionless settings with every friction field changed (still mu = 0).
ContactSettings frictionless_with_friction_fields(ContactSettings s) {
  s.mu = 0.0;
  s.fkt = 7.0;
  s.ftolt = 0.5;
  if (s.algorithm == ContactAlgorithm::LagrangeMultiplier)
    s.tangential = TangentialEnforcement::LagrangeMultiplier;
  return s;
}

void check_model(const Model& model, const ContactPair& pair, const std::string& label) {
  // Reference: a fresh analysis per model running the default (frictionless) settings.
  LinearStaticAnalysis elastic_ref(model);
  ContactAnalysis reference(elastic_ref, pair);
  // Under test: another analysis that also runs frictional solves in between.
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, pair);
  for (ContactDiscretization d :
       {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
        ContactDiscretization::Mortar}) {
    for (ContactAlgorithm a :
         {ContactAlgorithm::Penalty, ContactAlgorithm::AugmentedLagrangian,
          ContactAlgorithm::LagrangeMultiplier, ContactAlgorithm::MultipointConstraint}) {
      const ContactSettings s = contact_test::settings(d, a);
      const std::string what = label + " " + to_string(d) + " " + to_string(a);
      const ContactResult expected = reference.solve(s);
      if (a != ContactAlgorithm::MultipointConstraint) {
        ContactSettings f = s;
        f.mu = 0.2;
        const ContactResult frictional = contact.solve(f);  // its own stages
        if (frictional.converged()) {
          EXPECT_FALSE(frictional.friction_history.empty()) << what;
        }
        expect_bit_identical(
            expected,
            contact.solve(frictionless_with_friction_fields(s), frictional.friction_history),
            what + " (history ignored)");
      }
      expect_bit_identical(expected, contact.solve(frictionless_with_friction_fields(s)),
                           what + " (friction fields)");
      const std::vector<ContactResult> steps = contact.solve_steps(s, {{"one", {}}});
      ASSERT_EQ(steps.size(), 1u);
      expect_bit_identical(expected, steps[0], what + " (solve_steps)");
    }
  }
}

TEST(FrictionOptions, MuZeroIsBitIdenticalToFrictionless) {
  {
    contact_test::HertzSpec h;
    h.n = 16;
    check_model(contact_test::hertz_model(h), contact_test::hertz_pair(h), "H_p Q4 rigid");
  }
  {
    contact_test::HertzSpec h;
    h.n = 16;
    h.type = ElementType::Q8;
    h.meshed_indenter = true;
    check_model(contact_test::hertz_model(h), contact_test::hertz_pair(h), "H_p Q8 meshed");
  }
  {
    contact_test::PatchSpec p;
    p.nx = p.nz = 10;
    p.indenter_nx = 9;
    p.E_ratio = 1.0;
    check_model(contact_test::patch_model(p), contact_test::patch_pair(p), "two-body patch");
  }
}

/// The message of the ContactError that solving `s` on a small patch model throws ("" if none).
std::string error_of(const ContactSettings& s, const FrictionHistory& history = {}) {
  const contact_test::PatchSpec p;
  const Model model = contact_test::patch_model(p);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::patch_pair(p));
  try {
    contact.solve(s, history);
  } catch (const ContactError& e) {
    return e.what();
  }
  return "";
}

ContactSettings frictional(ContactAlgorithm a, double mu) {
  return contact_test::friction_settings(ContactDiscretization::NodeToSurface, a, mu);
}

TEST(FrictionOptions, BadFrictionInputIsAContactError) {
  const ContactAlgorithm LM = ContactAlgorithm::LagrangeMultiplier;
  EXPECT_NE(error_of(frictional(LM, -0.1)).find("mu = -0.1"), std::string::npos);
  EXPECT_NE(error_of(frictional(LM, std::numeric_limits<double>::quiet_NaN())).find("mu = nan"),
            std::string::npos);
  EXPECT_NE(error_of(frictional(LM, std::numeric_limits<double>::infinity())).find("mu = inf"),
            std::string::npos);
  EXPECT_NE(error_of(frictional(LM, 10.5)).find("must be <= 10"), std::string::npos);
  EXPECT_EQ(error_of(frictional(LM, 10.0)), "");  // the bound itself is accepted
  EXPECT_EQ(error_of(frictional(ContactAlgorithm::MultipointConstraint, 0.3)),
            "contact: friction is not defined for MPC (tied constraints have no slip)");
  EXPECT_EQ(error_of(frictional(ContactAlgorithm::MultipointConstraint, 0.0)), "");
  ContactSettings s = frictional(ContactAlgorithm::Penalty, 0.3);
  s.tangential = TangentialEnforcement::LagrangeMultiplier;
  EXPECT_NE(error_of(s).find("need the Lagrange multiplier algorithm"), std::string::npos);
  s = frictional(LM, 0.3);
  s.fkt = 0.0;
  EXPECT_NE(error_of(s).find("FKT = 0"), std::string::npos);
  s = frictional(LM, 0.3);
  s.ftolt = -1.0;
  EXPECT_NE(error_of(s).find("FTOLT = -1"), std::string::npos);
  s = frictional(LM, 0.3);
  s.tangential = static_cast<TangentialEnforcement>(5);
  EXPECT_NE(error_of(s).find("unknown tangential enforcement"), std::string::npos);
  // A history of other rows (ss Gauss-point rows) handed to a node-to-surface solve.
  FrictionHistory other;
  other.rows = ConstraintRows::GaussPoints;
  other.slip_s = other.force_t = Eigen::VectorXd::Zero(8);
  other.node_slip = Eigen::VectorXd::Zero(5);
  EXPECT_NE(error_of(frictional(LM, 0.3), other).find("does not belong"), std::string::npos);
}

}  // namespace
}  // namespace cs::solver
