#pragma once
// A row's Richardson limit and GCI (schema::ErrorEstimate, computed from its values on C, M
// and F) used only where the grading layer trusts an observed order of its errors: one rule for
// "asymptotic", shared by the estimates appendix and the extent appendix.

#include <string>

#include "reports/results/results_index.hpp"

namespace cs::reports {

/// A row's estimate, or why there is none to use.
struct TrustedEstimate {
  const schema::ErrorEstimate* estimate = nullptr;  ///< nullptr: none to use
  std::string note;                                 ///< why not ("changes sign", ...)
};

/// The row's estimate when it is asymptotic (its differences shrink, one sign) and, where the
/// row has errors on C, M and F, grading::observed_order gives an order (converging, C and M
/// resolved, the error of one sign, pair orders within one of each other): an extrapolation
/// from a sequence with no trusted order (S(1) AL ns +0.35/+0.11/-0.13 %: a limit of -9.8 %) is
/// not an estimate. Otherwise the note of whichever rule refused it.
TrustedEstimate trusted_estimate(const ResultsIndex& index, const schema::RowVerdict& row);

}  // namespace cs::reports
