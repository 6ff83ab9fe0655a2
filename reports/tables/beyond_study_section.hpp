#pragma once
// The problems beyond the study (no table of its appendix: the equal-moduli patch tests, the
// frictional problems, ...) and the quantities it did not grade on its own problems (the
// contact half-width of H and S): one table per problem and quantity with our value and error per
// mesh, the grade of the finest mesh (Eq. 46) with its convergence flag, and the observed order
// per mesh pair (none where the errors are at round-off). Graded by the same rules as
// Tables 2a′ and 2b′.

#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// "+0.81 %"; below 0.01 % in magnitude "4.1e-13 %", so that an exact result and a small error
/// are told apart.
std::string format_error_resolved(double percent);

/// The section (empty when the results hold no baseline row of such a problem).
std::string beyond_study_section(const ResultsIndex& index);

}  // namespace cs::reports
