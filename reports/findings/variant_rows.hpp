#pragma once
// Which variant rows (a rigid target, parameter overrides, another solver) the report lists in
// its general "other option sets" tables: those no dedicated section shows.

#include <vector>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The variant rows, in document order, less those with a section of their own: another
/// solver's (the cross-code section), the extent study's (extent_section.hpp), or a sweep's (a row
/// overriding a key that a run of the document swept: the parameter-sweeps section).
std::vector<const schema::RowVerdict*> other_variant_rows(const ResultsIndex& index);

}  // namespace cs::reports
