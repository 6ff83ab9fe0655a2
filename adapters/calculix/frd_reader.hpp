#pragma once
// Reads CalculiX's ASCII result file (.frd): the node block and the nodal result blocks.
//
// The records used (CalculiX GraphiX's frd format; every record starts with a key):
//   "    1C", "    1U...", "    1P..."   header and parameter records (skipped)
//   "    2C ... <n> ... <format>"       node block: n records " -1<id><x><y><z>", then " -3"
//   "    3C ..."                        element block (skipped up to its " -3")
//   "  100C<set><time><n> ... <format>" a nodal result block, followed by
//       " -4  <NAME> <ncomp> <irtype>"  its name (DISP, STRESS, CONTACT, ERROR, ...)
//       " -5  <COMP> <menu> <ictype> <i1> <i2> <iexist>"  ncomp component records; iexist = 1
//                                       marks a component not stored (e.g. ALL of DISP)
//       " -1<id><v1>...<v6>" and " -2<v7>..." continuation records per node, then " -3"
//   " 9999"                             end of file
// Node ids are 10 characters wide (format 1) or 5 (format 0); format 2 (binary, from
// *NODE OUTPUT / *EL OUTPUT) is refused. Values are read as consecutive numbers (E12.5 fields
// may touch, e.g. "-1.0E-07-9.9E-01"; a three-digit exponent overflows its field), so "NaN" and
// "Inf" are read too.
//
// Results of several increments appear as repeated blocks: last_block() returns the last one
// (the final increment). Anything malformed or truncated throws CalculixOutputError with
// "<source>: line <n>: <what>"; the reader never reads outside the text.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cs::adapters::calculix {

/// The node block: ids and coordinates (x, y, z).
struct FrdNodes {
  std::vector<int> ids;
  std::vector<double> coordinates;  ///< 3 per node, parallel to ids
};

/// One nodal result block.
struct FrdResultBlock {
  std::string name;                     ///< DISP, STRESS, CONTACT, ...
  double time = 0.0;                    ///< the step time of the block
  std::vector<std::string> components;  ///< the stored components, e.g. SXX ... SZX
  std::vector<int> node_ids;
  std::vector<double> values;  ///< node-major: values[i * components.size() + c]

  int n_components() const { return static_cast<int>(components.size()); }
  int n_nodes() const { return static_cast<int>(node_ids.size()); }
  /// The index of component `name`, or -1.
  int component(std::string_view name) const;
  double value(int node_row, int component_index) const {
    return values[static_cast<std::size_t>(node_row) * components.size() + component_index];
  }
};

/// The parsed file.
struct FrdFile {
  FrdNodes nodes;
  std::vector<FrdResultBlock> blocks;  ///< in file order

  /// The last block called `name` (the final increment's), or nullptr.
  const FrdResultBlock* last_block(std::string_view name) const;
};

/// Parses .frd text; `source` names it in messages. Throws CalculixOutputError.
FrdFile parse_frd(std::string_view text, std::string_view source = "frd");

/// Reads and parses a .frd file. Throws CalculixOutputError (also for an unreadable file).
FrdFile read_frd(const std::filesystem::path& path);

/// The whole content of a text file; throws CalculixOutputError if it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace cs::adapters::calculix
