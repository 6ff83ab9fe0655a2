#pragma once
// The friction problems (those grading the peak shear tau_max: FP_p, CM_p): the grade of every
// option on every graded quantity, and LMP beside PLM. Without friction the study merges them;
// with friction LMP enforces stick by a tangential penalty (a sticking point slips elastically
// by its shear over kt) and PLM by multipliers (no slip increment at all), so they differ
// wherever the shear varies along the contact. The section states by how much, from the rows.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The largest |LMP - PLM| difference of the fine-mesh errors of one problem, and where.
struct LmpPlmDifference {
  double points = 0.0;  ///< |error(LMP) - error(PLM)| on F, percentage points
  schema::Quantity quantity = schema::Quantity::tau_max;
  schema::Element element = schema::Element::Q4;
  schema::ContactKind contact = schema::ContactKind::ss;
  int n_pairs = 0;  ///< pairs of rows (element, contact, quantity) with both on F
  int n_equal = 0;  ///< of which equal to within 0.01 percentage points
  /// Every pair within the study's resolution of the largest difference ("τ̄max, Q4 ss"): a tie
  /// is named whole.
  std::vector<std::string> largest_at;
  /// The largest pair's noise (grading::pair_noise_points), and the pairs that differ by more
  /// than their own noise: a smaller difference is not resolved by these meshes.
  double largest_noise = 0.0;
  int n_beyond_noise = 0;
};

/// The LMP-PLM comparison of `problem` over every element, contact and quantity (empty
/// n_pairs when the results hold no such pair).
LmpPlmDifference lmp_plm_difference(const ResultsIndex& index, schema::ProblemId problem);

/// The section (empty when the results hold no baseline row of a friction problem).
std::string friction_section(const ResultsIndex& index);

}  // namespace cs::reports
