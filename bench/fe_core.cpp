// Benchmarks of the FE core on square blocks of Q4 and Q8 elements, up to the study's largest
// mesh (268,944 Q8 elements, about 1.6 million unknowns; here 519 x 519 = 269,361 elements):
//   BM_Assembly   element stiffness + scatter into the fixed pattern of K_ff (+ K_cg);
//   BM_AssemblyTriplets   the same through triplets and setFromTriplets (for comparison);
//   BM_Phases     one full linear solve, phase by phase: assembly, symbolic analysis
//                 (fill-reducing ordering), numeric factorization, one solve. The reported
//                 time is the FACTORIZATION; every phase, the unknowns, nnz(L), flops and the
//                 process's peak RSS are counters. CHOLMOD supernodal at every size, Eigen
//                 SimplicialLDLT up to moderate sizes (it is 7-15x slower).
//   BM_StressRecovery   nodal stresses of a smooth displacement field: extrapolated and
//                 averaged (arg 0) or superconvergent patch recovery (arg 1), whose cost is
//                 reported beside the extrapolation it starts from in the same run.
// The model: the unit block, roller supports on the bottom (u_z = 0) and left (u_x = 0),
// uniform pressure on the top, plane strain.
//
// Run: build-*/bench/bench_fe_core --benchmark_filter=Phases   (the largest cases take
// minutes; --benchmark_filter='Phases/0/1/519' runs the largest Q8 CHOLMOD case alone, which
// gives its own peak RSS).

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/benchmark_main.hpp"

#include "solver/elements/element_stiffness.hpp"
#include "solver/linear_static.hpp"
#include "solver/load_vector.hpp"
#include "solver/mesh/structured_block.hpp"
#include "solver/stress_recovery.hpp"
#include "suites/start_settings.hpp"

namespace {

using namespace cs::solver;

double peak_rss_gb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / (1024.0 * 1024.0);  // ru_maxrss is in KiB
}

std::unique_ptr<Model> block_model(ElementType type, int n) {
  auto model = std::make_unique<Model>();
  BlockSpec spec;
  spec.type = type;
  spec.nx = n;
  spec.nz = n;
  model->mesh = make_block(spec);
  model->materials = {{1000.0, 0.3}};
  model->fix(NodeSelection::node_set("bottom"), Component::Z);
  model->fix(NodeSelection::node_set("left"), Component::X);
  model->loads.add_pressure("top", 1.0);
  return model;
}

ElementType element_type(int64_t arg) {
  return arg == 0 ? ElementType::Q4 : ElementType::Q8;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Args: element type (0 = Q4, 1 = Q8), n (n x n elements).
void BM_Assembly(benchmark::State& state) {
  const auto model = block_model(element_type(state.range(0)), static_cast<int>(state.range(1)));
  const DofMap dofs(*model);
  const Assembler assembler(*model, dofs);
  StiffnessMatrices K;
  for (auto _ : state) {
    assembler.assemble(K);
    benchmark::DoNotOptimize(K.K_ff.valuePtr());
  }
  state.counters["unknowns"] = dofs.n_free();
  state.counters["nnz_K"] = static_cast<double>(assembler.nnz());
  state.counters["elements/s"] =
      benchmark::Counter(model->mesh.n_elements(), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_rss_GB"] = peak_rss_gb();
}

/// The same assembly the textbook way, for comparison: element matrices into triplets (lower
/// triangle of the free block), then SparseMatrix::setFromTriplets. Args as BM_Assembly.
void BM_AssemblyTriplets(benchmark::State& state) {
  const auto model = block_model(element_type(state.range(0)), static_cast<int>(state.range(1)));
  const DofMap dofs(*model);
  const Mesh& mesh = model->mesh;
  const Eigen::Matrix4d D = elasticity_matrix(model->materials[0]);
  const int nd = 2 * mesh.n_element_nodes();
  Eigen::SparseMatrix<double> K(dofs.n_free(), dofs.n_free());
  std::vector<Eigen::Triplet<double>> triplets;
  for (auto _ : state) {
    triplets.clear();
    triplets.reserve(static_cast<std::size_t>(mesh.n_elements()) * nd * (nd + 1) / 2);
    ElementMatrix K_e;
    for (int e = 0; e < mesh.n_elements(); ++e) {
      element_stiffness(element_geometry(mesh, model->analysis, e), D, model->element_points(),
                        K_e);
      int eq[16];
      for (int i = 0; i < nd; ++i)
        eq[i] = dofs.equation(2 * mesh.elements[e][i / 2] + i % 2);
      for (int j = 0; j < nd; ++j) {
        for (int i = 0; i < nd; ++i) {
          if (eq[i] >= eq[j] && eq[j] >= 0)
            triplets.emplace_back(eq[i], eq[j], K_e(i, j));
        }
      }
    }
    K.setFromTriplets(triplets.begin(), triplets.end());
    benchmark::DoNotOptimize(K.valuePtr());
  }
  state.counters["unknowns"] = dofs.n_free();
  state.counters["nnz_K"] = static_cast<double>(K.nonZeros());
  state.counters["elements/s"] =
      benchmark::Counter(mesh.n_elements(), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_rss_GB"] = peak_rss_gb();
}

/// Process CPU seconds (user + system, all threads): with the machine shared, wall time
/// depends on the load; CPU time does not (a quiet 2-core machine runs the BLAS-3 parts in
/// about half of it).
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// Wall and CPU seconds of one phase.
struct PhaseTime {
  double wall = 0.0;
  double cpu = 0.0;
};

template <typename F>
PhaseTime timed(F&& phase) {
  const auto start = std::chrono::steady_clock::now();
  const double cpu = cpu_seconds();
  phase();
  return {seconds_since(start), cpu_seconds() - cpu};
}

/// Args: solver (0 = CHOLMOD supernodal, 1 = SimplicialLDLT), element type, n, ordering
/// (0 = automatic, 1 = METIS, 2 = AMD, 3 = NESDIS). The phases as LinearStaticAnalysis runs
/// them (DofMap, Assembler, LinearSolver with the nodes as supervariables).
void BM_Phases(benchmark::State& state) {
  const auto model = block_model(element_type(state.range(1)), static_cast<int>(state.range(2)));
  LinearSolverOptions options;
  options.kind = state.range(0) == 0 ? LinearSolverKind::CholmodSupernodal
                                     : LinearSolverKind::EigenSimplicialLDLT;
  const FillReducingOrdering orderings[] = {FillReducingOrdering::Automatic,
                                            FillReducingOrdering::Metis, FillReducingOrdering::Amd,
                                            FillReducingOrdering::Nesdis};
  options.ordering = orderings[state.range(3)];
  PhaseTime setup, assembly, analyze, factorize, solve;
  FactorizationInfo info;
  int unknowns = 0;
  for (auto _ : state) {
    std::unique_ptr<DofMap> dofs;
    std::unique_ptr<Assembler> assembler;
    setup = timed([&] {
      dofs = std::make_unique<DofMap>(*model);
      assembler = std::make_unique<Assembler>(*model, *dofs);
    });
    StiffnessMatrices K;
    assembly = timed([&] { assembler->assemble(K); });
    LinearSolver solver(options);
    std::vector<int> node_of_equation(dofs->n_free());
    for (int k = 0; k < dofs->n_free(); ++k)
      node_of_equation[k] = dofs->free_dofs()[k] / 2;
    solver.set_supervariables(std::move(node_of_equation));
    SolveOutcome outcome;
    analyze = timed([&] { outcome = solver.analyze(K.K_ff); });
    if (outcome.ok())
      factorize = timed([&] { outcome = solver.factorize(K.K_ff); });
    if (!outcome.ok()) {
      state.SkipWithError(outcome.reason.c_str());
      break;
    }
    solve = timed([&] {
      const Eigen::VectorXd f = dofs->restrict_to_free(assemble_load_vector(*model, model->loads));
      const Eigen::VectorXd u = solver.solve(f);
      benchmark::DoNotOptimize(u.data());
    });
    info = solver.info();
    unknowns = dofs->n_free();
    state.SetIterationTime(factorize.wall);
  }
  state.counters["unknowns"] = unknowns;
  state.counters["setup_s"] = setup.wall;
  state.counters["assembly_s"] = assembly.wall;
  state.counters["analyze_s"] = analyze.wall;
  state.counters["analyze_cpu_s"] = analyze.cpu;
  state.counters["factorize_s"] = factorize.wall;
  state.counters["factorize_cpu_s"] = factorize.cpu;
  state.counters["solve_s"] = solve.wall;
  state.counters["nnz_L"] = info.nnz_factor;
  state.counters["GFlop"] = info.flops * 1e-9;
  state.counters["peak_rss_GB"] = peak_rss_gb();
  state.SetLabel(std::string(to_string(info.kind)) + ", " + info.ordering);
}

BENCHMARK(BM_Assembly)
    ->ArgNames({"q8", "n"})
    ->Args({0, 128})
    ->Args({0, 519})
    ->Args({1, 128})
    ->Args({1, 519})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(BM_AssemblyTriplets)
    ->ArgNames({"q8", "n"})
    ->Args({0, 128})
    ->Args({1, 128})
    ->Unit(benchmark::kMillisecond);

void phase_cases(benchmark::internal::Benchmark* b) {
  b->ArgNames({"ldlt", "q8", "n", "ordering"});
  for (int n : {128, 256, 519})
    b->Args({0, 0, n, 0});  // CHOLMOD, Q4
  for (int n : {64, 128, 256, 519})
    b->Args({0, 1, n, 0});  // CHOLMOD, Q8
  for (int n : {128, 256})
    b->Args({1, 0, n, 0});  // SimplicialLDLT, Q4
  for (int n : {64, 128})
    b->Args({1, 1, n, 0});  // SimplicialLDLT, Q8
  for (int ordering : {1, 2, 3})
    b->Args({0, 1, 256, ordering});  // orderings compared, Q8 256
  b->Args({0, 1, 519, 3});           // NESDIS at the largest
}

BENCHMARK(BM_Phases)->Apply(phase_cases)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

/// Args: method (0 extrapolated and averaged, 1 patch recovery), element (0 Q4, 1 Q8), n.
void BM_StressRecovery(benchmark::State& state) {
  const auto model = block_model(element_type(state.range(1)), static_cast<int>(state.range(2)));
  Eigen::VectorXd u(2 * model->mesh.n_nodes());
  for (int n = 0; n < model->mesh.n_nodes(); ++n) {
    const Eigen::Vector2d x = model->mesh.nodes[n];
    u.segment<2>(2 * n) = 1e-3 * Eigen::Vector2d(std::sin(x.x() + 2 * x.y()), x.x() * x.y());
  }
  StressRecoveryOptions options;
  options.method = state.range(0) == 0 ? StressRecoveryMethod::ExtrapolatedAveraged
                                       : StressRecoveryMethod::PatchRecovered;
  for (auto _ : state) {
    const StressField field = recover_stresses(*model, u, options);
    benchmark::DoNotOptimize(field.nodal.data());
  }
  state.counters["nodes"] = model->mesh.n_nodes();
}

BENCHMARK(BM_StressRecovery)
    ->Name("StressRecovery")
    ->ArgsProduct({{0, 1}, {0, 1}, {256}})
    ->ArgNames({"method", "element", "n"})
    ->Unit(benchmark::kMillisecond);

/// BENCHMARK_MAIN with OpenBLAS's kernels and huge pages as `contact-suite run` has them (a
/// factorization is timed).
int main(int argc, char** argv) {
  cs::suites::start_with_the_machines_settings(argv, {.huge_pages = true});
  return cs::bench::run_benchmarks(argc, argv);
}
