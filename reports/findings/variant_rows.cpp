#include "reports/findings/variant_rows.hpp"

#include <algorithm>

#include "reports/findings/extent_section.hpp"

namespace cs::reports {
namespace {

bool swept_key(const schema::RunInfo& run, const std::string& key) {
  return std::any_of(run.sweep.begin(), run.sweep.end(),
                     [&](const schema::SweepAxis& axis) { return axis.key == key; });
}

bool overrides_a_swept_key(const schema::ResultsDocument& doc, const schema::CaseSpec& spec) {
  for (const auto& [key, value] : spec.overrides) {
    if (swept_key(doc.run, key))
      return true;
    for (const auto& [source, run] : doc.added_runs) {
      if (swept_key(run, key))
        return true;
    }
  }
  return false;
}

bool has_own_section(const ResultsIndex& index, const schema::RowVerdict& row) {
  return row.spec.solver != schema::SolverKind::builtin || in_extent_study(row.spec) ||
         overrides_a_swept_key(index.results(), row.spec);
}

}  // namespace

std::vector<const schema::RowVerdict*> other_variant_rows(const ResultsIndex& index) {
  std::vector<const schema::RowVerdict*> rows;
  for (const schema::RowVerdict* r : index.variant_rows()) {
    if (!has_own_section(index, *r))
      rows.push_back(r);
  }
  return rows;
}

}  // namespace cs::reports
