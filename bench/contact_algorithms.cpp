// Benchmarks of the contact algorithms on the study's problems H_p, S_1_7 and P'_p (meshed
// stiff indenter, the study's choice), per mesh level, element, discretization and algorithm:
//   time     the contact analysis: assembly, constraint rows, condensation (one sparse
//            factorization with the contact DOFs ordered last, then dense BLAS-3), the active-set
//            iterations and the displacement recovery;
//   counters iterations (linear solves of the condensed problem), augmentations (AL), the
//            unknowns, the contact DOFs |c| and candidate rows m, and ratio = contact time /
//            (one assembly + factorization + solve of the same model), the latter measured in
//            the same run (the physical floor of the ratio is 1; see reference_seconds).
//
// ContactAllOptions: the 12 discretization x algorithm cases of one model on one
// ContactAnalysis (one shared factorization), with ratio_per_case = time / 12 / reference.
//
// Args: problem (0 H_p, 1 S_1_7, 2 P'_p), mesh (0 C, 1 M, 2 F), element (0 Q4, 1 Q8),
//       discretization (0 ns, 1 ss, 2 mortar), algorithm (0 PM, 1 AL, 2 LM, 3 MPC).
// Run:  build-*/bench/bench_contact_algorithms --benchmark_filter='Contact/0/1/'  (H_p, M)
//       (the F meshes of S_1_7 take minutes per case; JSON with --benchmark_format=json).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <benchmark/benchmark.h>

#include "solver/contact/contact_analysis.hpp"
#include "solver/linear_static.hpp"
#include "suites/problem_setup.hpp"

namespace {

using namespace cs;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

suites::CaseSpec case_spec(const benchmark::State& state) {
  static const suites::ProblemId problems[] = {suites::ProblemId::H_p, suites::ProblemId::S_1_7,
                                               suites::ProblemId::Pprime_p};
  suites::CaseSpec spec;
  spec.problem = problems[state.range(0)];
  spec.mesh = static_cast<suites::MeshLevel>(state.range(1));
  spec.element = state.range(2) == 0 ? solver::ElementType::Q4 : solver::ElementType::Q8;
  spec.target = suites::TargetKind::Discretized;
  return spec;
}

/// One assembly + factorization + solve of the model (seconds), measured once per model. The
/// bodies held only by contact (the block; S's loaded punch) get tiny springs (1e-3 of the
/// diagonal) on their contact surfaces' z DOFs: the same pattern and cost, a regular matrix.
double reference_seconds(const suites::CaseSpec& spec, const solver::Model& model,
                         const solver::ContactPair& pair) {
  static std::map<std::tuple<int, int, int>, double> cache;
  const auto key = std::make_tuple(static_cast<int>(spec.problem), static_cast<int>(spec.mesh),
                                   static_cast<int>(spec.element));
  if (const auto it = cache.find(key); it != cache.end()) {
    return it->second;
  }
  const auto start = Clock::now();
  solver::LinearStaticAnalysis elastic(model);
  elastic.assemble();
  const solver::DofMap& dofs = elastic.dof_map();
  std::vector<std::string> surfaces{pair.contact_surface};
  if (const auto* t = std::get_if<solver::TargetSurface>(&pair.target)) {
    surfaces.push_back(t->edge_set);
  }
  std::vector<Eigen::Triplet<double>> springs;
  for (const std::string& surface : surfaces) {
    for (const auto& side : model.mesh.edge_sets.at(surface)) {
      for (int node : model.mesh.side_nodes(side)) {
        const int eq = node >= 0 ? dofs.equation(2 * node + 1) : -1;
        if (eq >= 0) {
          springs.emplace_back(eq, eq, 1e-3 * elastic.stiffness().K_ff.coeff(eq, eq));
        }
      }
    }
  }
  Eigen::SparseMatrix<double> P(dofs.n_free(), dofs.n_free());
  P.setFromTriplets(springs.begin(), springs.end());  // duplicates summed: still small
  const solver::SolveOutcome outcome = elastic.factorize_with(P);
  if (!outcome.ok()) {
    std::fprintf(stderr, "reference factorization failed: %s\n", outcome.reason.c_str());
    return cache[key] = std::nan("");
  }
  const Eigen::VectorXd u = elastic.solve_reduced(elastic.reduced_load(model.loads));
  benchmark::DoNotOptimize(u.data());
  return cache[key] = seconds_since(start);
}

void BM_Contact(benchmark::State& state) {
  const suites::CaseSpec spec = case_spec(state);
  const suites::ProblemSetup setup = suites::build_problem(spec);
  solver::ContactSettings settings;
  settings.discretization = static_cast<solver::ContactDiscretization>(state.range(3));
  settings.algorithm = static_cast<solver::ContactAlgorithm>(state.range(4));
  const double reference = reference_seconds(spec, setup.model, setup.pair);
  solver::ContactResult r;
  double seconds = 0.0;
  for (auto _ : state) {
    const auto start = Clock::now();
    solver::LinearStaticAnalysis elastic(setup.model);
    solver::ContactAnalysis contact(elastic, setup.pair);
    r = contact.solve(settings);
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
  }
  if (!r.converged())
    state.SetLabel("not converged: " + r.reason);
  state.counters["iterations"] = r.active_set_iterations;
  state.counters["augmentations"] = r.augmentations;
  state.counters["ratio"] = seconds / reference;
  state.counters["reference_s"] = reference;
  state.counters["condensation_s"] = r.timings.condensation_s;
  state.counters["analyze_s"] = r.timings.analyze_s;
  state.counters["factorize_s"] = r.timings.factorize_s;
  state.counters["condense_s"] = r.timings.condense_s;
  state.counters["iterations_s"] = r.timings.iterations_s;
  state.counters["contact_dofs"] = r.n_contact_dofs;
  state.counters["candidates"] = r.n_candidates;
}

/// Every discretization x algorithm (12 cases) on ONE ContactAnalysis, as the suite engine runs
/// a model's cases: the sparse factorization is shared. Args: problem, mesh, element.
void BM_ContactAllOptions(benchmark::State& state) {
  const suites::CaseSpec spec = case_spec(state);
  const suites::ProblemSetup setup = suites::build_problem(spec);
  const double reference = reference_seconds(spec, setup.model, setup.pair);
  int converged = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    const auto start = Clock::now();
    solver::LinearStaticAnalysis elastic(setup.model);
    solver::ContactAnalysis contact(elastic, setup.pair);
    converged = 0;
    for (int d = 0; d < 3; ++d) {
      for (int a = 0; a < 4; ++a) {
        solver::ContactSettings settings;
        settings.discretization = static_cast<solver::ContactDiscretization>(d);
        settings.algorithm = static_cast<solver::ContactAlgorithm>(a);
        converged += contact.solve(settings).converged() ? 1 : 0;
      }
    }
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
  }
  state.counters["cases"] = 12;
  state.counters["converged"] = converged;
  state.counters["ratio_per_case"] = seconds / 12.0 / reference;
  state.counters["reference_s"] = reference;
}

void contact_arguments(benchmark::internal::Benchmark* b) {
  for (int problem = 0; problem < 3; ++problem) {
    for (int mesh = 0; mesh < 3; ++mesh) {
      for (int element = 0; element < 2; ++element) {
        for (int discretization = 0; discretization < 3; ++discretization) {
          for (int algorithm = 0; algorithm < 4; ++algorithm) {
            b->Args({problem, mesh, element, discretization, algorithm});
          }
        }
      }
    }
  }
}

}  // namespace

BENCHMARK(BM_Contact)
    ->Name("Contact")
    ->Apply(contact_arguments)
    ->ArgNames({"problem", "mesh", "element", "contact", "algorithm"})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(BM_ContactAllOptions)
    ->Name("ContactAllOptions")
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}, {0, 1}})
    ->ArgNames({"problem", "mesh", "element"})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
