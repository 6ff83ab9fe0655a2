#pragma once
// A GitHub-flavoured Markdown table, and the number and name formats every section of the report
// uses (values to the study's 4 decimals, signed percentages, the vocabulary's names).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "schema/name_table.hpp"

namespace cs::reports {

/// How a column's cells are aligned.
enum class Align { left, center, right };

/// A pipe table: a header row, then body rows of the same width (shorter rows are padded).
/// Columns are aligned as `align` says; without it (or past its end) the first column is left-
/// and the others centre-aligned.
class MarkdownTable {
 public:
  explicit MarkdownTable(std::vector<std::string> header, std::vector<Align> align = {})
      : header_(std::move(header)), align_(std::move(align)) {}
  void add_row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  std::size_t n_rows() const { return rows_.size(); }
  const std::vector<std::string>& header() const { return header_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }
  /// The cell under `column` in the first row whose first cell is `row_label`, or nullopt.
  std::optional<std::string> cell(const std::string& row_label, const std::string& column) const;
  /// The table as Markdown, ending with a newline; '|' inside cells is escaped.
  std::string render() const;

 private:
  std::vector<std::string> header_;
  std::vector<Align> align_;
  std::vector<std::vector<std::string>> rows_;
};

/// `text` as a Markdown table cell: '|' escaped, line breaks as spaces.
std::string escape_cell(const std::string& text);

/// The table of `rows`: one body row per element, in order, its cells `cells(row)` under `header`.
template <class Rows, class Cells>
MarkdownTable table_of(std::vector<std::string> header, const Rows& rows, Cells&& cells,
                       std::vector<Align> align = {}) {
  MarkdownTable table(std::move(header), std::move(align));
  for (const auto& row : rows)
    table.add_row(cells(row));
  return table;
}

/// `markdown` with every run of blank lines (left by a template's skipped sections) cut to one.
std::string tidy_markdown(const std::string& markdown);

/// A normalized stress as the study prints it: 4 decimals ("1.2732").
std::string format_value(double v);
/// A time in milliseconds to about three significant digits, without exponent: "1234", "56.7",
/// "8.90", "0.123".
std::string format_milliseconds(double ms);
/// A signed percentage: "+0.07 %", "−12.3 %" (2 significant decimals below 10 %, 1 above);
/// below 0.01 % in magnitude "4.1e-13 %", so that an exact result and a small error are told
/// apart (never "−0.00 %").
std::string format_error_resolved(double percent);
/// `text` with a leading '-' printed as the minus sign, as every signed number of the report:
/// "-0.05" -> "−0.05".
std::string with_minus_sign(std::string text);

/// format_value, or the em dash for nullopt.
std::string format_value(const std::optional<double>& v);
/// format_error_resolved, or the em dash for nullopt.
std::string format_error_resolved(const std::optional<double>& percent);
/// A value and its signed error: "1.2741 (+0.07 %)"; the value alone without an error, the em
/// dash without a value.
std::string format_value_and_error(const std::optional<double>& value,
                                   const std::optional<double>& error_percent);
/// "a / b / c": the three cells of a C, M, F sequence.
std::string join_meshes(const std::array<std::string, 3>& cells);

/// "a, b and c": `items` joined by ", ", the last two by `last` (" and ", " or ", ", ").
std::string join_words(const std::vector<std::string>& items, const char* last = " and ");

/// The vocabulary's name of `v` (schema/name_table.hpp): "PM", "ss", "F".
template <schema::Axis E>
std::string name_of(E v) {
  return std::string(schema::to_string(v));
}

/// The vocabulary's names of `values`, in their order: {"AL", "PM"}.
template <class Values>
std::vector<std::string> names_of(const Values& values) {
  std::vector<std::string> out;
  for (const auto v : values)
    out.push_back(name_of(v));
  return out;
}

/// The em dash the report uses for "not in this results file".
inline constexpr const char* kMissing = "—";

}  // namespace cs::reports
