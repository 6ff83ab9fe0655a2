#pragma once
// The report's benchmarks appendix, from the Google Benchmark JSON of
// bench/bench_contact_algorithms (reports/bench/bench_results.hpp): the machine each file was
// measured on, the check of issue #7's target, the ContactAllOptions ratio per case, the
// ModelCases ratio of a model's full set of cases to one analysis of it (issue #27's target, in
// wall and CPU time), and per model a table of time, ratio and iterations per algorithm and
// contact discretization, naming every case that did not converge or stopped with an error.
//
// ratio = time of the contact analysis / time of one assembly + factorization + solve of the
// same model measured in the same run: the physical floor is 1.

#include <string>
#include <vector>

#include "reports/bench/bench_results.hpp"
#include "reports/figures/figures.hpp"
#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The performance targets: issue #7's, the contact analysis of `algorithms` costs at most
/// `max_ratio` x one assembly + factorization + solve on `problems` at `mesh`; issue #27's, a
/// model's full set of cases (ModelCases) costs at most `max_model_cases_ratio` x one analysis.
struct BenchTarget {
  double max_ratio = 1.5;
  schema::MeshLevel mesh = schema::MeshLevel::F;
  std::vector<BenchMethod> algorithms{BenchMethod::PM, BenchMethod::AL, BenchMethod::LM};
  std::vector<schema::ProblemId> problems{schema::ProblemId::H_p, schema::ProblemId::S_1_7,
                                          schema::ProblemId::Pprime_p};
  double max_model_cases_ratio = 1.3;
};

/// The cases the target applies to, by outcome. A case meets the target when it converged and
/// every measurement of it (each file's) is at or below the target ratio; misses it when it did
/// not converge, has no ratio (an error) or every measurement is above; is split when its
/// measurements lie on both sides; ties with it when the last median lies within one standard
/// deviation of its repetitions of the target.
struct TargetCheck {
  std::vector<const BenchRow*> met;
  std::vector<const BenchRow*> missed;  ///< the worst first
  std::vector<const BenchRow*> split;   ///< measured on both sides of the target
  std::vector<const BenchRow*> tied;    ///< within the noise of the target
  /// "S(1/7) Q8": listed problems x elements with no case at the target mesh (Markdown).
  std::vector<std::string> not_measured;
  int n_cases() const {
    return static_cast<int>(met.size() + missed.size() + split.size() + tied.size());
  }
};

/// Checks every Contact benchmark of `bench` against `target`; the vectors point into `bench`.
TargetCheck check_target(const BenchResults& bench, const BenchTarget& target = {});

/// How the benchmarked solver compares with the one behind a results document: of the Contact
/// cases that are also baseline cases of the results, how many took another number of
/// active-set iterations (the timings are then of another build of the solver), and the first.
struct BenchProvenance {
  int compared = 0, differing = 0;
  std::string example;  ///< "H_p F Q8 ss AL: 8 iterations benchmarked, 23 in the results"
};
BenchProvenance bench_provenance(const BenchResults& bench, const ResultsIndex& index);

/// The whole appendix, starting "## Benchmarks"; `figures` holds the bench chart (empty when
/// figures are off); `results`, when given, is compared with the benchmarks (bench_provenance).
std::string bench_section(const BenchResults& bench, const FigureSet& figures,
                          const BenchTarget& target = {}, const ResultsIndex* results = nullptr);

}  // namespace cs::reports
