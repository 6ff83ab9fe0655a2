#pragma once
// What a row's three meshes say beyond the study's verdicts: observed orders of convergence,
// Richardson extrapolation and Roache's grid convergence index for the smooth problems, and a
// strict divergence verdict for the singular ones (schema/row_verdict.hpp defines the records).
// The meshes halve h each level (refinement ratio 2).

#include <array>
#include <optional>

#include "schema/row_verdict.hpp"

namespace cs::suites {

/// log2(|e_C| / |e_M|) and log2(|e_M| / |e_F|) from signed percentage errors; empty where an
/// error is missing or below schema::kErrorNoiseFloorPercent (round-off: no order fitted).
std::array<std::optional<double>, 2> pair_orders(const std::array<std::optional<double>, 3>& e);

/// Observed order, Richardson limit and GCI (safety factor 1.25) from values on C, M, F; not
/// asymptotic (with a note) when the differences change sign, do not shrink, or are at
/// round-off (below 1e-12 of the values).
schema::ErrorEstimate error_estimate(double f_c, double f_m, double f_f);

/// The divergence verdicts are schema::divergence_verdict (the report applies them to the
/// study's values too).
using schema::divergence_verdict;

}  // namespace cs::suites
