#pragma once
// What a run plans per model before it builds any: a relative cost (to start the largest first
// and to estimate memory, apps/memory_plan.hpp) and the BLAS threads its factorization uses.
//
// Threads: a model of cost kThreadedCost or more (the Steuermann problems from mesh F on: their
// factorization is dominated by the dense BLAS-3 of large supernodes, which threaded OpenBLAS
// splits well) uses every core this process may run on; smaller models use one. The count
// depends on the model and the machine only, never on --jobs or on what else runs: a threaded
// BLAS sums in an order that depends on its thread count (the S problems' graded peaks move in
// the 8th digit between 1 and 2 threads), so this is what keeps results bit-identical for every
// --jobs. The runner (suites/runner.hpp) runs a threaded model alone.

#include "suites/case_spec.hpp"

namespace cs::apps {

/// A rough relative cost of a model: the problem's relative cost (its descriptor) times f^2 for
/// the level's elements (f = 1, 2, 4, 8 for C, M, F, VF), and 3 for Q8. E.g. H_p F Q8: 48;
/// S(1/7) F Q4: 480; S(1/7) F Q8: 1440.
double group_cost(const suites::CaseSpec& spec);

/// From this cost on a model's factorization runs on every core (S at mesh F and finer).
inline constexpr double kThreadedCost = 400.0;

/// The BLAS threads of `spec`'s model on a process that may use `cores` cores (see above).
int model_threads(const suites::CaseSpec& spec, int cores);

}  // namespace cs::apps
