// The model is linear (small strains, linear elasticity, frictionless contact with a fixed
// active set): normalized results do not depend on the load. p/E = 1e-3 (the default) and
// 1e-4 give the same normalized values for every problem of the study on the C mesh.

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "suites/problem_catalog.hpp"
#include "suites/problem_executor.hpp"

namespace cs::suites {
namespace {

CaseResult run_at(ProblemId problem, Algorithm algorithm, double p_over_E) {
  const CaseSpec spec{.problem = problem,
                      .mesh = MeshLevel::C,
                      .element = Element::Q4,
                      .algorithm = algorithm,
                      .contact = ContactKind::ss,
                      .overrides = {{"p_over_E", p_over_E}}};
  ProblemExecutor executor(spec);
  return executor.run(spec);
}

/// The largest relative difference of the normalized values of two runs of one case.
double largest_difference(const CaseResult& a, const CaseResult& b) {
  EXPECT_EQ(a.quantities.size(), b.quantities.size());
  double worst = 0.0;
  for (std::size_t q = 0; q < a.quantities.size() && q < b.quantities.size(); ++q) {
    const double x = a.quantities[q].value, y = b.quantities[q].value;
    if (std::isfinite(x) && std::isfinite(y))
      worst = std::max(worst, std::abs(x - y) / std::max(std::abs(x), 1.0));
  }
  return worst;
}

// Requirement: for every study problem, with Lagrange multipliers (exact enforcement) and with
// the penalty method (FKN relative to E/h, so the penalty scales with the load too), the
// normalized values at p/E = 1e-3 and 1e-4 agree to 1e-4. What remains is geometric: the
// curved profiles' gap is not exactly quadratic (relative O((a/R)^2) ~ (p/E)^2) and a node at
// the contact edge may change state; a load-dependent error (a nonlinearity, a forgotten
// normalization) would show at the size of the results' own errors, percents.
TEST(LoadLinearity, NormalizedResultsDoNotDependOnPOverE) {
  for (ProblemId problem : study_problems()) {
    if (is_frictional(problem))
      continue;
    for (Algorithm algorithm : {Algorithm::LMP, Algorithm::PM}) {
      const CaseResult a = run_at(problem, algorithm, 1e-3);
      const CaseResult b = run_at(problem, algorithm, 1e-4);
      const std::string what = fmt::format("{} {}", to_string(problem), to_string(algorithm));
      ASSERT_EQ(a.status, CaseStatus::converged) << what << ": " << a.reason;
      ASSERT_EQ(b.status, CaseStatus::converged) << what << ": " << b.reason;
      const double d = largest_difference(a, b);
      std::printf("    %-12s p/E 1e-3 vs 1e-4: largest relative difference %.2e\n", what.c_str(),
                  d);
      EXPECT_LT(d, 1e-4) << what;
    }
  }
}

}  // namespace
}  // namespace cs::suites
