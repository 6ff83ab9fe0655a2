#pragma once
// How the report names and orders the study's problems and quantities: display names, the
// study's table numbers and section titles, the quantity definitions of its appendix, and the
// rows of its Table 2. Presentation only: no exact values and no grading live here (those
// arrive in the results file).

#include <string>
#include <vector>

namespace cs::reports {

/// One graded quantity of a problem, as the study's appendix defines it.
struct QuantityInfo {
  std::string name;       ///< as in results.json: sigma_z_max | sigma_c | sigma_h | sigma_c_star
  std::string symbol_md;  ///< Markdown, e.g. "σ̄<sub>c</sub>"
  std::string definition_md;  ///< Markdown, e.g. "−σ<sub>z</sub>(0, 0)/p"
  std::string plain;          ///< for figure titles, e.g. "-sigma_z(0,0)/p"
  std::string what;           ///< "contact stress", "horizontal stress", ...
  std::string study_table;    ///< the study's appendix table number, e.g. "8"
};

/// One of the study's eleven problems.
struct ProblemInfo {
  std::string id;            ///< as in results.json: P_p, Pprime_p, ..., F_a
  std::string name_md;       ///< Markdown, e.g. "P′<sub>p</sub>"
  std::string name_plain;    ///< plain text, e.g. "P'_p", "S(1/3)"
  std::string description;   ///< e.g. "plane-strain Hertzian contact"
  std::string study_table;   ///< the study's appendix table number(s), e.g. "7, 8"
  std::string exact_source;  ///< where the study takes its exact value from, e.g. "Eq. 15"
  bool singular = false;     ///< flat punch: graded by divergence (Eq. 47), not accuracy
  std::vector<QuantityInfo> quantities;
};

/// The problems in the study's appendix order (Tables 3 to 14).
const std::vector<ProblemInfo>& all_problem_infos();
/// The problem of that id, or nullptr for an id the catalogue does not know.
const ProblemInfo* find_problem_info(const std::string& id);
/// The quantity of a problem, or nullptr.
const QuantityInfo* find_quantity_info(const std::string& problem, const std::string& quantity);

/// One row of the study's Table 2: a problem and quantity with the study's row key.
struct GradeTableRow {
  std::string problem;
  std::string quantity;
  std::string study_row;  ///< "main", or for H_p "contact" / "horizontal" (ansys_grades.csv)
  std::string label_md;   ///< e.g. "H<sub>p</sub> (contact)"
};

/// The ten rows of Table 2 in the study's order.
const std::vector<GradeTableRow>& grade_table_rows();

}  // namespace cs::reports
