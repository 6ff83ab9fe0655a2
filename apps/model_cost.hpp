#pragma once
// What a run plans per model before it builds any: a relative cost, to start the largest first
// and to estimate memory (apps/memory_plan.hpp).
//
// Threads: every model's factorization runs on one BLAS thread, in `run` (models side by side,
// --jobs of them) and in `case` alike. Over half of a large model's time is serial (its METIS
// ordering and CHOLMOD's symbolic analysis: 10 of S(1/7) F Q8's 22 s), and a second BLAS thread
// spins in sched_yield between the small dense calls of a 2-D factorization: on 2 cores it
// gained `case S_1_7 --mesh F --element Q8` 5 % on a quiet machine and cost it 2.7 times with
// another process on the other core (docs/benchmarks.md, "Threads"). A threaded BLAS also sums
// in another order (the S problems' graded peaks move in the 8th digit), so with one thread a
// case's values never depend on the command, --jobs, the schedule or the selection.

#include "suites/case_spec.hpp"

namespace cs::apps {

/// A rough relative cost of a model: the problem's relative cost (its descriptor) times f^2 for
/// the level's elements (f = 1, 2, 4, 8 for C, M, F, VF), and 3 for Q8. E.g. H_p F Q8: 48;
/// S(1/7) F Q4: 480; S(1/7) F Q8: 1440.
double group_cost(const suites::CaseSpec& spec);

}  // namespace cs::apps
