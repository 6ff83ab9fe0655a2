#pragma once
// Lookups over a loaded results file: the row of an option set, the case behind a row's mesh,
// the status of each mesh. The "baseline" rows are the study's option sets (a discretized
// target, patch-recovered nodal stresses, no parameter overrides); the same option sets with
// extrapolated nodal stresses are "recovery twins" of the baseline rows (compared in their own
// section); rows with a rigid target or overrides are "variants", reported in their own section.

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "reports/results_file.hpp"

namespace cs::reports {

/// An option set of a row, less element: contact algorithm and contact discretization.
struct Option {
  std::string algorithm;  ///< AL PM LMP PLM MPC
  std::string contact;    ///< ss ns mortar
  std::string label() const { return algorithm + " " + contact; }
  friend bool operator==(const Option&, const Option&) = default;
  friend auto operator<=>(const Option&, const Option&) = default;
};

/// Every option set in the report's order: AL, PM, LMP, PLM, MPC, each with ss, ns, mortar.
const std::vector<Option>& all_options();
/// Index of an algorithm in AL, PM, LMP, PLM, MPC (for ordering); 99 if unknown.
int algorithm_order(const std::string& algorithm);
/// Index of a contact in ss, ns, mortar (for ordering); 99 if unknown.
int contact_order(const std::string& contact);

/// How a row's case on one mesh ended.
enum class MeshState { missing, failed, not_converged, converged };

/// Read-only lookups over one results file (which it references: keep it alive).
class ResultsIndex {
 public:
  explicit ResultsIndex(const ResultsFile& results);

  const ResultsFile& results() const { return results_; }

  /// The baseline row of an option set, or nullptr when it is not in the file.
  const RowRecord* row(const std::string& problem, const std::string& quantity,
                       const std::string& element, const Option& option) const;
  /// The case behind a row on one mesh (0 = C, 1 = M, 2 = F), or nullptr.
  const CaseRecord* case_of(const RowRecord& row, std::size_t mesh) const;
  /// The row's quantity in the case of one mesh, or nullptr.
  const QuantityRecord* quantity_of(const RowRecord& row, std::size_t mesh) const;
  MeshState state(const RowRecord& row, std::size_t mesh) const;
  /// True when any mesh of the row did not converge (values are last iterates).
  bool any_not_converged(const RowRecord& row) const;
  /// True when the row has values on all three meshes.
  static bool complete(const RowRecord& row);

  /// The baseline rows in file order.
  const std::vector<const RowRecord*>& baseline_rows() const { return baseline_; }
  /// The variant rows (rigid target or overrides) in file order.
  const std::vector<const RowRecord*>& variant_rows() const { return variants_; }
  /// The baseline row's twin with extrapolated nodal stresses, or nullptr.
  const RowRecord* extrapolated_twin(const RowRecord& baseline) const;
  /// True when any baseline row has an extrapolated twin.
  bool has_extrapolated_twins() const { return !extrapolated_by_key_.empty(); }

  /// Baseline option sets present for (problem, quantity, element), in all_options() order.
  std::vector<Option> options_present(const std::string& problem, const std::string& quantity,
                                      const std::string& element) const;
  /// True when any baseline row exists for (problem, quantity, element).
  bool has(const std::string& problem, const std::string& quantity,
           const std::string& element) const;

  /// The exact value of a row's quantity (from its first case that has it), if finite.
  std::optional<double> exact_of(const RowRecord& row) const;
  /// The study's printed exact value recorded in the row's cases (`study_exact`), if any.
  std::optional<double> study_exact_of(const RowRecord& row) const;

 private:
  using RowKey = std::tuple<std::string, std::string, std::string, std::string, std::string>;
  const ResultsFile& results_;
  std::map<RowKey, const RowRecord*> baseline_by_key_;
  std::map<RowKey, const RowRecord*> extrapolated_by_key_;
  std::map<std::string, const CaseRecord*> case_by_id_key_;  ///< case key + "#" + mesh
  std::vector<const RowRecord*> baseline_;
  std::vector<const RowRecord*> variants_;
};

}  // namespace cs::reports
