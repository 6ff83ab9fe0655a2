#pragma once
// One quantity of one option set over a varied parameter, shared by the sections that vary one:
// a swept value (`run --sweep KEY=...`: sweep_section.hpp) and the block's extent (`--set
// extent=K`: extent_section.hpp).

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "reports/tables/markdown_table.hpp"
#include "schema/results_file.hpp"

namespace cs::reports {

/// One point of a series: the parameter's value and what was measured there.
struct SeriesPoint {
  double parameter = 0.0;
  std::optional<double> value{};  ///< the quantity's value on mesh F, in a series of rows
  std::optional<double> error{};  ///< its signed error (%), when finite
  schema::CaseStatus status = schema::CaseStatus::converged;
  int iterations = 0;
  const schema::CaseResult* result = nullptr;  ///< the case, in a series of cases
  const schema::RowVerdict* row = nullptr;     ///< the row, in a series of rows

  bool converged() const { return status == schema::CaseStatus::converged; }
};

/// One quantity of one option set over a varied parameter.
struct ParameterSeries {
  schema::CaseSpec spec;  ///< the common spec, the varied parameter removed from its overrides
  schema::Quantity quantity = schema::Quantity::sigma_c;
  std::vector<SeriesPoint> points;  ///< by ascending parameter

  /// The point at `parameter`, or nullptr.
  const SeriesPoint* at(double parameter) const;
  /// "AL ss" plus any other variant ("AL ss, rigid, E_ratio=1e+09"), for legends and tables.
  std::string option_label() const;
  /// Problem, quantity, mesh, element and option_label(): the lead cells of a table row.
  std::vector<std::string> label_cells() const;
  /// label_cells() joined by spaces: "H_p sigma_c F Q4 AL ss".
  std::string label() const;
  /// The smallest and the largest error of a converged point, if any.
  std::optional<std::pair<double, double>> error_range() const;
};

/// Pointers into a set of series, as a section selects them.
using SeriesRefs = std::vector<const ParameterSeries*>;

/// The series of `all` that `keep` accepts, in their order.
template <typename Keep>
SeriesRefs select_series(const std::vector<ParameterSeries>& all, Keep&& keep) {
  SeriesRefs out;
  for (const auto& s : all) {
    if (keep(s))
      out.push_back(&s);
  }
  return out;
}

/// Series grouped by an id the caller chooses, in the order of their first point.
class SeriesGroups {
 public:
  /// The series of `id`; a copy of `first` when there is none yet.
  ParameterSeries& of(const std::string& id, const ParameterSeries& first);
  /// The series, their points by ascending parameter (stable among equals).
  std::vector<ParameterSeries> sorted() &&;

 private:
  std::map<std::string, std::size_t> slot_;
  std::vector<ParameterSeries> series_;
};

/// The parameter values of a set of series, ascending and distinct.
std::vector<double> parameter_values(const SeriesRefs& series);

/// A parameter value as the report prints it ({:g}: "0.001", "1e+04").
std::string format_parameter(double value);
/// "0.01, 1, 100", or "none".
std::string parameter_list(const std::vector<double>& values);
/// "0.01 to 100" when `chosen` is a contiguous run of two or more of `all`, else the list.
std::string parameter_window(const std::vector<double>& chosen, const std::vector<double>& all);

/// A table with the `lead` columns, then one right-aligned column per parameter value.
MarkdownTable parameter_table(std::vector<std::string> lead, std::vector<Align> align,
                              const std::vector<double>& values);

}  // namespace cs::reports
