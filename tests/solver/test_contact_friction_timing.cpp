// Time of a frictional solve against the frictionless one on the same model: H_p (the study's
// plane Hertz problem, McEwen's far-field tractions, symmetric half model) with the rigid
// cylinder (M mesh, Q4) and with the meshed stiff indenter (C mesh, Q8), every discretization
// and PM, AL, LMP, PLM with mu = 0.3, the normal load in one step.
//
// Requirement: every frictional solve converges (the node on the symmetry line, whose slip is
// held by both bodies' supports, included: its tangential row is left out). The output gives both
// times (the sparse factorizations, one each, excluded: second solves), the iteration counts and
// how friction changes the peak pressure (a rigid cylinder resisting the block's inward surface
// displacement, Spence's problem: a few percent for nu = 0.3).

#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using Clock = std::chrono::steady_clock;

double timed_ms(ContactAnalysis& contact, const ContactSettings& s, ContactResult& r) {
  contact.solve(s);  // the factorization and the condensation of this row kind
  const auto t0 = Clock::now();
  r = contact.solve(s);
  return 1e3 * std::chrono::duration<double>(Clock::now() - t0).count();
}

class FrictionTiming : public ::testing::TestWithParam<contact_test::HertzSpec> {};

TEST_P(FrictionTiming, FrictionalAgainstFrictionlessOnHertz) {
  const contact_test::HertzSpec spec = GetParam();
  const char* label = spec.meshed_indenter ? "C Q8 meshed" : "M Q4 rigid";
  const Model model = contact_test::hertz_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  for (ContactDiscretization d :
       {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
        ContactDiscretization::Mortar}) {
    for (int m = 0; m < 4; ++m) {
      const ContactAlgorithm a = m == 0   ? ContactAlgorithm::Penalty
                                 : m == 1 ? ContactAlgorithm::AugmentedLagrangian
                                          : ContactAlgorithm::LagrangeMultiplier;
      const TangentialEnforcement t =
          m == 3 ? TangentialEnforcement::LagrangeMultiplier : TangentialEnforcement::Penalty;
      const char* method = m == 0 ? "PM" : m == 1 ? "AL" : m == 2 ? "LMP" : "PLM";
      ContactResult frictionless, frictional;
      const double t0 = timed_ms(contact, contact_test::friction_settings(d, a, 0.0), frictionless);
      const double t1 =
          timed_ms(contact, contact_test::friction_settings(d, a, 0.3, t), frictional);
      ASSERT_TRUE(frictionless.converged()) << frictionless.reason;
      EXPECT_TRUE(frictional.converged())
          << to_string(d) << " " << method << ": " << frictional.reason;
      std::printf(
          "[ info     ] H_p %s %s %s: frictionless %.2f ms (%d iterations), mu = 0.3 %.2f ms "
          "(%d iterations, %d augmentations, %d rows); peak p %.4f -> %.4f, peak shear %.4f\n",
          label, to_string(d), method, t0, frictionless.active_set_iterations, t1,
          frictional.active_set_iterations, frictional.augmentations, frictional.n_candidates,
          frictionless.peak_pressure, frictional.peak_pressure, frictional.peak_shear);
    }
  }
}

contact_test::HertzSpec hertz(int n, ElementType type, bool meshed) {
  contact_test::HertzSpec spec;
  spec.n = n;
  spec.type = type;
  spec.meshed_indenter = meshed;
  return spec;
}

INSTANTIATE_TEST_SUITE_P(Hertz, FrictionTiming,
                         ::testing::Values(hertz(32, ElementType::Q4, false),
                                           hertz(16, ElementType::Q8, true)),
                         [](const auto& info) {
                           return std::string(info.param.meshed_indenter ? "C_Q8_meshed"
                                                                         : "M_Q4_rigid");
                         });

}  // namespace
}  // namespace cs::solver
