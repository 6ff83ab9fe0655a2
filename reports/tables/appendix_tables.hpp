#pragma once
// The study's appendix Tables 3-14, side by side with ours: per problem, quantity, element and
// contact type, rows C, M, F; per study column our values and signed errors beside the study's
// ANSYS value (schema/study_reference.hpp maps the columns); the exact values above each group.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"
#include "schema/study_reference.hpp"

namespace cs::reports {

/// One table: one problem, quantity, element and contact type; rows C, M, F; columns "Mesh",
/// "h", our classes of coinciding algorithms ("AL = PM"), "ANSYS <study column>".
struct AppendixTableFacts {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::Element element = schema::Element::Q4;
  schema::ContactKind contact = schema::ContactKind::ss;
  MarkdownTable table{{}};
  std::set<std::string> study_tables{};  ///< the study's tables the ANSYS values come from
  bool merged = false;                   ///< a column stands for coinciding algorithms
  bool via_note = false, missing = false, failed = false, not_converged = false;
  bool extrapolated = false;  ///< our values are those of extrapolated stresses (ANSYS's basis)
};

/// One table per (problem, quantity, element, contact) present, in the study's order.
std::vector<AppendixTableFacts> build_appendix_tables(const ResultsIndex& index,
                                                      const schema::StudyReference& study);

/// The exact value above a problem's tables: ours, and the study's printed one.
struct ExactValueFacts {
  bool singular = false;
  std::optional<double> exact;    ///< ours (the physically consistent value)
  std::optional<double> printed;  ///< the study's printed value, where a number other than ours
  std::optional<double> printed_shift;  ///< (printed - ours) / ours, percent
  std::optional<double> convention;     ///< under the study's convention (docs/conventions.md)
};
ExactValueFacts exact_value_facts(const ResultsIndex& index, const schema::StudyReference& study,
                                  schema::ProblemId problem, schema::Quantity quantity);

/// The report section "Appendix tables" (empty when no baseline row is present).
std::string appendix_section(const ResultsIndex& index, const schema::StudyReference& study);

}  // namespace cs::reports
