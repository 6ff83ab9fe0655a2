#include "grading/richardson.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grading/convergence.hpp"

namespace cs::grading {
namespace {

/// Relative size below which a difference of two values is round-off.
constexpr double kRoundOff = 1e-12;
/// Roache's safety factor for a three-grid study.
constexpr double kGciSafetyFactor = 1.25;

}  // namespace

schema::ErrorEstimate error_estimate(double f_c, double f_m, double f_f) {
  schema::ErrorEstimate out;
  const double d1 = f_c - f_m, d2 = f_m - f_f;
  const double scale = std::max({std::abs(f_c), std::abs(f_m), std::abs(f_f)});
  if (std::abs(d1) <= kRoundOff * scale || std::abs(d2) <= kRoundOff * scale) {
    out.note = "differences at round-off";
    return out;
  }
  if (d1 * d2 < 0.0) {
    out.note = "oscillatory";
    return out;
  }
  if (std::abs(d1) <= std::abs(d2)) {
    out.note = "differences do not shrink";
    return out;
  }
  const double p = std::log2(std::abs(d1) / std::abs(d2));
  const double denominator = std::exp2(p) - 1.0;
  out.asymptotic = true;
  out.observed_order = p;
  out.richardson = f_f + (f_f - f_m) / denominator;
  if (f_f != 0.0)
    out.gci_percent = kGciSafetyFactor * std::abs(d2 / f_f) / denominator * 100.0;
  return out;
}

TrustedEstimate trusted_estimate(const schema::RowVerdict& row) {
  if (!row.estimate)
    return {};
  const schema::ErrorEstimate& e = *row.estimate;
  if (!e.asymptotic || !e.observed_order)
    return {nullptr, e.note};
  if (std::ranges::all_of(row.errors, [](const std::optional<double>& x) {
        return x && std::abs(*x) <= kErrorResolutionPercent;
      }))
    return {nullptr, "within the study's resolution on every mesh: nothing to extrapolate"};
  const auto within_resolution = [](const std::optional<double>& a,
                                    const std::optional<double>& b) {
    return a && b && std::abs(*a - *b) <= kErrorResolutionPercent;
  };
  if (within_resolution(row.errors[0], row.errors[1]) &&
      within_resolution(row.errors[1], row.errors[2]))
    return {nullptr, "settled within the study's resolution: nothing to extrapolate"};
  if (schema::read_between_nodes(row.quantity))
    return {nullptr, "read between two nodes: it moves by whole nodes"};
  const double e_c = row.errors[0].value_or(0.0), e_m = row.errors[1].value_or(0.0);
  if (unresolved(e_c, e_m))
    return {nullptr, fmt::format("pre-asymptotic ({:.3g} % on C or M: not resolved)",
                                 std::max(std::abs(e_c), std::abs(e_m)))};
  // Beyond the resolution by more than round-off: 0.73 -> 0.72 % is a change of 0.01 points.
  if (!row.errors[1] || !row.errors[2] ||
      !(std::abs(*row.errors[2] - *row.errors[1]) > kErrorResolutionPercent * (1.0 + 1e-9)))
    return {nullptr, "M to F within the study's resolution: the order would be noise"};
  if (*e.observed_order < kMinimumRichardsonOrder)
    return {nullptr, fmt::format("order {:.2f}: the differences barely shrink", *e.observed_order)};
  if (const double most = maximum_richardson_order(row.spec.element); *e.observed_order > most)
    return {nullptr, fmt::format("order {:.2f}: above {:g}, more than the element's recovered "
                                 "stresses reach: not the asymptotic range",
                                 *e.observed_order, most)};
  return {&e, {}};
}

std::optional<bool> gci_bounds_error(const schema::RowVerdict& row, double exact) {
  if (!row.estimate || !row.estimate->gci_percent || !row.values[2] || *row.values[2] == 0.0)
    return std::nullopt;
  const double error = std::abs(*row.values[2] - exact) / std::abs(*row.values[2]) * 100.0;
  return error <= *row.estimate->gci_percent;
}

double maximum_richardson_order(schema::Element element) {
  switch (element) {
    case schema::Element::Q4:
      return 3.0;
    case schema::Element::Q8:
      return 4.0;
  }
  return 3.0;
}

}  // namespace cs::grading
