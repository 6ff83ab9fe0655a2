// Penalty and augmented Lagrangian: how they approach the Lagrange multiplier answer.
//
// Requirement: the penalty stiffness is FKN (E / h) w, so on the patch test the penetration is
// exactly p h / (FKN E) with the exact uniform pressure; on Hertz the penalty answer tends to the
// Lagrange multiplier answer as FKN grows (error ~ 1 / FKN); augmented Lagrangian stops once every
// penetration is <= FTOLN h, and equals the penalty method when that holds at once (the study's
// "AL and PM are the same").

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using contact_test::HertzSpec;
using contact_test::PatchSpec;
using cs::testing::Near;

double max_penetration(const ContactResult& r) {
  double d = 0.0;
  for (const ContactNodeResult& n : r.nodes)
    d = std::max(d, n.penetration);
  return d;
}

TEST(ContactPenalty, PatchTestPenetrationIsPressureOverPenaltyStiffness) {
  for (ContactDiscretization d :
       {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
        ContactDiscretization::Mortar}) {
    for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
      PatchSpec spec;
      spec.type = type;
      const Model model = contact_test::patch_model(spec);
      ContactSettings s = contact_test::settings(d, ContactAlgorithm::Penalty);
      s.fkn = 10.0;
      const ContactResult r = solve_contact(model, contact_test::patch_pair(spec), s);
      ASSERT_TRUE(r.converged()) << r.reason;
      const double h = spec.h / spec.nz;  // underlying element depth
      for (const ContactNodeResult& n : r.nodes) {
        EXPECT_TRUE(Near(n.pressure, spec.p, {1e-10, 0.0}));  // round-off
        EXPECT_TRUE(Near(n.penetration, spec.p * h / (s.fkn * spec.E), {1e-10, 0.0}));
      }
    }
  }
}

TEST(ContactPenalty, TendsToLagrangeAsFknGrows) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  const ContactResult lm = contact.solve(contact_test::settings(
      ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier));
  ASSERT_TRUE(lm.converged()) << lm.reason;
  std::vector<double> u_error, penetration;
  for (double fkn : {1.0, 10.0, 100.0}) {
    ContactSettings s =
        contact_test::settings(ContactDiscretization::NodeToSurface, ContactAlgorithm::Penalty);
    s.fkn = fkn;
    const ContactResult pm = contact.solve(s);
    ASSERT_TRUE(pm.converged()) << pm.reason;
    EXPECT_TRUE(pm.timings.condensation_reused);  // one factorization for every FKN
    EXPECT_EQ(pm.timings.factorize_s, 0.0);
    u_error.push_back((pm.displacement - lm.displacement).norm() / lm.displacement.norm());
    penetration.push_back(max_penetration(pm));
    std::printf(
        "[ info     ] H_p ns PM FKN = %5.0f: peak %.5f (LM %.5f), |u - u_LM| / |u_LM| = "
        "%.3e, max penetration %.3e\n",
        fkn, pm.peak_pressure, lm.peak_pressure, u_error.back(), penetration.back());
  }
  // Penalty is a perturbation of order 1 / FKN: each tenfold FKN cuts the error about tenfold
  // (at least fivefold, allowing for the active set settling at FKN = 1).
  EXPECT_LT(u_error[1], u_error[0] / 5.0);
  EXPECT_LT(u_error[2], u_error[1] / 5.0);
  EXPECT_LT(penetration[1], penetration[0] / 5.0);
  EXPECT_LT(penetration[2], penetration[1] / 5.0);
}

TEST(ContactAugmentedLagrangian, AugmentsUntilPenetrationBelowFtoln) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  const double h = 4.0 * spec.a / spec.n;
  // A soft penalty (FKN = 1e-3) penetrates p h / (FKN E) ~ h: AL must augment.
  ContactSettings s = contact_test::settings(ContactDiscretization::SurfaceToSurface,
                                             ContactAlgorithm::AugmentedLagrangian);
  s.fkn = 1e-3;
  s.ftoln = 0.01;
  s.pinball = 10.0;
  const ContactResult al = contact.solve(s);
  ASSERT_TRUE(al.converged()) << al.reason;
  EXPECT_GT(al.augmentations, 0);
  s.algorithm = ContactAlgorithm::Penalty;
  const ContactResult pm = contact.solve(s);
  ASSERT_TRUE(pm.converged()) << pm.reason;
  std::printf(
      "[ info     ] H_p ss FKN = 1e-3: AL %d augmentations, %d solves, max penetration "
      "%.3e h (FTOLN 0.01); PM max penetration %.3e h\n",
      al.augmentations, al.active_set_iterations, max_penetration(al) / h, max_penetration(pm) / h);
  EXPECT_LE(max_penetration(al), s.ftoln * h * (1 + 1e-9));
  EXPECT_GT(max_penetration(pm), s.ftoln * h);
}

TEST(ContactAugmentedLagrangian, EqualsPenaltyWhenPenetrationIsWithinFtoln) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  const ContactResult al = contact.solve(contact_test::settings(
      ContactDiscretization::SurfaceToSurface, ContactAlgorithm::AugmentedLagrangian));
  const ContactResult pm = contact.solve(
      contact_test::settings(ContactDiscretization::SurfaceToSurface, ContactAlgorithm::Penalty));
  ASSERT_TRUE(al.converged() && pm.converged());
  EXPECT_EQ(al.augmentations, 0);
  EXPECT_EQ((al.displacement - pm.displacement).norm(), 0.0);  // the same computation
}

}  // namespace
}  // namespace cs::solver
