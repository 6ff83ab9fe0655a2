#pragma once
// The study's printed ANSYS results (Sezer & Sinclair, appendix Tables 3-14 and Table 2), as
// transcribed in data/study/ansys_results.csv and ansys_grades.csv (see data/study/README.md),
// and the mapping of our options onto the study's. The files keep their format; their names
// are read with the vocabulary (schema/), which holds the study's names as aliases.
//
// Mapping (ours -> study), all from the vocabulary:
//   element    the study's name is the element's alias: Q4 -> 4Q, Q8 -> 8Q
//   algorithm  the study merges the algorithms of one study column (traits(a).study_column):
//              AL, PM -> "AL, PM"; LMP, PLM -> "LMP, PLM"; MPC -> "IMC" (MPC's alias)
//   contact    ss, ns -> the same key (traits(c).in_study); where the study prints an LMP, PLM
//              or IMC column that holds for "either node-to-surface or surface-to-surface",
//              the key `either` answers for both; where a node-to-surface table says "LMP,
//              PLM have the same results as for surface-to-surface elements", our ns LMP/PLM is
//              compared with the study's ss value (flagged as such). Mortar has no study
//              counterpart.
//   Table 2    columns AL_PM_ss, AL_PM_ns (a study column and a contact), LMP_PLM and IMC (a
//              study column, for either contact type: the study does not separate them).

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "schema/case_axes.hpp"
#include "schema/grade.hpp"
#include "schema/quantity.hpp"

namespace cs::schema {

/// One printed appendix value (one row of ansys_results.csv).
struct StudyValue {
  std::string table;  ///< 3a ... 14d, or 3text
  ProblemId problem = ProblemId::P_p;
  Quantity quantity = Quantity::sigma_c;
  Element element = Element::Q4;
  std::optional<ContactKind> contact;  ///< nullopt: `either` (ss or ns)
  /// The first of the study column's algorithms (AL for "AL, PM").
  Algorithm algorithm = Algorithm::AL;
  MeshLevel mesh = MeshLevel::C;
  std::string printed;  ///< the value as printed (4 decimals)
  double value = 0.0;
  std::string exact_printed;    ///< the exact value printed above the table group, or "inf"
  std::optional<double> exact;  ///< nullopt for "inf"
};

/// One printed Table 2 cell (one row of ansys_grades.csv).
struct StudyGrade {
  std::string table;  ///< 2a | 2b
  ProblemId problem = ProblemId::P_p;
  std::string row;  ///< the study's row key: main | contact | horizontal
  Element element = Element::Q4;
  /// The first of the column's algorithms (AL for AL_PM_ss).
  Algorithm algorithm = Algorithm::AL;
  std::optional<ContactKind> contact;  ///< nullopt: a column for ss and ns alike
  Grade grade = Grade::u;
  bool converging = false;
  /// "e, c" or "g": the cell as the study prints it.
  std::string cell() const;
  /// The column head as the study prints it, with the contact type: "AL, PM ss", "IMC".
  std::string column_label() const;
};

/// The answer of a value lookup: the study's value and how it was matched.
struct StudyMatch {
  const StudyValue* value = nullptr;
  /// True when our ns LMP/PLM is compared with the study's ss value because the study's
  /// node-to-surface table says they have the same results.
  bool via_ss_note = false;
};

/// Both CSV files of data/study.
class StudyReference {
 public:
  StudyReference() = default;
  StudyReference(std::vector<StudyValue> values, std::vector<StudyGrade> grades,
                 std::map<std::pair<ProblemId, MeshLevel>, int> table1 = {});

  /// The study's Table 1: elements of the indented body of a problem on a mesh level
  /// (table1_elements.csv; the axisymmetric problems share their plane column), if printed.
  std::optional<int> table1_elements(ProblemId problem, MeshLevel mesh) const;

  /// The study's value for our option set on one mesh; `value == nullptr` when the study
  /// printed none (e.g. mortar, or a table it omitted).
  StudyMatch find_value(ProblemId problem, Quantity quantity, Element element, Algorithm algorithm,
                        ContactKind contact, MeshLevel mesh) const;

  /// The study's Table 2 cell for our option set, or nullptr (mortar, flat punch).
  const StudyGrade* find_grade(ProblemId problem, const std::string& study_row, Element element,
                               Algorithm algorithm, ContactKind contact) const;

  /// The study's printed exact value for a problem and quantity ("inf" for the flat punch),
  /// or an empty string when the study printed no table for it.
  std::string printed_exact(ProblemId problem, Quantity quantity) const;

  /// True when the study's Table 2 has a column per contact type for a's study column (AL, PM
  /// (ss) and (ns)); false when one column holds for both (LMP, PLM; IMC).
  bool separates_contacts(Algorithm a) const;
  /// The study's Table 2 of an element ("2a" for Q4), or "" when it has none.
  std::string grade_table(Element element) const;
  /// The rows of the study's Table 2 (problem and row key), in the file's order.
  std::vector<std::pair<ProblemId, std::string>> grade_rows() const;
  /// The problems whose printed exact value is "inf" (the singular flat punches), in the
  /// vocabulary's order.
  std::vector<ProblemId> singular_problems() const;

  const std::vector<StudyValue>& values() const { return values_; }
  const std::vector<StudyGrade>& grades() const { return grades_; }

 private:
  const StudyValue* find_exact_key(ProblemId problem, Quantity quantity, Element element,
                                   Algorithm algorithm, std::optional<ContactKind> contact,
                                   MeshLevel mesh) const;
  std::vector<StudyValue> values_;
  std::vector<StudyGrade> grades_;
  std::map<std::pair<ProblemId, MeshLevel>, int> table1_;
};

/// Reads ansys_results.csv and ansys_grades.csv from `dir`; throws SchemaError naming the
/// file and line of anything it cannot read (a name the vocabulary does not know included).
StudyReference load_study_reference(const std::filesystem::path& dir);

/// Where the study data is when the user does not say: PREFIX/share/contact-suite/data/study
/// for a program in PREFIX/bin (an installed or unpacked package), else the compile definition
/// CONTACT_SUITE_STUDY_DATA_DIR if that directory exists, else the first `data/study` (or
/// `share/contact-suite/data/study`, where `cmake --install` puts it) found walking up from the
/// running executable's directory, else `data/study` in the working directory.
/// Throws SchemaError when none holds ansys_results.csv.
std::filesystem::path default_study_data_dir();

/// The study's name of a value: its alias where it has one (Q4 -> 4Q, MPC -> IMC), else its
/// name.
template <Axis E>
constexpr std::string_view study_name(E v) {
  const AxisEntry e = entry(v);
  return e.alias.empty() ? e.name : e.alias;
}

/// True when the study reports both algorithms in one column (AL and PM; LMP and PLM).
bool same_study_column(Algorithm a, Algorithm b);
/// Our algorithms of a's study column, in the vocabulary's order: AL, PM for PM.
std::vector<Algorithm> study_column_members(Algorithm a);
/// The first algorithm of each study column, in the vocabulary's order: AL, LMP, MPC.
std::vector<Algorithm> study_columns();
/// The study's printed column head of a's study column: "AL, PM", "LMP, PLM", "IMC".
std::string study_column_label(Algorithm a);

}  // namespace cs::schema
