// Time of a frictional solve against the frictionless one on the same model: H_p (the study's
// plane Hertz problem, McEwen's far-field tractions, rigid cylinder, symmetric half model), M
// mesh, Q4, every discretization and PM, AL, LMP, PLM with mu = 0.3, the normal load in one step.
//
// Requirement: every frictional solve converges (the node on the symmetry line, whose tangential
// DOF is held, included). The output gives both times (the sparse factorizations, one each,
// excluded: second solves), the iteration counts and how friction changes the peak pressure (a
// rigid cylinder resisting the block's inward surface displacement, Spence's problem: a few
// percent for nu = 0.3).

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

TEST(FrictionTiming, FrictionalAgainstFrictionlessOnHertz) {
  contact_test::HertzSpec spec;
  spec.n = 32;
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
          "[ info     ] H_p M Q4 %s %s: frictionless %.2f ms (%d iterations), mu = 0.3 %.2f ms "
          "(%d iterations, %d augmentations, %d rows); peak p %.4f -> %.4f, peak shear %.4f\n",
          to_string(d), method, t0, frictionless.active_set_iterations, t1,
          frictional.active_set_iterations, frictional.augmentations, frictional.n_candidates,
          frictionless.peak_pressure, frictional.peak_pressure, frictional.peak_shear);
    }
  }
}

}  // namespace
}  // namespace cs::solver
