#pragma once
// A results file (`contact-suite/results`, schema version 1, docs/results-schema.md) as the
// reports read it: loaded and validated here, in one place, with nlohmann-json. The reports
// layer never includes from suites/: every name (problem, mesh, grade, ...) arrives as a
// string, checked against the accepted names of the schema.
//
// Non-finite numbers are `null` in the file and std::nullopt here; the exact value of a
// singular quantity (flat punch) is the string "inf" and sets `QuantityRecord::singular`.

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cs::reports {

inline constexpr const char* kResultsSchemaName = "contact-suite/results";
inline constexpr int kResultsSchemaVersion = 2;

/// Mesh levels in file order: coarse, medium (h/2), fine (h/4).
inline constexpr std::array<const char*, 3> kMeshLevels{"C", "M", "F"};

/// One graded quantity of one case (normalized by p, positive in compression).
struct QuantityRecord {
  std::string name;                        ///< sigma_z_max | sigma_c | sigma_h | sigma_c_star
  std::optional<double> value;             ///< nullopt: not finite (failed case)
  std::optional<double> exact;             ///< nullopt when singular ("inf")
  bool singular = false;                   ///< exact value is "inf": graded by Eq. 47 only
  std::optional<double> error_percent;     ///< signed, percent
  std::string grade;                       ///< e | g | s | u (u for singular quantities)
  std::optional<double> contact_pressure;  ///< the same quantity from the contact pressure
  std::optional<double> study_exact;       ///< the study's printed exact value, where it differs
};

/// A curve along the contact surface z = 0, sorted by x; NaN where the file has null.
struct ProfileCurve {
  std::vector<double> x_over_a;         ///< position / a (/ b for the S problems)
  std::vector<double> sigma_z_over_p;   ///< -sigma_z/p, nodal stresses
  std::vector<double> pressure_over_p;  ///< contact pressure / p (empty for an exact curve)
  bool empty() const { return x_over_a.empty(); }
};

/// One case record (one analysis).
struct CaseRecord {
  std::string id;         ///< "H_p/F/Q4/LMP/ss" (+ "/rigid", "/extrapolated", "/k=v")
  std::string problem;    ///< P_p P_a Pprime_p Pprime_a H_p H_a S_1 S_1_3 S_1_7 F_p F_a
  std::string mesh;       ///< C M F
  std::string element;    ///< Q4 Q8
  std::string algorithm;  ///< AL PM LMP PLM MPC
  std::string contact;    ///< ns ss mortar
  std::string target;     ///< discretized rigid
  std::string recovery;   ///< spr extrapolated (nodal stresses)
  std::map<std::string, double> overrides;
  std::string status;  ///< converged | not_converged | failed
  std::string reason;
  int iterations = 0;
  std::optional<double> wall_seconds;
  std::optional<double> peak_rss_mb;
  long n_elements = 0;
  long n_equations = 0;
  std::optional<double> element_size_h;  ///< element size at the contact / a (or / b)
  std::vector<QuantityRecord> quantities;
  ProfileCurve profile;
  /// Optional `exact_profile` {x_over_a, sigma_z_over_p}: the exact -sigma_z/p on z = 0.
  ProfileCurve exact_profile;

  /// The quantity of that name, or nullptr.
  const QuantityRecord* quantity(const std::string& name) const;
  /// True for the study's option sets: a discretized target, the default (spr) nodal stresses
  /// and no parameter overrides.
  bool is_baseline() const {
    return target == "discretized" && recovery == "spr" && overrides.empty();
  }
};

/// One row verdict: a case less its mesh, for one quantity (the study's unit of assessment).
struct RowRecord {
  /// "H_p/Q4/LMP/ss/sigma_c" (+ "/rigid", "/extrapolated", "/k=v" before the quantity)
  std::string id;
  std::string problem, element, algorithm, contact, target, recovery, quantity;
  std::array<std::optional<double>, 3> values;  ///< C, M, F; nullopt: missing or failed
  std::array<std::optional<double>, 3> errors;  ///< percent; nullopt for singular rows
  std::optional<std::string> grade;             ///< of the finest mesh present
  std::optional<std::string> graded_mesh;       ///< C | M | F
  std::optional<bool> converging;               ///< nonsingular rows with all three meshes
  std::optional<bool> diverging;                ///< singular rows with all three meshes (Eq. 47)

  /// The option variant of the row: "" for the study's options, else e.g. "rigid/fkn=10" or
  /// "extrapolated".
  std::string variant() const;
  /// The row's key without the quantity (the case id less the mesh).
  std::string case_key() const;
};

/// The run as a whole.
struct RunRecord {
  std::string started_utc;
  std::optional<double> wall_seconds;
  int jobs = 1;
  std::optional<double> peak_rss_mb;
  std::string command_line;
  nlohmann::json environment = nlohmann::json::object();
};

/// A loaded, validated results file.
struct ResultsFile {
  std::string source;  ///< where it came from (a path), for messages and the report
  RunRecord run;
  std::vector<CaseRecord> cases;
  std::vector<RowRecord> rows;
};

/// Reads and validates a results file; throws ReportError with a one-line message naming the
/// file and the problem (missing, unreadable, not JSON or truncated, wrong schema or version,
/// a malformed record).
ResultsFile load_results_file(const std::filesystem::path& path);

/// Validates an already parsed document; `source` names it in error messages.
ResultsFile parse_results_document(const nlohmann::json& doc, const std::string& source);

/// The case id with its mesh field removed: "H_p/F/Q4/LMP/ss" -> "H_p/Q4/LMP/ss".
std::string case_key_of(const std::string& case_id);

}  // namespace cs::reports
