#pragma once
// Section 8 of the report, "Benchmarks", from the Google Benchmark JSON of
// bench/bench_contact_algorithms (see reports/bench/bench_results.hpp): the machine each file was
// measured on (from its `context`), the check of issue #7's target (ratio <= 1.5 for PM, AL and
// LM on every listed model at mesh F: which cases meet it, which miss it and by how much, which
// models were not measured there), the ContactAllOptions ratio per case, the ModelCases ratio of
// a model's full set of cases to one analysis of it (issue #27's target, in wall and CPU
// time), and per model (problem,
// mesh, element) a table of time, ratio and iterations per algorithm and contact
// discretization, with every case that did not converge or stopped with an error named.
//
// ratio = time of the contact analysis / time of one assembly + factorization + solve of the
// same model measured in the same run: the physical floor is 1.

#include <string>
#include <vector>

#include "reports/bench/bench_results.hpp"
#include "reports/figures/figures.hpp"

namespace cs::reports {

/// The performance target of issue #7: the contact analysis of PM, AL and LM costs at most
/// 1.5 x one assembly + factorization + solve, on H_p, S_1_7 and P'_p at mesh F.
struct BenchTarget {
  double max_ratio = 1.5;
  schema::MeshLevel mesh = schema::MeshLevel::F;
  std::vector<BenchMethod> algorithms{BenchMethod::PM, BenchMethod::AL, BenchMethod::LM};
  std::vector<schema::ProblemId> problems{schema::ProblemId::H_p, schema::ProblemId::S_1_7,
                                          schema::ProblemId::Pprime_p};
  /// Issue #27's target: a model's full set of cases (ModelCases) costs at most this x one
  /// analysis of the model.
  double max_model_cases_ratio = 1.3;
};

/// The cases the target applies to, split by outcome. A case misses the target when its ratio
/// exceeds the limit, when it did not converge, or when it has no ratio (an error).
struct TargetCheck {
  std::vector<const BenchRow*> met;
  std::vector<const BenchRow*> missed;
  /// "S(1/7) Q8": listed problems x elements with no case at the target mesh (Markdown).
  std::vector<std::string> not_measured;
  int n_cases() const { return static_cast<int>(met.size() + missed.size()); }
};

/// Checks every Contact benchmark of `bench` against `target`; the vectors point into `bench`.
TargetCheck check_target(const BenchResults& bench, const BenchTarget& target = {});

/// The machine line of one file: host, CPUs and clock, load, library build type, date.
std::string machine_line(const BenchSource& source);

/// The whole section, starting "## 8. Benchmarks"; `figures` holds the bench chart (empty when
/// figures are off).
std::string bench_section(const BenchResults& bench, const FigureSet& figures,
                          const BenchTarget& target = {});

}  // namespace cs::reports
