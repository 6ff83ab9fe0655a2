#pragma once
// What the report needs to know of a problem, recorded in results.json by the run from the
// problem's descriptor (suites/problems/): its title, analysis type, whether it is singular,
// the study's tables and equations for it, and how each graded quantity is defined. The report
// builds its catalogue from these records, never from a list of its own.
//
// `situation` and `length_scale` came in after results files had been written without them:
// they are optional in results.json, and `report` and `merge` fill them in from the built-in
// catalogue for a problem it knows (suites::refresh_problem_records). A run always writes them.

#include <optional>
#include <string>
#include <vector>

#include "schema/case_axes.hpp"
#include "schema/problem_facts.hpp"
#include "schema/quantity.hpp"

namespace cs::schema {

/// One graded quantity of a problem, as the study's appendix defines it.
struct QuantityDefinition {
  Quantity quantity = Quantity::sigma_c;
  std::string definition_md;     ///< Markdown, e.g. "−σ<sub>z</sub>(0, 0)/p"
  std::string definition_plain;  ///< for figure titles, e.g. "-sigma_z(0,0)/p"
  std::string study_table;       ///< the study's appendix table number, e.g. "8"
  /// The study's Table 2 row key ("main", "contact", "horizontal"); empty when the study's
  /// Table 2 has no row for it.
  std::string study_row;
};

/// One problem of the battery.
struct ProblemRecord {
  ProblemId id = ProblemId::P_p;
  std::string title;        ///< e.g. "Hertz contact of a cylinder (plane strain)"
  std::string description;  ///< short, e.g. "plane-strain Hertzian contact"
  bool axisymmetric = false;
  bool singular = false;     ///< graded by divergence (Eq. 47), not accuracy
  std::string study_tables;  ///< the study's appendix tables, e.g. "7, 8"
  std::string exact_source;  ///< where the exact value comes from, e.g. "Eq. 15"
  std::vector<QuantityDefinition> quantities;
  /// The analyst's situation the problem stands for (the advice is given per situation); none
  /// in a results file written before it was recorded, for a problem no catalogue knows.
  std::optional<Situation> situation{};
  /// What x and the element size h are normalized by; none as for `situation`.
  std::optional<LengthScale> length_scale{};

  /// The definition of `q`, or nullptr when the problem does not grade it.
  const QuantityDefinition* definition(Quantity q) const;
};

}  // namespace cs::schema
