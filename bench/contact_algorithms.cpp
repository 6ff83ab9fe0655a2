// Benchmarks of the contact algorithms on the study's problems H_p, S_1_7 and P'_p (meshed
// stiff indenter, the study's choice), per mesh level, element, discretization and algorithm.
//
// Names say what they time, with the names of results.json and the solver (no index to decode):
//   Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>   e.g. Contact/H_p/F/Q4/ss/LM
//     problem H_p | S_1_7 | Pprime_p (the study's P'_p), mesh C | M | F, element Q4 | Q8,
//     contact ns | ss | mortar, algorithm PM | AL | LM | MPC.
//   ContactAllOptions/<problem>/<mesh>/<element>                e.g. ContactAllOptions/H_p/F/Q4
// Google Benchmark appends "/iterations:1/manual_time" to the names it prints.
//
// Contact: one contact analysis, with the contact settings the suite gives that case (the
// problem's FKN, FTOLN and pinball: suites::contact_settings), so that it is a case of the results.
//   time     the contact analysis: assembly, constraint rows, condensation (one sparse
//            factorization with the contact DOFs ordered last, then dense BLAS-3), the active-set
//            iterations and the displacement recovery;
//   counters active_set_iterations (linear solves of the condensed problem; not called
//            "iterations", which the JSON output already uses for the benchmark's own loop
//            count), augmentations (AL), the contact DOFs |c| (contact_dofs) and candidate rows m
//            (candidates), the phases' seconds (condensation_s, analyze_s, factorize_s,
//            condense_s, iterations_s), reference_s (one assembly + factorization + solve of the
//            same model, measured in the same run, the faster of two) and ratio = time /
//            reference_s (the physical floor of the ratio is 1; see reference_seconds). A case that
//            does not converge is labelled "not converged: <reason>".
//
// ContactAllOptions: the 12 discretization x algorithm cases of one model on one
// ContactAnalysis (one shared factorization), with ratio_per_case = time / 12 / reference_s and
// the number of cases that converged.
//
// ModelCases: the suite engine's full set of cases of one model, as the main job runs them
// (ci/main.sh: 5 algorithms x ns, ss, mortar x patch-recovered and extrapolated stresses, 30
// cases on one ProblemExecutor: model built once, one shared factorization, each case graded),
// against one analysis of the model (`contact-suite case <problem> --algorithm LMP --contact ss`:
// build, assembly, factorization, solve and grading). The set and the one analysis are timed in
// turns, `pairs` times (until 2 s have passed, at most 9; once for a large model), and the time
// is the set's median. Counters: cases, converged, pairs, one_case_s (the one analysis's median)
// and ratio = the set's median / one_case_s (the target is at most 1.3: every case after the
// first adds little to the factorization); the same in process CPU time (one_case_cpu_s,
// ratio_cpu), which a loaded machine leaves comparable; and blas_threads: one for the set and
// for the one analysis, as `run` gives every model.
//   ModelCases/<problem>/<mesh>/<element>                       e.g. ModelCases/H_p/F/Q8
//
// Run:  build-*/bench/bench_contact_algorithms --benchmark_filter='Contact/H_p/M/'   (H_p, M)
//       --benchmark_filter='^Contact/Pprime_p/(C|M)/Q4/'     --benchmark_list_tests lists names
//       --benchmark_out=bench.json --benchmark_out_format=json   JSON for `contact-suite report
//       --bench bench.json` (see ci/bench.sh and docs/benchmarks.md). The F meshes of S_1_7
//       take about 7 s (Q4) and 30 s (Q8) per case on 2 cores.

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "bench/benchmark_main.hpp"

#include "solver/contact/contact_analysis.hpp"
#include "solver/linear_static.hpp"
#include "suites/case_matrix.hpp"
#include "suites/problem_executor.hpp"
#include "suites/problem_setup.hpp"
#include "suites/run_environment.hpp"
#include "suites/start_settings.hpp"

namespace {

using namespace cs;
using Clock = std::chrono::steady_clock;

/// The problems of the timing matrix.
constexpr suites::ProblemId kProblems[] = {suites::ProblemId::H_p, suites::ProblemId::S_1_7,
                                           suites::ProblemId::Pprime_p};
constexpr suites::ContactKind kDiscretizations[] = {
    suites::ContactKind::ns, suites::ContactKind::ss, suites::ContactKind::mortar};
constexpr suites::Algorithm kAlgorithms[] = {suites::Algorithm::PM, suites::Algorithm::AL,
                                             suites::Algorithm::LMP, suites::Algorithm::MPC};
constexpr int kCasesPerModel =
    static_cast<int>(std::size(kDiscretizations) * std::size(kAlgorithms));

/// The contact settings of `model` with `contact` and `algorithm` as a case of the suite runs
/// them (the problem's FKN, FTOLN and pinball), so that a timing is of a case of the results.
solver::ContactSettings case_settings(suites::CaseSpec model, suites::ContactKind contact,
                                      suites::Algorithm algorithm) {
  model.contact = contact;
  model.algorithm = algorithm;
  return suites::contact_settings(model);
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// CPU seconds of the whole process (every thread) so far: a ratio of two of them holds on a
/// loaded machine, where wall-clock time also counts the waits for a core.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// "H_p/F/Q4": the model part of a benchmark name.
std::string model_name(const suites::CaseSpec& spec) {
  return fmt::format("{}/{}/{}", suites::to_string(spec.problem), suites::to_string(spec.mesh),
                     suites::to_string(spec.element));
}

/// One assembly + factorization + solve of the model (seconds; NaN if the factorization fails).
/// The bodies held only by contact (the block; S's loaded punch) get tiny springs (1e-3 of the
/// diagonal) on their contact surfaces' z DOFs: the same pattern and cost, a regular matrix.
double time_reference_solve(const solver::Model& model, const solver::ContactPair& pair) {
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
    return std::nan("");
  }
  const Eigen::VectorXd u = elastic.solve_reduced(elastic.reduced_load(model.loads));
  benchmark::DoNotOptimize(u.data());
  return seconds_since(start);
}

/// The reference of the ratio: time_reference_solve, measured once per model as the faster of
/// two runs, so that no model's reference carries the one-time costs of the process (loading
/// and initializing BLAS and CHOLMOD, first-touch page faults; measured 4x the warm time on the
/// first model).
double reference_seconds(const suites::CaseSpec& spec, const solver::Model& model,
                         const solver::ContactPair& pair) {
  static std::map<std::tuple<int, int, int>, double> cache;
  const auto key = std::make_tuple(static_cast<int>(spec.problem), static_cast<int>(spec.mesh),
                                   static_cast<int>(spec.element));
  if (const auto it = cache.find(key); it != cache.end()) {
    return it->second;
  }
  const double first = time_reference_solve(model, pair);
  return cache[key] = std::fmin(first, time_reference_solve(model, pair));
}

/// One contact analysis of `spec`'s model with `settings`.
void BM_Contact(benchmark::State& state, const suites::CaseSpec& spec,
                const solver::ContactSettings& settings) {
  const suites::ProblemSetup setup = suites::build_problem(spec);
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
  state.counters["active_set_iterations"] = r.active_set_iterations;
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

/// Every discretization x algorithm on ONE ContactAnalysis, as the suite engine runs a model's
/// cases: the sparse factorization is shared.
void BM_ContactAllOptions(benchmark::State& state, const suites::CaseSpec& spec) {
  const suites::ProblemSetup setup = suites::build_problem(spec);
  const double reference = reference_seconds(spec, setup.model, setup.pair);
  int converged = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    const auto start = Clock::now();
    solver::LinearStaticAnalysis elastic(setup.model);
    solver::ContactAnalysis contact(elastic, setup.pair);
    converged = 0;
    for (const auto discretization : kDiscretizations) {
      for (const auto algorithm : kAlgorithms)
        converged +=
            contact.solve(case_settings(spec, discretization, algorithm)).converged() ? 1 : 0;
    }
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
  }
  state.counters["cases"] = kCasesPerModel;
  state.counters["converged"] = converged;
  state.counters["ratio_per_case"] = seconds / kCasesPerModel / reference;
  state.counters["reference_s"] = reference;
}

/// The main job's cases of `model`'s model (ci/main.sh): every algorithm, ns, ss and mortar,
/// patch-recovered and extrapolated stresses.
std::vector<suites::CaseSpec> model_cases(const suites::CaseSpec& model) {
  suites::CaseSelection selection;
  selection.problems = {model.problem};
  selection.meshes = {model.mesh};
  selection.elements = {model.element};
  selection.contacts = {suites::ContactKind::ns, suites::ContactKind::ss,
                        suites::ContactKind::mortar};
  selection.recoveries = {suites::Recovery::spr, suites::Recovery::extrapolated};
  return suites::make_case_matrix(selection);
}

/// Wall and process CPU seconds of one timed piece of work.
struct Timing {
  double wall = 0.0;
  double cpu = 0.0;
};

template <typename Work>
Timing timed(Work&& work) {
  const auto start = Clock::now();
  const double cpu_start = process_cpu_seconds();
  work();
  return {seconds_since(start), process_cpu_seconds() - cpu_start};
}

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Pairs (the set, then one analysis) are repeated until they took this long, so that a small
/// model's ratio is not the ratio of two single samples of 0.1 s each.
constexpr double kModelCasesSeconds = 2.0;
constexpr int kModelCasesMaxPairs = 9;

/// A model's full set of cases on one executor, against one analysis of the model: both timed
/// in turns, each pair in the same state of the machine, and compared by their medians.
void BM_ModelCases(benchmark::State& state, const suites::CaseSpec& model) {
  const std::vector<suites::CaseSpec> cases = model_cases(model);
  suites::CaseSpec one = cases.front();
  one.algorithm = suites::Algorithm::LMP;
  one.contact = suites::ContactKind::ss;
  one.recovery = suites::Recovery::spr;
  // One BLAS thread, as `contact-suite run` gives every model (apps/model_cost.hpp).
  const int threads_before = suites::blas_threads();
  const int threads = 1;
  suites::set_blas_threads(threads);
  int converged = 0;
  std::vector<double> set_wall, set_cpu, one_wall, one_cpu;
  for (auto _ : state) {
    double spent = 0.0;
    set_wall.clear(), set_cpu.clear(), one_wall.clear(), one_cpu.clear();
    while (set_wall.empty() || (spent < kModelCasesSeconds &&
                                static_cast<int>(set_wall.size()) < kModelCasesMaxPairs)) {
      const Timing set = timed([&] {
        suites::ProblemExecutor executor(cases.front());
        converged = 0;
        for (const suites::CaseSpec& spec : cases)
          converged += executor.run(spec).status == suites::CaseStatus::converged ? 1 : 0;
      });
      const Timing single = timed([&] {
        suites::ProblemExecutor executor(one);
        benchmark::DoNotOptimize(executor.run(one).status);
      });
      set_wall.push_back(set.wall), set_cpu.push_back(set.cpu);
      one_wall.push_back(single.wall), one_cpu.push_back(single.cpu);
      spent += set.wall + single.wall;
    }
    state.SetIterationTime(median_of(set_wall));
  }
  state.counters["cases"] = static_cast<double>(cases.size());
  state.counters["converged"] = converged;
  state.counters["pairs"] = static_cast<double>(set_wall.size());
  state.counters["one_case_s"] = median_of(one_wall);
  state.counters["ratio"] = median_of(set_wall) / median_of(one_wall);
  state.counters["one_case_cpu_s"] = median_of(one_cpu);
  state.counters["ratio_cpu"] = median_of(set_cpu) / median_of(one_cpu);
  state.counters["blas_threads"] = threads;
  suites::set_blas_threads(threads_before);
}

/// Every model of the matrix: problem x mesh level x element, in the study's order.
std::vector<suites::CaseSpec> models() {
  std::vector<suites::CaseSpec> out;
  for (const auto problem : kProblems) {
    for (const auto mesh : schema::kStudyMeshes) {
      for (const auto element : schema::values<schema::Element>()) {
        suites::CaseSpec spec;
        spec.problem = problem;
        spec.mesh = mesh;
        spec.element = element;
        spec.target = suites::TargetKind::Discretized;
        out.push_back(spec);
      }
    }
  }
  return out;
}

/// Registers Contact/... for every model and option, then ContactAllOptions/... per model.
void register_benchmarks() {
  for (const suites::CaseSpec& spec : models()) {
    for (const auto discretization : kDiscretizations) {
      for (const auto algorithm : kAlgorithms) {
        const solver::ContactSettings settings = case_settings(spec, discretization, algorithm);
        const std::string name = fmt::format("Contact/{}/{}/{}", model_name(spec),
                                             solver::to_string(settings.discretization),
                                             solver::to_string(settings.algorithm));
        benchmark::RegisterBenchmark(name.c_str(), BM_Contact, spec, settings)
            ->UseManualTime()
            ->Iterations(1)
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
  for (const suites::CaseSpec& spec : models()) {
    const std::string name = "ModelCases/" + model_name(spec);
    benchmark::RegisterBenchmark(name.c_str(), BM_ModelCases, spec)
        ->UseManualTime()
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  for (const suites::CaseSpec& spec : models()) {
    const std::string name = "ContactAllOptions/" + model_name(spec);
    benchmark::RegisterBenchmark(name.c_str(), BM_ContactAllOptions, spec)
        ->UseManualTime()
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

/// BENCHMARK_MAIN with the benchmarks registered by name first, and OpenBLAS's kernels, huge
/// pages and the OpenMP regions as `contact-suite run` has them
/// (suites::start_with_the_machines_settings, suites::run_openmp_regions_serially), so that the
/// timings are its.
int main(int argc, char** argv) {
  cs::suites::start_with_the_machines_settings(argv, {.huge_pages = true});
  cs::suites::run_openmp_regions_serially();
  register_benchmarks();
  return cs::bench::run_benchmarks(argc, argv);
}
