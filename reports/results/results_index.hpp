#pragma once
// Lookups over a results document (schema/results_file.hpp): the problems in the report's
// order, the row of an option set, the case behind a row's mesh, the status of each mesh. The
// "baseline" rows are the study's option sets (our solver, or in results without a row of ours
// the other solver first by name, so that an imported code's results read like ours; a
// discretized target, patch-recovered nodal stresses, no parameter overrides); the same option sets
// with extrapolated nodal stresses are "recovery twins" of the baseline rows (compared in their own
// section); every other row (a rigid target, overrides, another solver) is a "variant",
// reported in its own section.

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "schema/results_file.hpp"

namespace cs::reports {

/// The study's mesh levels in order: C, M, F (index i of RowVerdict::values is kMeshes[i]); the
/// fourth level, VF, is in RowVerdict::refinement and has its own report section.
inline constexpr auto kMeshes = schema::kStudyMeshes;
/// The position of a mesh level in RowVerdict::values.
constexpr std::size_t mesh_index(schema::MeshLevel m) {
  return static_cast<std::size_t>(m);
}
/// The finest mesh level (F): the one the study grades.
inline constexpr schema::MeshLevel kFinestMesh = kMeshes.back();

/// A finite number, or nullopt for NaN and infinities (the schema's "no value").
std::optional<double> finite(double v);

/// An option set of a row, less element: contact algorithm and contact discretization.
struct Option {
  schema::Algorithm algorithm = schema::Algorithm::AL;
  schema::ContactKind contact = schema::ContactKind::ss;
  /// "LMP ss".
  std::string label() const;
  friend bool operator==(const Option&, const Option&) = default;
  friend auto operator<=>(const Option&, const Option&) = default;
};

/// Every option set in the vocabulary's order: each algorithm with each contact type.
const std::vector<Option>& all_options();

/// How a row's case on one mesh ended.
enum class MeshState { missing, failed, not_converged, converged };

/// The option variant of a case or row, as its id spells it after the option fields: "" for
/// the study's options, else e.g. "rigid/fkn=10", "extrapolated" or "@calculix".
std::string variant_of(const schema::CaseSpec& spec);

/// Read-only lookups over one results document (which it references: keep it alive).
class ResultsIndex {
 public:
  explicit ResultsIndex(const schema::ResultsDocument& results);

  const schema::ResultsDocument& results() const { return results_; }

  /// The document's problems in the study's appendix order (Tables 3-14: by the first table
  /// number each records), problems without a study table last, in battery order.
  const std::vector<const schema::ProblemRecord*>& problems() const { return problems_; }
  /// The record of a problem, or nullptr when the document has none.
  const schema::ProblemRecord* problem(schema::ProblemId id) const;
  /// How a problem defines a quantity, or nullptr.
  const schema::QuantityDefinition* definition(schema::ProblemId id, schema::Quantity q) const;
  /// True when the problem is recorded as singular (graded by Eq. 47, not accuracy).
  bool singular(schema::ProblemId id) const;

  /// The baseline row of an option set, or nullptr when it is not in the document.
  const schema::RowVerdict* row(schema::ProblemId problem, schema::Quantity quantity,
                                schema::Element element, const Option& option) const;
  /// The case behind a row on one mesh, or nullptr.
  const schema::CaseResult* case_of(const schema::RowVerdict& row, schema::MeshLevel mesh) const;
  /// The row's quantity in the case of one mesh, or nullptr.
  const schema::QuantityResult* quantity_of(const schema::RowVerdict& row,
                                            schema::MeshLevel mesh) const;
  MeshState state(const schema::RowVerdict& row, schema::MeshLevel mesh) const;
  /// True when any mesh of the row did not converge (values are last iterates).
  bool any_not_converged(const schema::RowVerdict& row) const;
  /// True when the row has values on all three meshes.
  static bool complete(const schema::RowVerdict& row);

  /// The baseline rows in document order.
  const std::vector<const schema::RowVerdict*>& baseline_rows() const { return baseline_; }
  /// The variant rows in document order.
  const std::vector<const schema::RowVerdict*>& variant_rows() const { return variants_; }
  /// The baseline row's twin with extrapolated nodal stresses, or nullptr.
  const schema::RowVerdict* extrapolated_twin(const schema::RowVerdict& baseline) const;
  /// True when any baseline row has an extrapolated twin.
  bool has_extrapolated_twins() const { return !extrapolated_by_key_.empty(); }

  /// Baseline option sets present for (problem, quantity, element), in all_options() order.
  std::vector<Option> options_present(schema::ProblemId problem, schema::Quantity quantity,
                                      schema::Element element) const;
  /// True when any baseline row exists for (problem, quantity, element).
  bool has(schema::ProblemId problem, schema::Quantity quantity, schema::Element element) const;

  /// The exact value of a row's quantity (from its first case that has it), if finite.
  std::optional<double> exact_of(const schema::RowVerdict& row) const;
  /// The resolution on `mesh` of a row whose quantity is read between two nodes
  /// (schema::read_between_nodes), in percentage points: grading::node_read_resolution_percent
  /// of the node spacing along the contact (the case's element size h; h/2 with Q8's mid-side
  /// nodes) and the exact value. 0 for a quantity read at a point, or without that case.
  double read_resolution_percent(const schema::RowVerdict& row, schema::MeshLevel mesh) const;
  /// The study's printed exact value recorded in the row's cases (`study_exact`), if any.
  std::optional<double> study_exact_of(const schema::RowVerdict& row) const;

 private:
  using RowKey = std::tuple<schema::ProblemId, schema::Quantity, schema::Element, schema::Algorithm,
                            schema::ContactKind>;
  static RowKey key_of(const schema::RowVerdict& row);

  const schema::ResultsDocument& results_;
  std::vector<const schema::ProblemRecord*> problems_;
  std::map<RowKey, const schema::RowVerdict*> baseline_by_key_;
  std::map<RowKey, const schema::RowVerdict*> extrapolated_by_key_;
  /// By case key (the case id less its mesh) and mesh.
  std::map<std::pair<std::string, schema::MeshLevel>, const schema::CaseResult*> case_by_key_;
  std::vector<const schema::RowVerdict*> baseline_;
  std::vector<const schema::RowVerdict*> variants_;
};

}  // namespace cs::reports
