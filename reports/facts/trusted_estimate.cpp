#include "reports/facts/trusted_estimate.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grading/convergence.hpp"

namespace cs::reports {

TrustedEstimate trusted_estimate(const schema::RowVerdict& row) {
  if (!row.estimate)
    return {};
  const schema::ErrorEstimate& e = *row.estimate;
  if (!e.asymptotic || !e.observed_order)
    return {nullptr, e.note};
  if (std::ranges::all_of(row.errors, [](const std::optional<double>& x) {
        return x && std::abs(*x) <= grading::kErrorResolutionPercent;
      }))
    return {nullptr, "within the study's resolution on every mesh: nothing to extrapolate"};
  if (schema::read_between_nodes(row.quantity))
    return {nullptr, "read between two nodes: it moves by whole nodes"};
  const double coarse =
      std::max(std::abs(row.errors[0].value_or(0.0)), std::abs(row.errors[1].value_or(0.0)));
  if (coarse >= grading::kUnresolvedErrorPercent)
    return {nullptr, fmt::format("pre-asymptotic ({:.3g} % on C or M: not resolved)", coarse)};
  if (*e.observed_order < kMinimumRichardsonOrder)
    return {nullptr, fmt::format("order {:.2f}: the differences barely shrink", *e.observed_order)};
  return {&e, {}};
}

}  // namespace cs::reports
