#pragma once
// What the errors of one quantity on the meshes C, M, F (h halving per level) say about
// convergence: the study's flag, a noise-aware verdict, the observed order and the one-mesh
// luck rule. Errors are signed percentages (grading/accuracy.hpp); each rule reads them as
// stated in its comment.

#include <array>
#include <optional>
#include <string>

#include "schema/convergence_trend.hpp"

namespace cs::grading {

using schema::Trend;

/// The resolution of the study's printed values (4 decimals of a value of order 1, i.e. 0.01
/// percentage points): differences below it count as equal.
inline constexpr double kErrorResolutionPercent = 0.01;

/// The noise of two rows' F errors (points): what one refinement changes in either (their
/// |e_F - e_M|), the two reads' resolutions together where they are read between nodes (r_a +
/// r_b: CM_p Q8 c/a one F node apart, 4.42 points), or the study's resolution
/// kErrorResolutionPercent, whichever is largest. Two F errors, or their magnitudes, differ only
/// by more than this (H_a sigma_c -0.789 % vs -0.775 %, moving 2.7 points from M to F, do not).
double pair_noise_points(double m_to_f_change_a, double m_to_f_change_b, double resolution_a = 0.0,
                         double resolution_b = 0.0);

/// The study's 'c' (Table 2): with |e| the error magnitudes and r = kErrorResolutionPercent,
///   |e_M| <= |e_C| + r  and  |e_F| <= |e_M| + r  (never grows)
///   and (|e_F| < |e_C| - r  or  |e_C| <= r)      (improves, or exact on every mesh).
/// False when an error is not finite. It is the study's rule, printed as the study's `c`.
bool study_converging(double e_c, double e_m, double e_f);

/// The noise-aware verdict, the floor below which a change is noise, and which bound set it.
struct ConvergenceAssessment {
  Trend trend = Trend::not_converging;
  double floor_percent = 0.0;           ///< percentage points: C -> M's (the larger)
  std::array<double, 2> pair_floors{};  ///< C -> M, M -> F
  std::string floor_reason;
};

/// A change of the error smaller than a tenth of the error itself cannot be told from its
/// plateau.
inline constexpr double kPlateauFraction = 0.1;

/// The resolution of a quantity read between two nodes (an edge of the contact or stick zone,
/// placed halfway between the last node in the zone and the next): half the node spacing s at
/// the contact, in percentage points of the exact value x: 100 (s / 2) / |x|. A change of its
/// error smaller than this is a step from one node to the next, not convergence. 0 when s or x
/// is not a positive finite length.
double node_read_resolution_percent(double node_spacing, double exact);

/// True when a read's error is within its resolution r > 0 (|e| <= r, an edge at a node reading
/// exactly half a node off included): as close as the read can tell.
bool within_resolution(double error_percent, double resolution_percent);

/// The noise-aware convergence verdict of the errors on C, M, F, with a floor per mesh pair:
///   base = max(kErrorResolutionPercent, kPlateauFraction |e_F|); r = `resolution_percent`,
///          the quantity's own resolution on C (0 for a value read at a point;
///          node_read_resolution_percent on C for one read between two nodes, which halves
///          with h); f1 = max(base, r) for C -> M and f2 = max(base, r/2) for M -> F;
///   converging     when r > 0 and |e_C| <= r, |e_M| <= r/2, |e_F| <= r/4: the read is as
///                  close as its resolution on every mesh, and that halves with h;
///   settled        when |e_M - e_C| < f1 and |e_F - e_M| < f2 (a plateau: the grade tells how
///                  good it is);
///   converging     when |e_M| <= |e_C| + f1, |e_F| <= |e_M| + f2 and |e_F| < |e_C| - f1;
///   not_converging otherwise, and when an error is not finite.
/// A plateau reached through noise of a few thousandths of a point (S(1/3) Q8 LMP ss
/// -0.3194/-0.3217/-0.3130 %, ns -0.3238/-0.3239/-0.3124 %) is settled either way, where the
/// study's flag tells the two apart on a 0.001-point difference. A contact half-width read
/// between nodes (S(1/7) Q4, r = 0.038 points) that moves by 0.02 from C to M is within C's
/// floor; one that is half a node off on every mesh (H_p Q4: +12.5/+6.25/+3.12 %, r = 12.5)
/// converges.
ConvergenceAssessment assess_convergence(double e_c, double e_m, double e_f,
                                         double resolution_percent = 0.0);

/// What one more mesh (VF, h/8) says of a row, judged by the noise-aware trend over M, F, VF
/// (assess_convergence with r = `resolution_on_m`, the quantity's own resolution on M):
///   converges      when that trend is converging (within half a node on every mesh included);
///   at_resolution  when it is settled with |e_VF| <= kErrorResolutionPercent: nothing is left
///                  to converge (a patch test at round-off);
///   plateau        when it is settled at a larger error: a bias refinement does not remove
///                  (P_a Q8 AL ns +0.71 % on C, M, F and VF), not convergence to the exact value;
///   fails          otherwise (not converging, or an error not finite).
enum class FurtherRefinement { converges, at_resolution, plateau, fails };
FurtherRefinement further_refinement(double e_m, double e_f, double e_vf,
                                     double resolution_on_m = 0.0);

/// The observed order of one mesh pair (h halving), log2(|e_coarse| / |e_fine|); empty where
/// an error is missing or below schema::kErrorNoiseFloorPercent (round-off: no order fitted).
std::optional<double> pair_order(const std::optional<double>& e_coarse,
                                 const std::optional<double>& e_fine);

/// An error at or above this on C or M means the mesh does not resolve the quantity at all:
/// to fall from it into the g band (< 5 %) within two halvings of h, the error must shrink
/// 20-fold, an order above log2(20)/2 = 2.2 per halving, beyond what these elements deliver
/// at a contact edge.
inline constexpr double kUnresolvedErrorPercent = 100.0;

/// True when C or M does not resolve the quantity: max(|e_C|, |e_M|) >= kUnresolvedErrorPercent.
bool unresolved(double e_c, double e_m);

/// The largest spread of the two pair orders for which the sequence counts as in its
/// asymptotic range: within one order of each other.
inline constexpr double kAsymptoticOrderSpread = 1.0;

/// The observed order of the error and the pair orders it comes from.
struct ObservedOrder {
  std::array<std::optional<double>, 2> pair_orders;  ///< C->M, M->F (see pair_order)
  std::optional<double> order;                       ///< (p1 + p2) / 2 when it can be trusted
  std::string note;                                  ///< why there is no order
};

/// Pair orders p1 = log2(|e_C|/|e_M|), p2 = log2(|e_M|/|e_F|) (see pair_order) and their mean
/// as the observed order, given only when assess_convergence (with `resolution_percent`) finds
/// the sequence converging, each pair's change is at least its floor, p1 > 0, p2 > 0, the error
/// keeps its sign, |p1 - p2| <= kAsymptoticOrderSpread and neither C nor M is unresolved
/// (|e| < kUnresolvedErrorPercent). Otherwise `note` says why: "within half a node spacing on
/// every mesh" (the order would be the read's, not the solution's), "at noise level" (an error
/// at round-off, the trend settled, or one pair's change within its floor), "not monotone" (the
/// trend is not converging, or an error grows within the floor), "falls within its floors: not
/// converging by the trend" (the magnitudes fall on both pairs, by no more than the floors: CM_p
/// Q4 AL ss c/a +23.7/+14.9/+6.07 %, one node per halving against floors of 17.7 and 8.84),
/// "changes sign" (H_a Q4 AL ss sigma_c +3.74 -> +1.92 -> -0.77 %: magnitudes through zero give no
/// order), "pre-asymptotic (p1 = .., p2 = .. differ by ..)" or "pre-asymptotic (.. % on C or M: not
/// resolved)". 4 -> 1 -> 0.25 has order 2; 445 -> 310 -> 0.68 (p1 0.52, p2 8.8) has none, nor has
/// 427 -> 65 -> 5.0 (p1 2.7, p2 3.7: within one order, but from a mesh that does not resolve the
/// quantity).
ObservedOrder observed_order(double e_c, double e_m, double e_f, double resolution_percent = 0.0);

/// The luck of one mesh: the F error grades e or g (Eq. 46) after an error of at least
/// kUnresolvedErrorPercent on C or M: max(|e_C|, |e_M|) >= 100 and |e_F| < 5. Such a fine
/// grade is not evidence for the option. Pass 0 for a missing C or M error.
bool luck_of_one_mesh(double e_c, double e_m, double e_f);

}  // namespace cs::grading
