#pragma once
// The study's printed ANSYS results (Sezer & Sinclair, appendix Tables 3-14 and Table 2), as
// transcribed in data/study/ansys_results.csv and ansys_grades.csv (see data/study/README.md),
// and the mapping of our option names onto the study's CSV keys.
//
// Mapping (ours -> study):
//   element    Q4 -> 4Q, Q8 -> 8Q
//   algorithm  AL, PM -> AL_PM;  LMP, PLM -> LMP_PLM;  MPC -> IMC
//   contact    ss, ns -> the same key; where the study prints an LMP, PLM or IMC column that
//              holds for "either node-to-surface or surface-to-surface", the key `either`
//              answers for both; where a node-to-surface table says "LMP, PLM have the same
//              results as for surface-to-surface elements", our ns LMP/PLM is compared with
//              the study's ss value (flagged as such). Mortar has no study counterpart.
//   Table 2    (AL_PM, ss) -> AL_PM_ss, (AL_PM, ns) -> AL_PM_ns, LMP_PLM -> LMP_PLM,
//              IMC -> IMC, for either contact type (the study does not separate them).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cs::reports {

/// One printed appendix value (one row of ansys_results.csv).
struct StudyValue {
  std::string table;      ///< 3a ... 14d, or 3text
  std::string problem;    ///< P_p ... F_a (our ids)
  std::string quantity;   ///< sigma_z_max | sigma_c | sigma_h | sigma_c_star
  std::string element;    ///< 4Q | 8Q
  std::string contact;    ///< ss | ns | either
  std::string algorithm;  ///< AL_PM | LMP_PLM | IMC
  std::string mesh;       ///< C | M | F
  std::string printed;    ///< the value as printed (4 decimals)
  double value = 0.0;
  std::string exact_printed;    ///< the exact value printed above the table group, or "inf"
  std::optional<double> exact;  ///< nullopt for "inf"
};

/// One printed Table 2 cell (one row of ansys_grades.csv).
struct StudyGrade {
  std::string table;  ///< 2a | 2b
  std::string problem;
  std::string row;      ///< main | contact | horizontal
  std::string element;  ///< 4Q | 8Q
  std::string column;   ///< AL_PM_ss | AL_PM_ns | LMP_PLM | IMC
  std::string grade;    ///< e | g | s | u
  bool converging = false;
  /// "e, c" or "g": the cell as the study prints it.
  std::string cell() const { return converging ? grade + ", c" : grade; }
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
  StudyReference(std::vector<StudyValue> values, std::vector<StudyGrade> grades);

  /// The study's value for our option set on one mesh (our names: Q4, AL, ss, ...);
  /// `value == nullptr` when the study printed none (e.g. mortar, or a table it omitted).
  StudyMatch find_value(const std::string& problem, const std::string& quantity,
                        const std::string& element, const std::string& algorithm,
                        const std::string& contact, const std::string& mesh) const;

  /// The study's Table 2 cell for our option set, or nullptr (mortar, flat punch).
  const StudyGrade* find_grade(const std::string& problem, const std::string& study_row,
                               const std::string& element, const std::string& algorithm,
                               const std::string& contact) const;

  /// A study Table 2 cell by its own keys, or nullptr.
  const StudyGrade* find_grade_cell(const std::string& problem, const std::string& study_row,
                                    const std::string& study_element,
                                    const std::string& column) const;

  /// The study's printed exact value for a problem and quantity ("inf" for the flat punch),
  /// or an empty string when the study printed no table for it.
  std::string printed_exact(const std::string& problem, const std::string& quantity) const;

  const std::vector<StudyValue>& values() const { return values_; }
  const std::vector<StudyGrade>& grades() const { return grades_; }

 private:
  const StudyValue* find_exact_key(const std::string& problem, const std::string& quantity,
                                   const std::string& element, const std::string& algorithm,
                                   const std::string& contact, const std::string& mesh) const;
  std::vector<StudyValue> values_;
  std::vector<StudyGrade> grades_;
};

/// Reads ansys_results.csv and ansys_grades.csv from `dir`; throws ReportError naming the
/// file and line of anything it cannot read.
StudyReference load_study_reference(const std::filesystem::path& dir);

/// Where the study data is when the user does not say: the compile definition
/// CONTACT_SUITE_STUDY_DATA_DIR if that directory exists, else the first `data/study` found
/// walking up from the running executable's directory, else from the working directory.
/// Throws ReportError when none holds ansys_results.csv.
std::filesystem::path default_study_data_dir();

/// Our element name -> the study's ("Q4" -> "4Q").
std::string study_element(const std::string& element);
/// Our algorithm -> the study's CSV key ("PM" -> "AL_PM", "MPC" -> "IMC"); "" if none.
std::string study_algorithm(const std::string& algorithm);
/// The study's printed column head for its algorithm key ("AL_PM" -> "AL, PM").
std::string study_algorithm_label(const std::string& study_algorithm);
/// Our (algorithm, contact) -> the study's Table 2 column, or "" (mortar).
std::string study_grade_column(const std::string& algorithm, const std::string& contact);

}  // namespace cs::reports
