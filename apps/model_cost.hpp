#pragma once
// What a run plans per model before it builds any: a relative cost (to start the largest first
// and to estimate memory, apps/memory_plan.hpp) and the BLAS threads its factorization uses.
//
// Threads: a process that solves one model (`case`, the benchmarks) gives a model of cost
// kThreadedCost or more (the Steuermann problems from mesh F on, whose factorization holds the
// largest dense supernodes) every core it may run on, and a smaller one a single thread. A `run`
// gives every model one thread and runs models side by side instead: about half of a large
// model's time is serial (its METIS ordering, CHOLMOD's symbolic work, the recoveries), so a
// second BLAS thread gains it little while a second model gains a whole core (docs/benchmarks.md,
// "Threads"). A threaded BLAS sums in an order that depends on its thread count (the S problems'
// graded peaks move in the 8th digit between 1 and 2 threads), so a run's results never depend
// on --jobs, the schedule or the selection, and `case` may differ from `run` in that digit.

#include "suites/case_spec.hpp"

namespace cs::apps {

/// A rough relative cost of a model: the problem's relative cost (its descriptor) times f^2 for
/// the level's elements (f = 1, 2, 4, 8 for C, M, F, VF), and 3 for Q8. E.g. H_p F Q8: 48;
/// S(1/7) F Q4: 480; S(1/7) F Q8: 1440.
double group_cost(const suites::CaseSpec& spec);

/// From this cost on a model's factorization runs on every core (S at mesh F and finer).
inline constexpr double kThreadedCost = 400.0;

/// The BLAS threads of `spec`'s model alone on a process that may use `cores` cores (see above).
int model_threads(const suites::CaseSpec& spec, int cores);

}  // namespace cs::apps
