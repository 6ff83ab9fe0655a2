#pragma once
// Number and name formats shared by the report's pages (beside tables/markdown_table.hpp's
// format_value and format_percent): every error a page prints is signed.

#include <string>

#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {

/// A difference of percentages, unsigned: "0.012 points".
std::string format_points(double points);

/// A ratio from an interface check, to three significant digits: "19.2", "2.78e+03".
std::string format_measure(double measure);

/// The solvers whose cases the results hold, as a reader knows them: "ours", "ours and
/// CalculiX" (`last` joins the last two).
std::string solver_names(const ResultsIndex& index, const char* last = " and ");

}  // namespace cs::reports
