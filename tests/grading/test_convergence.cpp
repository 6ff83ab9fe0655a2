// Requirement: the study's 'c' stays the study's rule (0.01-point resolution); the noise-aware
// verdict calls a plateau settled whichever way noise of a few thousandths of a point falls,
// and names the bound that set its floor; no order is fitted to a non-monotone, noise-level or
// pre-asymptotic sequence; a fine grade after an unresolved coarse mesh is the luck of one mesh.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "grading/convergence.hpp"
#include "support/tolerance.hpp"

namespace cs::grading {
namespace {

using cs::testing::Near;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(StudyConverging, IsTheStudysRule) {
  // Table 7a (4Q, ss, AL/PM) 1.2628, 1.2704, 1.2737 against 4/pi: Table 2a marks it 'c'.
  const double exact = 4.0 / M_PI;
  auto e = [&](double v) { return 100.0 * (v - exact) / exact; };
  EXPECT_TRUE(study_converging(e(1.2628), e(1.2704), e(1.2737)));
  // Table 3a LMP/PLM 1.0001, 1.0003, 1.0019: not converging in Table 2a.
  EXPECT_FALSE(study_converging(0.01, 0.03, 0.19));
  EXPECT_TRUE(study_converging(1e-12, 3e-12, 2e-12));  // exact on every mesh
  EXPECT_FALSE(study_converging(5.0, 5.0, 5.0));       // stuck at 5 %
  EXPECT_FALSE(study_converging(1.0, 2.0, 0.5));       // grows on M
  EXPECT_FALSE(study_converging(kNaN, 1.0, 0.5));
}

TEST(StudyConverging, FlipsOnNoiseAtAPlateau) {
  // Issue 23, item 5: S(1/3) Q8 LMP ss gets no c, LMP ns gets c, on 0.001-point differences.
  EXPECT_FALSE(study_converging(-0.3194, -0.3217, -0.3130));
  EXPECT_TRUE(study_converging(-0.3238, -0.3239, -0.3124));
}

TEST(AssessConvergence, ThePlateauOfSOneThirdIsSettledBothWays) {
  const auto ss = assess_convergence(-0.3194, -0.3217, -0.3130);
  const auto ns = assess_convergence(-0.3238, -0.3239, -0.3124);
  EXPECT_EQ(ss.trend, Trend::settled);
  EXPECT_EQ(ns.trend, Trend::settled);
  // The floor is a tenth of |e_F|, 0.0313 and 0.03124 points, above the 0.01 resolution.
  EXPECT_TRUE(Near(ss.floor_percent, 0.03130, {1e-12, 0}));  // machine precision
  EXPECT_NE(ss.floor_reason.find("a tenth of the F error"), std::string::npos) << ss.floor_reason;
}

TEST(AssessConvergence, ConvergingAndNotConverging) {
  const auto falling = assess_convergence(4.0, 1.0, 0.25);
  EXPECT_EQ(falling.trend, Trend::converging);
  EXPECT_EQ(assess_convergence(1.0, 2.0, 3.0).trend, Trend::not_converging);
  EXPECT_EQ(assess_convergence(-4.0, 1.0, -0.25).trend, Trend::converging);   // magnitudes fall
  EXPECT_EQ(assess_convergence(4.0, 1.0, 3.0).trend, Trend::not_converging);  // grows on F
  EXPECT_EQ(assess_convergence(kNaN, 1.0, 0.5).trend, Trend::not_converging);
}

TEST(AssessConvergence, SmallErrorsUseTheStudysResolutionAsTheFloor) {
  const auto exact = assess_convergence(1e-12, 3e-12, 2e-12);
  EXPECT_EQ(exact.trend, Trend::settled);
  EXPECT_EQ(exact.floor_percent, kErrorResolutionPercent);
  EXPECT_NE(exact.floor_reason.find("resolution"), std::string::npos) << exact.floor_reason;
  // 0.05 -> 0.03 -> 0.02: the first change, 0.02 points, exceeds the floor of 0.01: not
  // settled; the error falls by more than the floor: converging.
  EXPECT_EQ(assess_convergence(0.05, 0.03, 0.02).trend, Trend::converging);
}

TEST(AssessConvergence, AValueReadBetweenNodesSettlesWithinHalfANodeSpacing) {
  // S(1/7) Q4 a_FE: nodes 0.000764 b apart on C, exact 1.0047 b: half a spacing is 0.038
  // points on C, 0.019 on M. +0.12 -> +0.10 -> +0.09 % moves by less on each pair: settled
  // (against the 0.01-point floor of a value read at a point it converges).
  const double resolution = node_read_resolution_percent(0.000764, 1.0047);
  EXPECT_TRUE(Near(resolution, 100.0 * 0.000382 / 1.0047, {1e-12, 0}));  // machine precision
  const auto a = assess_convergence(0.12, 0.10, 0.09, resolution);
  EXPECT_EQ(a.trend, Trend::settled);
  EXPECT_EQ(a.floor_percent, resolution);
  EXPECT_NE(a.floor_reason.find("node spacing"), std::string::npos) << a.floor_reason;
  EXPECT_EQ(assess_convergence(0.12, 0.10, 0.09).trend, Trend::converging);
  // The committed row, +0.12 -> +0.10 -> +0.07 %, falls beyond M's 0.019 on F: converging, but
  // with no order (it was 0.39): C -> M moves 0.02, within C's 0.038.
  EXPECT_EQ(assess_convergence(0.12, 0.10, 0.07, resolution).trend, Trend::converging);
  EXPECT_EQ(observed_order(0.12, 0.10, 0.07, resolution).note, "at noise level");
  // H_p Q4 a_FE: the edge at a node, read half a node off on every mesh (nodes 0.25 a apart
  // on C): +12.5 -> +6.25 -> +3.125 % converges with the spacing, with no order of its own.
  const double h_p = node_read_resolution_percent(0.25, 1.0);
  EXPECT_EQ(h_p, 12.5);
  EXPECT_EQ(assess_convergence(12.5, 6.25, 3.125, h_p).trend, Trend::converging);
  const auto read = observed_order(12.5, 6.25, 3.125, h_p);
  EXPECT_FALSE(read.order.has_value());
  EXPECT_EQ(read.note, "within half a node spacing on every mesh");
  // MPC ss there: +87.5 -> +93.8 -> +96.9 % is further off than half a node: settled.
  EXPECT_EQ(assess_convergence(87.5, 93.75, 96.875, h_p).trend, Trend::settled);
  // MPC ss on the S(1/7) mesh: +2.16 -> +0.58 -> +0.25 % moves by far more: an order.
  const auto mpc = observed_order(2.16, 0.58, 0.25, resolution);
  ASSERT_TRUE(mpc.order.has_value()) << mpc.note;
  EXPECT_TRUE(Near(*mpc.order, 0.5 * std::log2(2.16 / 0.25), {1e-12, 0}));  // machine precision
}

// Requirement: a read that steps exactly one node per halving (its fall equal to its floor, up
// to round-off) gets one verdict whichever way the last digits fall: it neither settles nor
// converges (CM_p AL ss c/a printed "not converging", a like row "converging", on 3e-9).
TEST(AssessConvergence, AFallEqualToItsFloorIsDecidedByNoRoundOff) {
  const double r = node_read_resolution_percent(0.125, 0.7071);  // 17.68 points on C
  for (const double last_digits : {-1e-12, 0.0, 1e-12}) {
    const double e_f = 30.0 - r * (1.0 + last_digits);
    EXPECT_EQ(assess_convergence(30.0, 30.0 - r / 2, e_f, r).trend, Trend::not_converging)
        << last_digits;
  }
}

// Requirement: two F errors differ only beyond their pair's noise: the study's 0.01 points,
// what one refinement changes in either, or two reads' resolutions together, whichever is
// largest (CM_p Q8 c/a pairs one F node apart, 2.21 + 2.21 points).
TEST(PairNoise, IsTheLargestOfResolutionChangesAndReads) {
  EXPECT_EQ(pair_noise_points(0.0, 0.0), kErrorResolutionPercent);
  EXPECT_EQ(pair_noise_points(2.7, 0.4), 2.7);
  EXPECT_EQ(pair_noise_points(0.4, 2.7), 2.7);
  EXPECT_NEAR(pair_noise_points(1.0, 0.5, 2.21, 2.21), 4.42, 1e-12);
  EXPECT_EQ(pair_noise_points(5.0, 0.5, 2.21, 2.21), 5.0);
}

TEST(NodeReadResolution, IsZeroWithoutAPositiveFiniteSpacingAndExactValue) {
  EXPECT_TRUE(Near(node_read_resolution_percent(0.5, -2.0), 12.5, {1e-15, 0}));  // |exact|
  EXPECT_EQ(node_read_resolution_percent(0.0, 1.0), 0.0);
  EXPECT_EQ(node_read_resolution_percent(0.1, 0.0), 0.0);
  EXPECT_EQ(node_read_resolution_percent(kNaN, 1.0), 0.0);
  EXPECT_EQ(node_read_resolution_percent(0.1, kNaN), 0.0);
  EXPECT_TRUE(within_resolution(-6.25, 6.25));  // an edge at a node: exactly half a node off
  EXPECT_FALSE(within_resolution(6.3, 6.25));
  EXPECT_FALSE(within_resolution(0.0, 0.0));  // a value read at a point has no such band
  EXPECT_FALSE(within_resolution(kNaN, 1.0));
}

TEST(ObservedOrder, OrderTwoOfAnExactPowerLaw) {
  const auto o = observed_order(4.0, 1.0, 0.25);
  ASSERT_TRUE(o.order.has_value()) << o.note;
  EXPECT_TRUE(Near(*o.order, 2.0, {1e-12, 0}));  // machine precision
  EXPECT_TRUE(o.note.empty());
}

TEST(ObservedOrder, NoOrderForThePreAsymptoticMpcRow) {
  // Issue 23: S(1/3) Q4 MPC ss runs 445 -> 310 -> 0.68 %, once fitted an order of 4.7.
  const auto o = observed_order(445.0, 310.0, 0.68);
  EXPECT_FALSE(o.order.has_value());
  ASSERT_TRUE(o.pair_orders[0] && o.pair_orders[1]);
  EXPECT_TRUE(Near(*o.pair_orders[0], std::log2(445.0 / 310.0), {1e-12, 0}));
  EXPECT_NE(o.note.find("pre-asymptotic"), std::string::npos) << o.note;
  // H_p Q4 MPC ss: -116 -> -39 -> -4.8 %, pair orders 1.57 and 3.02.
  EXPECT_FALSE(observed_order(-116.0, -39.0, -4.8).order.has_value());
}

TEST(ObservedOrder, NoOrderFromAMeshThatDoesNotResolveTheQuantity) {
  // S(1/7) Q8 MPC ns sigma_c: +427.3 -> +65.0 -> +5.04 %, pair orders 2.72 and 3.69: within
  // one order of each other, once given an order of 3.20, beyond what Q8 delivers at an edge.
  const auto o = observed_order(427.3, 65.0, 5.04);
  EXPECT_FALSE(o.order.has_value());
  EXPECT_LE(std::abs(*o.pair_orders[0] - *o.pair_orders[1]), kAsymptoticOrderSpread);
  EXPECT_NE(o.note.find("427 % on C or M: not resolved"), std::string::npos) << o.note;
  // Below 100 % on C and M the same shape has its order.
  const auto resolved = observed_order(80.0, 20.0, 5.0);
  ASSERT_TRUE(resolved.order.has_value()) << resolved.note;
  EXPECT_TRUE(Near(*resolved.order, 2.0, {1e-12, 0}));  // machine precision
}

TEST(ObservedOrder, NoOrderThroughZeroOrFromAChangeWithinItsFloor) {
  // H_a Q4 AL ss sigma_c: +3.74 -> +1.92 -> -0.77 %, magnitudes falling, once order 1.14.
  const auto through_zero = observed_order(3.74, 1.92, -0.77);
  EXPECT_EQ(assess_convergence(3.74, 1.92, -0.77).trend, Trend::converging);
  EXPECT_FALSE(through_zero.order.has_value());
  EXPECT_EQ(through_zero.note, "changes sign");
  // H_a Q4 MPC ns: +55.4 -> +44.5 -> +41.9 %: M -> F moves 2.6 points, within the floor of
  // 4.19 (a tenth of e_F); it once had order 0.20.
  const auto plateau_on_f = observed_order(55.4, 44.5, 41.9);
  EXPECT_FALSE(plateau_on_f.order.has_value());
  EXPECT_EQ(plateau_on_f.note, "at noise level");
}

TEST(AssessConvergence, AValueReadBetweenNodesHasAFloorPerMeshPair) {
  // A stick-zone edge read between nodes 10 points apart on C (resolution 10, 5 on M):
  // +23.7 -> +14.9 -> +6.07 % moves by 8.8 twice: within C's half spacing, beyond M's, and
  // falls by more than C's: converging, with no order (C -> M is within its floor).
  const auto a = assess_convergence(23.7, 14.9, 6.07, 10.0);
  EXPECT_EQ(a.trend, Trend::converging);
  EXPECT_EQ(a.pair_floors[0], 10.0);
  EXPECT_EQ(a.pair_floors[1], 5.0);
  EXPECT_EQ(observed_order(23.7, 14.9, 6.07, 10.0).note, "at noise level");
  // +40 -> +10 -> +2.5 % resolves both pairs: order 2.
  const auto resolved = observed_order(40.0, 10.0, 2.5, 10.0);
  ASSERT_TRUE(resolved.order.has_value()) << resolved.note;
  EXPECT_TRUE(Near(*resolved.order, 2.0, {1e-12, 0}));  // machine precision
}

TEST(ObservedOrder, NoOrderForNoiseOrNonMonotoneSequences) {
  const auto plateau = observed_order(-0.3194, -0.3217, -0.3130);
  EXPECT_FALSE(plateau.order.has_value());
  EXPECT_EQ(plateau.note, "at noise level");
  const auto round_off = observed_order(4.0, 1.0, 1e-12);
  EXPECT_FALSE(round_off.order.has_value());
  EXPECT_FALSE(round_off.pair_orders[1].has_value());  // 1e-12 % is round-off
  EXPECT_EQ(round_off.note, "at noise level");
  const auto growing = observed_order(1.0, 2.0, 3.0);
  EXPECT_FALSE(growing.order.has_value());
  EXPECT_EQ(growing.note, "not monotone");
  // 4 -> 4.05 -> 1: converging (the growth on M is within the floor of 0.1), so p1 < 0 comes
  // from a change at noise level.
  const auto dip = observed_order(4.0, 4.05, 1.0);
  EXPECT_FALSE(dip.order.has_value());
  EXPECT_EQ(dip.note, "at noise level");
  // A read that stops at one node on M and F (CM_p Q8 AL mortar c/a, +14.9/+1.65/+1.65 %):
  // converging, no order, and no "not monotone".
  EXPECT_EQ(observed_order(14.9, 1.65, 1.65, 8.839).note, "at noise level");
  // Not converging, with one pair within its floor: not monotone, not noise.
  EXPECT_EQ(observed_order(-0.47, -0.61, -0.56).note, "not monotone");
  // Falling on both pairs by exactly the floors of a read between nodes, one node per halving,
  // yet converging by the trend (as CM_p Q8 AL ns c/a, +14.9/+6.07/+1.65 % with floors 8.839
  // and 4.419 points): no change is beyond its floor, so no order (it read "converging, 1.59").
  const auto step = observed_order(14.9, 14.9 - 8.839, 14.9 - 8.839 - 4.4195, 8.839);
  EXPECT_FALSE(step.order.has_value());
  EXPECT_EQ(step.note, "at noise level");
  // Falling on both pairs by exactly the floors (as CM_p Q4 AL ss c/a, +23.7/+14.9/+6.07 %),
  // by less than C's floor in all: monotone, refused by the trend, not settled.
  EXPECT_EQ(observed_order(24.0, 16.0, 8.0, 16.0).note,
            "falls within its floors: not converging by the trend");
}

TEST(PairOrder, MissingOrRoundOffErrorsHaveNoOrder) {
  EXPECT_TRUE(Near(*pair_order(4.0, 1.0), 2.0, {1e-12, 0}));
  EXPECT_TRUE(Near(*pair_order(-4.0, 2.0), 1.0, {1e-12, 0}));  // magnitudes
  EXPECT_FALSE(pair_order(std::nullopt, 1.0).has_value());
  EXPECT_FALSE(pair_order(1.0, 1e-9).has_value());
}

TEST(LuckOfOneMesh, AFineGradeAfterAnUnresolvedMesh) {
  EXPECT_TRUE(luck_of_one_mesh(445.0, 310.0, 0.68));   // e on F
  EXPECT_TRUE(luck_of_one_mesh(-116.0, -39.0, -4.8));  // g on F, from C
  EXPECT_TRUE(luck_of_one_mesh(0.0, 100.0, 4.0));      // from M; missing C passed as 0
  EXPECT_FALSE(luck_of_one_mesh(99.0, 60.0, 0.5));     // never unresolved
  EXPECT_FALSE(luck_of_one_mesh(445.0, 310.0, 5.0));   // s on F: no good grade to discount
}

}  // namespace
}  // namespace cs::grading

// Requirement: one more mesh is judged by the noise-aware trend over M, F, VF: a bias that is
// the same on every mesh is a plateau, not convergence; only an error at the study's resolution
// counts as settled for good; a read between nodes within half a node on every mesh converges.
TEST(FurtherRefinement, APlateauAtANonzeroErrorIsNotConvergence) {
  using cs::grading::further_refinement;
  using cs::grading::FurtherRefinement;
  EXPECT_EQ(further_refinement(0.71, 0.71, 0.71), FurtherRefinement::plateau);   // P_a Q8 AL ns
  EXPECT_EQ(further_refinement(-0.23, -0.30, -0.30), FurtherRefinement::fails);  // H_p sigma_h
  EXPECT_EQ(further_refinement(3e-12, -2e-12, 1.6e-11), FurtherRefinement::at_resolution);
  EXPECT_EQ(further_refinement(4.0, 2.0, 1.0), FurtherRefinement::converges);
  EXPECT_EQ(further_refinement(-2.0, 1.0, 0.5), FurtherRefinement::converges);  // sign aside
  EXPECT_EQ(further_refinement(1.0, 1.0, 1.5), FurtherRefinement::fails);
  EXPECT_EQ(further_refinement(1.0, 1.0, std::nan("")), FurtherRefinement::fails);
  // A value read between two nodes, resolution 6.25 points on M (H_p Q4 a_FE): half a node
  // off on M, F and VF converges with the spacing.
  EXPECT_EQ(further_refinement(6.25, 3.125, 1.5625, 6.25), FurtherRefinement::converges);
}
