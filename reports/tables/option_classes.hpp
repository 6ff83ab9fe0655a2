#pragma once
// Which of our option sets give the same results. The study groups AL with PM and LMP with
// PLM ("the same for these pairs of algorithms with frictionless contact") and does not
// separate ss from ns for LMP, PLM and IMC. Ours are separate implementations, so the report
// computes whether they coincide, and merges them into one column only when they do.
//
// Two option sets coincide on a (problem, quantity, element) slot when both rows have values
// on the same meshes, their cases ended the same way on each mesh (converged, not converged,
// failed, missing), and every pair of values coincides (grading::values_coincide: within 0.01 %,
// the resolution of the study's 4-decimal values and of the convergence verdict).

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// A (problem, quantity, element) on which option sets are compared.
struct Slot {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::Element element = schema::Element::Q4;
};

/// How two option sets compare over a list of slots.
struct OptionComparison {
  int compared = 0;         ///< slots where both rows exist
  int differing = 0;        ///< of those, slots where they do not coincide
  int only_one = 0;         ///< slots where exactly one of the two rows exists
  int states_differ = 0;    ///< compared slots where the cases ended differently on a mesh
  double max_relative = 0;  ///< largest |a - b| / max(|a|, |b|) over compared values
  std::string where_max;    ///< "H_p sigma_c Q4 F" of the largest difference
  bool coincide() const { return compared > 0 && differing == 0; }
};

OptionComparison compare_options(const ResultsIndex& index, const Option& a, const Option& b,
                                 const std::vector<Slot>& slots);

/// A set of option sets that coincide with each other on every compared slot.
struct OptionClass {
  std::vector<Option> members;  ///< in all_options() order
  /// "AL = PM (ss)", "LMP = PLM (ss = ns)", "MPC (ns)", or "LMP ss = PLM ns".
  std::string label() const;
};

/// Partitions `candidates` (those with at least one row on the slots) into classes of option
/// sets that coincide pairwise. Candidates without any row are left out.
std::vector<OptionClass> coincidence_classes(const ResultsIndex& index,
                                             const std::vector<Option>& candidates,
                                             const std::vector<Slot>& slots);

/// The row of a class on a slot: that of its first member that has one, or nullptr.
const schema::RowVerdict* class_row(const ResultsIndex& index, const OptionClass& cls,
                                    const Slot& slot);

}  // namespace cs::reports
