#include "reports/facts/trusted_estimate.hpp"

#include "grading/convergence.hpp"

namespace cs::reports {

TrustedEstimate trusted_estimate(const ResultsIndex& index, const schema::RowVerdict& row) {
  if (!row.estimate)
    return {};
  if (!row.estimate->asymptotic)
    return {nullptr, row.estimate->note};
  const auto& e = row.errors;
  if (e[0] && e[1] && e[2]) {
    const grading::ObservedOrder o = grading::observed_order(
        *e[0], *e[1], *e[2], index.read_resolution_percent(row, schema::MeshLevel::C));
    if (!o.order)
      return {nullptr, o.note};
  }
  return {&*row.estimate, {}};
}

}  // namespace cs::reports
