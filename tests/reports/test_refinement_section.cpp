// The "Error estimates and refinement" section's verdicts: which rows the study's "further
// refinement would lead to converging results" applies to and whether it holds, and the GCI
// band test.

#include <gtest/gtest.h>

#include "reports/findings/refinement_section.hpp"

namespace cs::reports {
namespace {

using schema::Grade;
using schema::RowVerdict;

RowVerdict row(Grade grade, bool converging, std::optional<bool> converging_vf) {
  RowVerdict r;
  r.grade = grade;
  r.converging = converging;
  if (converging_vf) {
    r.refinement.emplace();
    r.refinement->converging = converging_vf;
  }
  return r;
}

// Requirement: the claim applies only to rows graded s or better on F that are not c over
// C-M-F; it holds when M-F-VF converges, fails when it does not, and is open without VF.
TEST(RefinementSection, StudyClaimAppliesToUnconvergedSatisfactoryRowsOnly) {
  EXPECT_EQ(refinement_claim(row(Grade::s, false, true)), RefinementClaim::holds);
  EXPECT_EQ(refinement_claim(row(Grade::e, false, false)), RefinementClaim::fails);
  EXPECT_EQ(refinement_claim(row(Grade::g, false, std::nullopt)), RefinementClaim::no_vf);
  EXPECT_EQ(refinement_claim(row(Grade::g, true, false)), RefinementClaim::not_applicable);
  EXPECT_EQ(refinement_claim(row(Grade::u, false, true)), RefinementClaim::not_applicable);
}

// Requirement: the GCI band holds the exact value when |f_F - exact| / |f_F| <= GCI.
TEST(RefinementSection, GciBandTest) {
  RowVerdict r;
  r.values = {1.3, 1.28, 1.275};
  r.estimate = schema::ErrorEstimate{true, 2.0, 1.2733, 0.2, ""};
  EXPECT_TRUE(*gci_bounds_error(r, 1.2732));   // 0.14 % <= 0.2 %
  EXPECT_FALSE(*gci_bounds_error(r, 1.2700));  // 0.39 % > 0.2 %
  r.estimate.reset();
  EXPECT_FALSE(gci_bounds_error(r, 1.2732).has_value());
}

}  // namespace
}  // namespace cs::reports
