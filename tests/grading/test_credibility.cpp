// Requirement: a case that fails force balance, carries tensile pressure or presses outside the
// exact patch (beyond the tolerances of schema/interface_checks.hpp) is not credible, each
// failure named; penetration is reported as a failing check but leaves the case credible;
// absent checks and checks exactly at their tolerance do not fail.

#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grading/credibility.hpp"
#include "grading/interface_check_rules.hpp"

namespace cs::grading {
namespace {

using Names = std::vector<std::string>;

schema::InterfaceChecks sound() {
  return {2e-7, 0.0, 0.0, 1e-3};
}

TEST(Credibility, ASoundInterfaceIsCredible) {
  const auto c = credibility(sound());
  EXPECT_TRUE(c.credible);
  EXPECT_TRUE(c.failures.empty());
  EXPECT_TRUE(credibility(schema::InterfaceChecks{}).credible);  // every check absent
}

TEST(Credibility, EachSoundnessCheckMakesACaseNotCredible) {
  // H_p Q4 MPC ss, issue 23: force-balance residual 19.2 (negative: the interface carries less).
  auto unbalanced = sound();
  unbalanced.force_balance = -19.2;
  EXPECT_EQ(credibility(unbalanced).failures, Names{"force balance"});
  auto pulling = sound();
  pulling.max_tensile_over_p = 0.5;
  EXPECT_EQ(credibility(pulling).failures, Names{"tensile pressure"});
  auto outside = sound();
  outside.max_outside_over_p = 0.2;
  EXPECT_EQ(credibility(outside).failures, Names{"pressure outside the patch"});
  auto all = sound();
  all.force_balance = 648.0;
  all.max_tensile_over_p = 0.5;
  all.max_outside_over_p = 0.2;
  const auto c = credibility(all);
  EXPECT_FALSE(c.credible);
  EXPECT_EQ(c.failures, (Names{"force balance", "tensile pressure", "pressure outside the patch"}));
}

TEST(Credibility, AnIterativeCodesResidualIsNotAMissingForce) {
  // CalculiX on the patch tests stops Newton at its residual tolerance, leaving 2.3e-4 of the
  // load; one node's force missing from the sum costs at least 1e-3 of it.
  auto newton = sound();
  newton.force_balance = 2.3e-4;
  EXPECT_TRUE(credibility(newton).credible);
  auto missing = sound();
  missing.force_balance = -1e-3;
  EXPECT_EQ(credibility(missing).failures, Names{"force balance"});
}

TEST(Credibility, PenetrationIsReportedButKeepsTheCaseCredible) {
  auto soft = sound();
  soft.max_penetration_over_h = 0.25;  // beyond FTOLN = 0.1
  EXPECT_TRUE(credibility(soft).credible);
  EXPECT_EQ(interface_failures(soft), Names{"penetration"});
}

TEST(Credibility, AToleranceItselfPassesAndNaNFails) {
  auto at = sound();
  at.force_balance = -schema::kForceBalanceTolerance;
  at.max_tensile_over_p = schema::kTensileTolerance;
  at.max_outside_over_p = schema::kOutsideTolerance;
  at.max_penetration_over_h = schema::kPenetrationTolerance;
  EXPECT_TRUE(interface_failures(at).empty());
  auto nan = sound();
  nan.force_balance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(credibility(nan).credible);
}

}  // namespace
}  // namespace cs::grading
