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

#include "solver/contact/repeated_solve.hpp"
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

/// Everything a solve gives but its settings and timings, bit for bit.
void expect_same_solve(const ContactResult& a, const ContactResult& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.active_set_iterations, b.active_set_iterations);
  EXPECT_EQ(a.augmentations, b.augmentations);
  EXPECT_EQ(a.n_candidates, b.n_candidates);
  EXPECT_EQ(a.peak_pressure, b.peak_pressure);
  EXPECT_EQ(a.total_normal_force, b.total_normal_force);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].pressure, b.nodes[i].pressure);
    EXPECT_EQ(a.nodes[i].gap, b.nodes[i].gap);
  }
  EXPECT_EQ((a.displacement - b.displacement).norm(), 0.0);
}

// Requirement (issue 27): a model's cases share what they can; a case whose solve would repeat
// an earlier one's step for step takes its result (solver/contact/repeated_solve.hpp). Each
// "repeats" is checked by solving again: fails if a rule admits a pair that solves differently,
// e.g. PM after an AL that augmented, or LMP and PLM with friction.
TEST(ContactRepeatedSolve, RepeatsOnlyWhatSolvingAgainWouldGive) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  const auto ss = ContactDiscretization::SurfaceToSurface;
  // PM after AL that needed no augmentation, whatever AL's FTOLN.
  ContactSettings al_settings = contact_test::settings(ss, ContactAlgorithm::AugmentedLagrangian);
  al_settings.ftoln = 0.2;
  const ContactResult al = contact.solve(al_settings);
  ASSERT_TRUE(al.converged()) << al.reason;
  ASSERT_EQ(al.augmentations, 0);
  ContactSettings pm_settings = contact_test::settings(ss, ContactAlgorithm::Penalty);
  EXPECT_TRUE(repeats_solve(pm_settings, al));
  expect_same_solve(contact.solve(pm_settings), al);
  // Not the other way round (AL reads FTOLN), nor with another FKN or discretization.
  EXPECT_FALSE(repeats_solve(al_settings, contact.solve(pm_settings)));
  ContactSettings other = pm_settings;
  other.fkn = 2.0;
  EXPECT_FALSE(repeats_solve(other, al));
  other = pm_settings;
  other.discretization = ContactDiscretization::Mortar;
  EXPECT_FALSE(repeats_solve(other, al));
  // Not after an AL that augmented: PM stops at AL's first pass.
  al_settings.fkn = 1e-3;
  al_settings.ftoln = 0.01;
  al_settings.pinball = 10.0;
  const ContactResult augmented = contact.solve(al_settings);
  ASSERT_TRUE(augmented.converged()) << augmented.reason;
  ASSERT_GT(augmented.augmentations, 0);
  pm_settings.fkn = al_settings.fkn;
  pm_settings.pinball = al_settings.pinball;
  EXPECT_FALSE(repeats_solve(pm_settings, augmented));
  EXPECT_NE(contact.solve(pm_settings).active_set_iterations, augmented.active_set_iterations);
  // PLM after LMP without friction: the tangential enforcement is not read.
  ContactSettings lmp = contact_test::settings(ss, ContactAlgorithm::LagrangeMultiplier);
  ContactSettings plm = lmp;
  plm.tangential = TangentialEnforcement::LagrangeMultiplier;
  const ContactResult lm = contact.solve(lmp);
  EXPECT_TRUE(repeats_solve(plm, lm));
  expect_same_solve(contact.solve(plm), lm);
  // With friction it is: another solve.
  ContactResult frictional = lm;
  frictional.settings.mu = plm.mu = 0.3;
  EXPECT_FALSE(repeats_solve(plm, frictional));
  EXPECT_TRUE(repeats_solve(frictional.settings, frictional));
}

}  // namespace
}  // namespace cs::solver
