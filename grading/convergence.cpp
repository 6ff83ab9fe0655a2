#include "grading/convergence.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "schema/row_verdict.hpp"

namespace cs::grading {
namespace {

bool all_finite(double a, double b, double c) {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c);
}

/// |e| never grows by more than `tol` from C to M to F.
bool never_grows(double c, double m, double f, double tol) {
  return m <= c + tol && f <= m + tol;
}

/// |e| within the read's resolution on every mesh: r on C, r/2 on M, r/4 on F (h halves).
bool within_read_resolution(double e_c, double e_m, double e_f, double r) {
  return within_resolution(e_c, r) && within_resolution(e_m, r / 2) &&
         within_resolution(e_f, r / 4);
}

}  // namespace

double pair_noise_points(double m_to_f_change_a, double m_to_f_change_b, double resolution_a,
                         double resolution_b) {
  return std::max({kErrorResolutionPercent, m_to_f_change_a, m_to_f_change_b,
                   std::max(resolution_a, 0.0) + std::max(resolution_b, 0.0)});
}

bool study_converging(double e_c, double e_m, double e_f) {
  const double c = std::abs(e_c), m = std::abs(e_m), f = std::abs(e_f);
  if (!all_finite(c, m, f))
    return false;
  constexpr double tol = kErrorResolutionPercent;
  return never_grows(c, m, f, tol) && (f < c - tol || c <= tol);
}

bool within_resolution(double error_percent, double resolution_percent) {
  // An edge at a node reads exactly half a node off: equality within round-off counts.
  return resolution_percent > 0.0 && std::abs(error_percent) <= resolution_percent * (1.0 + 1e-9);
}

double node_read_resolution_percent(double node_spacing, double exact) {
  if (!(node_spacing > 0.0) || !std::isfinite(node_spacing) || !(std::abs(exact) > 0.0) ||
      !std::isfinite(exact))
    return 0.0;
  return 100.0 * 0.5 * node_spacing / std::abs(exact);
}

namespace {

/// A change beyond its floor by more than round-off: an order needs both; a read stepping exactly
/// one node per halving (its changes equal to the floors) gives none.
bool beyond(double change, double floor) {
  return change > floor * (1.0 + 1e-9);
}

/// A change below its floor by more than round-off.
bool below(double change, double floor) {
  return change < floor * (1.0 - 1e-9);
}

}  // namespace

ConvergenceAssessment assess_convergence(double e_c, double e_m, double e_f,
                                         double resolution_percent) {
  ConvergenceAssessment out;
  if (within_read_resolution(e_c, e_m, e_f, resolution_percent)) {
    out.trend = Trend::converging;
    out.floor_percent = resolution_percent;
    out.pair_floors = {resolution_percent, resolution_percent / 2};
    out.floor_reason = fmt::format(
        "within half a node spacing on every mesh ({:.3g} points on C): the read converges "
        "with the spacing",
        resolution_percent);
    return out;
  }
  const double relative = kPlateauFraction * std::abs(e_f);
  const double base = std::max(relative, kErrorResolutionPercent);
  out.pair_floors = {std::max(base, resolution_percent), std::max(base, resolution_percent / 2)};
  out.floor_percent = out.pair_floors[0];
  if (resolution_percent > base) {
    out.floor_reason = fmt::format(
        "half the node spacing on the coarser mesh of each pair ({:.3g} points on C): the "
        "resolution of a value read between two nodes",
        resolution_percent);
  } else if (relative > kErrorResolutionPercent) {
    out.floor_reason = fmt::format(
        "a tenth of the F error ({:.3g} points): a smaller change cannot be told from the "
        "error's plateau",
        relative);
  } else {
    out.floor_reason =
        fmt::format("{:g} percentage points: the resolution of the study's 4-decimal values",
                    kErrorResolutionPercent);
  }
  if (!all_finite(e_c, e_m, e_f))
    return out;  // not_converging
  // A change equal to its floor up to round-off (a read stepping exactly one node per halving)
  // is neither below it nor beyond it: such a row neither settles nor converges, whichever way
  // the last digits fall.
  const auto [f1, f2] = out.pair_floors;
  if (below(std::abs(e_m - e_c), f1) && below(std::abs(e_f - e_m), f2)) {
    out.trend = Trend::settled;
    return out;
  }
  const double c = std::abs(e_c), m = std::abs(e_m), f = std::abs(e_f);
  if (m <= c + f1 && f <= m + f2 && beyond(c - f, f1))
    out.trend = Trend::converging;
  return out;
}

std::optional<double> pair_order(const std::optional<double>& e_coarse,
                                 const std::optional<double>& e_fine) {
  if (!e_coarse || !e_fine)
    return std::nullopt;
  const double c = std::abs(*e_coarse), f = std::abs(*e_fine);
  if (c < schema::kErrorNoiseFloorPercent || f < schema::kErrorNoiseFloorPercent)
    return std::nullopt;
  return std::log2(c / f);
}

ObservedOrder observed_order(double e_c, double e_m, double e_f, double resolution_percent) {
  ObservedOrder out;
  out.pair_orders = {pair_order(e_c, e_m), pair_order(e_m, e_f)};
  const auto& [p1, p2] = out.pair_orders;
  if (within_read_resolution(e_c, e_m, e_f, resolution_percent)) {
    out.note = "within half a node spacing on every mesh";
    return out;
  }
  const ConvergenceAssessment a = assess_convergence(e_c, e_m, e_f, resolution_percent);
  if (!p1 || !p2 || a.trend == Trend::settled) {
    out.note = "at noise level";
    return out;
  }
  if (a.trend == Trend::converging && (!(*p1 > 0.0) || !(*p2 > 0.0))) {
    out.note = "at noise level";  // converging, but one pair does not fall beyond its floor
    return out;
  }
  if (a.trend != Trend::converging) {
    // Magnitudes that fall on both pairs but by no more than the floors (a read between nodes
    // stepping one node per halving) are monotone: the trend, not the order, refuses them.
    const bool falls = std::abs(e_c) > std::abs(e_m) && std::abs(e_m) > std::abs(e_f);
    out.note = falls ? "falls within its floors: not converging by the trend" : "not monotone";
    return out;
  }
  if (!beyond(std::abs(e_m - e_c), a.pair_floors[0]) ||
      !beyond(std::abs(e_f - e_m), a.pair_floors[1])) {
    out.note = "at noise level";  // one pair's change within its floor: no order from it
    return out;
  }
  if (e_c * e_m < 0.0 || e_m * e_f < 0.0) {
    out.note = "changes sign";  // through zero: the magnitudes' ratios are no order
    return out;
  }
  if (unresolved(e_c, e_m)) {
    out.note = fmt::format("pre-asymptotic ({:.0f} % on C or M: not resolved)",
                           std::max(std::abs(e_c), std::abs(e_m)));
    return out;
  }
  const double spread = std::abs(*p1 - *p2);
  if (!(spread <= kAsymptoticOrderSpread)) {
    out.note =
        fmt::format("pre-asymptotic (p1 = {:.2f}, p2 = {:.2f} differ by {:.2f})", *p1, *p2, spread);
    return out;
  }
  out.order = 0.5 * (*p1 + *p2);
  return out;
}

bool unresolved(double e_c, double e_m) {
  return std::max(std::abs(e_c), std::abs(e_m)) >= kUnresolvedErrorPercent;
}

bool luck_of_one_mesh(double e_c, double e_m, double e_f) {
  return unresolved(e_c, e_m) && !schema::is_worse(grade_of_error(e_f), schema::Grade::g);
}

FurtherRefinement further_refinement(double e_m, double e_f, double e_vf, double resolution_on_m) {
  switch (assess_convergence(e_m, e_f, e_vf, resolution_on_m).trend) {
    case Trend::converging:
      return FurtherRefinement::converges;
    case Trend::settled:
      return std::abs(e_vf) <= kErrorResolutionPercent ? FurtherRefinement::at_resolution
                                                       : FurtherRefinement::plateau;
    case Trend::not_converging:
      return FurtherRefinement::fails;
  }
  return FurtherRefinement::fails;
}

}  // namespace cs::grading
