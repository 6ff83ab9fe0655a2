// The graded nodal stress near a loaded contact surface: the study's plane-strain Hertz problem
// with bilinear elements and Lagrange multipliers (H_p, Q4, LMP, ss) on its three meshes.
// Patch-recovered nodal stresses converge at second order to within 1 % on the fine mesh;
// extrapolated, averaged ones (the study's) carry the O(h) surface bias of Q4
// (docs/conventions.md, "Sampling and grading").

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "suites/problem_executor.hpp"

namespace cs::suites {
namespace {

/// Signed % errors of sigma_c (nodal) on C, M, F, and of the contact pressure on F.
struct HertzErrors {
  std::vector<double> sigma_c;
  double pressure_f = 0.0;
};

HertzErrors hertz_errors(Recovery recovery) {
  HertzErrors out;
  for (MeshLevel mesh : schema::kStudyMeshes) {
    const CaseSpec spec{.problem = ProblemId::H_p,
                        .mesh = mesh,
                        .element = Element::Q4,
                        .algorithm = Algorithm::LMP,
                        .contact = ContactKind::ss,
                        .recovery = recovery,
                        .overrides = {}};
    ProblemExecutor executor(spec);
    const CaseResult r = executor.run(spec);
    EXPECT_EQ(r.status, CaseStatus::converged) << case_id(spec) << ": " << r.reason;
    const QuantityResult& q = r.quantities.at(0);
    EXPECT_EQ(q.quantity, Quantity::sigma_c);
    out.sigma_c.push_back(q.error_percent);
    if (mesh == MeshLevel::F && q.contact_pressure)
      out.pressure_f = 100.0 * (*q.contact_pressure - q.exact) / q.exact;
  }
  return out;
}

/// Observed order from the errors of meshes h and h/4.
double observed_order(const std::vector<double>& e) {
  return std::log(std::abs(e[0] / e[2])) / std::log(4.0);
}

// Requirement (the battery's acceptance): H_p fine-mesh LM/ss Q4 sigma_c within 1 % of 4/pi,
// converging at about second order (observed errors 4.6, 1.05, 0.23 %: order 2.2); the contact
// pressure at the axis is within 0.1 %.
TEST(NodalStressAccuracy, HertzFineMeshLagrangeQ4WithinOnePercent) {
  const HertzErrors spr = hertz_errors(Recovery::spr);
  EXPECT_LT(std::abs(spr.sigma_c[2]), 1.0);
  EXPECT_LT(std::abs(spr.sigma_c[1]), std::abs(spr.sigma_c[0]));
  EXPECT_LT(std::abs(spr.sigma_c[2]), std::abs(spr.sigma_c[1]));
  EXPECT_GT(observed_order(spr.sigma_c), 1.7);
  EXPECT_LT(std::abs(spr.pressure_f), 0.1);
}

// Requirement: the extrapolated, averaged nodal stress (what the study graded) is biased high
// at first order (observed 6.6, 3.9, 2.1 %: order 0.8) while the contact pressure is right:
// the bias is the recovery's, and patch recovery removes most of it.
TEST(NodalStressAccuracy, ExtrapolatedQ4StressesCarryAFirstOrderBias) {
  const HertzErrors ext = hertz_errors(Recovery::extrapolated);
  const HertzErrors spr = hertz_errors(Recovery::spr);
  for (double e : ext.sigma_c)
    EXPECT_GT(e, 1.0);  // high on every mesh
  const double order = observed_order(ext.sigma_c);
  EXPECT_GT(order, 0.6);
  EXPECT_LT(order, 1.3);
  EXPECT_LT(std::abs(ext.pressure_f), 0.1);
  EXPECT_DOUBLE_EQ(ext.pressure_f, spr.pressure_f);  // same contact solution
  EXPECT_LT(std::abs(spr.sigma_c[2]), 0.25 * std::abs(ext.sigma_c[2]));
}

// Requirement: one executor running a case recovered both ways reuses the contact solution
// (same contact pressure, same iterations) and only the nodal stresses differ.
TEST(NodalStressAccuracy, RecoveriesOfOneCaseShareItsContactSolution) {
  CaseSpec spec{.problem = ProblemId::H_p,
                .mesh = MeshLevel::C,
                .element = Element::Q4,
                .algorithm = Algorithm::AL,
                .contact = ContactKind::ns,
                .overrides = {}};
  ProblemExecutor executor(spec);
  const CaseResult spr = executor.run(spec);
  spec.recovery = Recovery::extrapolated;
  const CaseResult ext = executor.run(spec);
  ASSERT_EQ(spr.status, CaseStatus::converged);
  ASSERT_EQ(ext.status, CaseStatus::converged);
  EXPECT_EQ(spr.iterations, ext.iterations);
  EXPECT_EQ(spr.quantities[0].contact_pressure, ext.quantities[0].contact_pressure);
  EXPECT_NE(spr.quantities[0].value, ext.quantities[0].value);
  // And the extrapolated value is what a fresh executor computes for that case alone.
  ProblemExecutor fresh(spec);
  EXPECT_EQ(fresh.run(spec).quantities[0].value, ext.quantities[0].value);
}

// Requirement: a singular quantity (the flat punch's edge stress, exact value infinite) has a
// value and no error: error_percent is NaN (null in results.json) and the grade u, never a 0 %
// error that reads as exact. Fails if the error keeps its default of 0.
TEST(NodalStressAccuracy, ASingularQuantityHasNoError) {
  const CaseSpec spec{.problem = ProblemId::F_p,
                      .mesh = MeshLevel::C,
                      .element = Element::Q4,
                      .algorithm = Algorithm::LMP,
                      .contact = ContactKind::ss,
                      .overrides = {}};
  ProblemExecutor executor(spec);
  const CaseResult r = executor.run(spec);
  ASSERT_EQ(r.status, CaseStatus::converged) << r.reason;
  int singular = 0;
  for (const QuantityResult& q : r.quantities) {
    if (!q.singular())
      continue;
    ++singular;
    EXPECT_TRUE(std::isfinite(q.value)) << to_string(q.quantity);
    EXPECT_TRUE(std::isnan(q.error_percent)) << to_string(q.quantity) << ": " << q.error_percent;
    EXPECT_EQ(q.grade, Grade::u);
  }
  EXPECT_GE(singular, 1);
}

}  // namespace
}  // namespace cs::suites
