#pragma once
// The study's appendix Tables 3-14, side by side with ours: for each problem, quantity,
// element and contact type, the C, M and F rows; per study column (AL, PM; LMP, PLM; IMC) our
// values and errors beside the study's ANSYS value (the mapping is in
// results/study_reference.hpp); the exact value (ours, and the study's printed one) above each
// group of tables, as the study prints it.

#include <optional>
#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/results/study_reference.hpp"

namespace cs::reports {

/// One table: one problem, quantity, element and contact type; rows C, M, F.
struct AppendixTable {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::Element element = schema::Element::Q4;
  schema::ContactKind contact = schema::ContactKind::ss;
  std::string title;                 ///< Markdown
  std::vector<std::string> columns;  ///< "Mesh", "h", our algorithm classes, "ANSYS ..." columns
  std::vector<std::vector<std::string>> rows;  ///< rows[i][0] is the mesh: C, M, F
  std::vector<std::string> notes;

  /// The cell of `mesh` under `column`, or nullopt.
  std::optional<std::string> cell(schema::MeshLevel mesh, const std::string& column) const;
  std::string markdown() const;
};

/// One table per (problem, quantity, element, contact) present, in the study's order.
std::vector<AppendixTable> build_appendix_tables(const ResultsIndex& index,
                                                 const StudyReference& study);

/// The line above a problem's tables: the quantity, our exact value and the study's.
std::string exact_value_line(const ResultsIndex& index, const StudyReference& study,
                             schema::ProblemId problem, schema::Quantity quantity);

/// The report section "Appendix tables" (empty when no baseline row is present).
std::string appendix_section(const ResultsIndex& index, const StudyReference& study);

}  // namespace cs::reports
