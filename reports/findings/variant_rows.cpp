#include "reports/findings/variant_rows.hpp"

#include <algorithm>

#include "reports/findings/extent_section.hpp"
#include "reports/findings/sweep_section.hpp"

namespace cs::reports {

std::vector<const schema::RowVerdict*> other_variant_rows(const ResultsIndex& index) {
  const std::vector<std::string> swept = run_sweep_keys(index.results());
  std::vector<const schema::RowVerdict*> rows = index.variant_rows();
  std::erase_if(rows, [&](const schema::RowVerdict* r) {
    const bool sweeps = std::ranges::any_of(r->spec.overrides, [&](const auto& o) {
      return std::ranges::find(swept, o.first) != swept.end();
    });
    return r->spec.solver != schema::SolverKind::builtin || in_extent_study(r->spec) || sweeps;
  });
  return rows;
}

}  // namespace cs::reports
