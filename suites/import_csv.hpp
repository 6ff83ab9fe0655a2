#pragma once
// The import layout: another code's results on the sampled surface of each case, one CSV file
// (docs/import-export.md). The reader is a pure function of the file's bytes — no file system,
// no case catalogue — so that it can be fuzzed on raw input; `grade` checks the case ids and
// the nodes against the rebuilt cases afterwards (suites/imported_results.hpp).
//
//   case_id,x,sigma_z,sigma_x,contact_pressure
//   H_p/C/Q4/PM/ss,0,-1.2731,-1.2731,1.2733
//
// - The header names the five columns, in any order; a missing, unknown or repeated column is
//   an error. Blank lines and lines starting with '#' are skipped; a UTF-8 byte-order mark and
//   CR line ends are accepted; fields are trimmed of spaces and tabs; quoting is not supported
//   (no field of the layout needs it).
// - case_id: a case id as cases.csv of `export` lists it (no "/@solver" suffix).
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

/// The header `import_csv_text` writes (any order of these five names is read).
inline constexpr std::string_view kImportHeader = "case_id,x,sigma_z,sigma_x,contact_pressure";

/// One row: a node of the sampled surface of one case.
struct ImportRow {
  double x = 0.0;        ///< reference coordinate x (r) of the node
  double sigma_z = 0.0;  ///< nodal sigma_z, tension positive, unnormalized
  double sigma_x = 0.0;  ///< nodal sigma_x (sigma_r), tension positive, unnormalized
  std::optional<double> contact_pressure;  ///< > 0 in compression; none: not reported
  int line = 0;                            ///< 1-based line of the file (0: not from a file)
};

/// The rows of one case id, in the file's order.
struct ImportedCase {
  std::string case_id;
  int line = 0;  ///< the line of its first row
  std::vector<ImportRow> rows;
};

/// A malformed import file. The message is one line: "<source>:<line>: column <k> (<name>):
/// <what>" (or without the column for a whole-line problem).
class ImportError : public SuiteInputError {
 public:
  explicit ImportError(const std::string& what) : SuiteInputError(what) {}
};

/// Parses the import layout. Returns one entry per case id, in the order of first appearance.
/// Throws ImportError, naming `source_name`, the line and the column, for: an empty file (no
/// header) or a header without data rows; a missing, unknown or repeated column; a row with
/// more or fewer fields than the header; an empty case id; a value that is not a number, not
/// finite or out of the range of a double (an empty contact_pressure is allowed); the same x
/// twice for one case id (a duplicate node).
std::vector<ImportedCase> parse_import_csv(std::string_view text, std::string_view source_name);

/// The import layout of `cases` (kImportHeader, then one row per node; numbers with 17
/// significant digits, so that parse_import_csv reads back the same doubles).
std::string import_csv_text(const std::vector<ImportedCase>& cases);

}  // namespace cs::suites
