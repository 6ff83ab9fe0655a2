#pragma once
// The import layout: another code's results on the sampled surface of each case, one CSV file
// (docs/import-export.md). The reader is a pure function of the file's bytes — no file system,
// no case catalogue — so that it can be fuzzed on raw input; `grade` checks the case ids and
// the nodes against the rebuilt cases afterwards (suites/imported_results.hpp).
//
//   case_id,x,sigma_z,sigma_x,contact_pressure
//   H_p/C/Q4/PM/ss,0,-1.2731,-1.2731,1.2733
//
// - The header names the five columns, in any order, and any of the optional per-case columns
//   option, wall_seconds, iterations, n_equations, peak_rss_mb (ImportedCaseValues); a
//   missing required, unknown or repeated column is an error. Blank lines and lines starting with
//   '#' are skipped; a UTF-8 byte-order mark and CR line ends are accepted; fields are trimmed of
//   spaces and tabs; quoting is not supported (no field of the layout needs it).
// - case_id: a case id as cases.csv of `export` lists it (no "/@solver" suffix); it may name
//   a rigid target ("/rigid") and the stress basis ("/own": the code's own stresses; none:
//   spr, our patch recovery of the code's displacements), see `grade --target --recovery`.
// - x: the node's reference coordinate x (r) on the sampled surface, in the model's units.
// - sigma_z, sigma_x: the code's nodal stresses there, unnormalized, tension positive
//   (compression negative), as the code reports them; required, finite.
// - contact_pressure: the code's contact pressure at the node, > 0 in compression; empty when
//   the code reports none there (the node is then left out of the contact-pressure sampling,
//   as a node without contact output is for any solver).
// Rows of one case may be spread over the file; a case's rows keep the file's order.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "suites/suite_error.hpp"

namespace cs::suites {

/// The five required columns (any order is read).
inline constexpr std::string_view kImportHeader = "case_id,x,sigma_z,sigma_x,contact_pressure";
/// The optional per-case columns (any order, any subset).
inline constexpr std::string_view kImportOptionalColumns =
    "option,wall_seconds,iterations,n_equations,peak_rss_mb";

/// One row: a node of the sampled surface of one case.
struct ImportRow {
  double x = 0.0;        ///< reference coordinate x (r) of the node
  double sigma_z = 0.0;  ///< nodal sigma_z, tension positive, unnormalized
  double sigma_x = 0.0;  ///< nodal sigma_x (sigma_r), tension positive, unnormalized
  std::optional<double> contact_pressure;  ///< > 0 in compression; none: not reported
  int line = 0;                            ///< 1-based line of the file (0: not from a file)
};

/// What the optional columns say of a case as a whole (none: not given). The option is part of
/// the case (rows of one id and two options are two cases): it is given on every row of a case
/// that has one. The others may be given on any of the case's rows and left empty on the rest;
/// where two rows give one, they agree.
struct ImportedCaseValues {
  std::optional<std::string> option;   ///< the code's own option label, e.g. "nitsche"
  std::optional<double> wall_seconds;  ///< the code's wall time for the case, >= 0
  std::optional<int> iterations;       ///< its (Newton or contact) iterations, >= 0
  std::optional<int> n_equations;      ///< its number of equations, >= 0
  std::optional<double> peak_rss_mb;   ///< its peak resident memory in MB, >= 0

  friend bool operator==(const ImportedCaseValues&, const ImportedCaseValues&) = default;
};

/// The rows of one case id and option, in the file's order.
struct ImportedCase {
  std::string case_id;
  int line = 0;  ///< the line of its first row
  std::vector<ImportRow> rows;
  ImportedCaseValues values{};
};

/// A malformed import file. The message is one line: "<source>:<line>: column <k> (<name>):
/// <what>" (or without the column for a whole-line problem).
class ImportError : public SuiteInputError {
 public:
  explicit ImportError(const std::string& what) : SuiteInputError(what) {}
};

/// Parses the import layout. Returns one entry per case id and option, in the order of first
/// appearance.
/// Throws ImportError, naming `source_name`, the line and the column, for: an empty file (no
/// header) or a header without data rows; a missing, unknown or repeated column; a row with
/// more or fewer fields than the header; an empty case id; a value that is not a number, not
/// finite or out of the range of a double (an empty contact_pressure is allowed); the same x
/// twice for one case id (a duplicate node); an option that is not a label, a negative time or
/// memory, a count that is not a whole number >= 0, and two rows of a case that give a per-case
/// value differently.
std::vector<ImportedCase> parse_import_csv(std::string_view text, std::string_view source_name);

/// The import layout of `cases` (kImportHeader, and the optional columns when any case has a
/// value for them, given on its first row; then one row per node; numbers with 17
/// significant digits, so that parse_import_csv reads back the same doubles).
std::string import_csv_text(const std::vector<ImportedCase>& cases);

}  // namespace cs::suites
