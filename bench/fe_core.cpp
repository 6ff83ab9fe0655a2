// Benchmarks of the FE core on square blocks of Q4 and Q8 elements, up to the study's largest
// mesh (268,944 Q8 elements, about 1.6 million unknowns; here 519 x 519 = 269,361 elements):
//   BM_Assembly   element stiffness + scatter into the fixed pattern of K_ff (+ K_cg);
//   BM_AssemblyTriplets   the same through triplets and setFromTriplets (for comparison);
//   BM_Phases     one full linear solve, phase by phase: assembly, symbolic analysis
//                 (fill-reducing ordering), numeric factorization, one solve. The reported
//                 time is the FACTORIZATION; every phase, the unknowns, nnz(L), flops and the
//                 process's peak RSS are counters. CHOLMOD supernodal at every size, Eigen
//                 SimplicialLDLT up to moderate sizes (it is 7-15x slower).
// The model: the unit block, roller supports on the bottom (u_z = 0) and left (u_x = 0),
// uniform pressure on the top, plane strain.
//
// Run: build-*/bench/bench_fe_core --benchmark_filter=Phases   (the largest cases take
// minutes; --benchmark_filter='Phases/0/1/519' runs the largest Q8 CHOLMOD case alone, which
// gives its own peak RSS).

#include <sys/resource.h>

#include <chrono>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "solver/elements/element_stiffness.hpp"
#include "solver/linear_static.hpp"
#include "solver/mesh/structured_block.hpp"

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

/// Args: solver (0 = CHOLMOD supernodal, 1 = SimplicialLDLT), element type, n, ordering
/// (0 = automatic, 1 = METIS, 2 = AMD, 3 = NESDIS).
void BM_Phases(benchmark::State& state) {
  const auto model = block_model(element_type(state.range(1)), static_cast<int>(state.range(2)));
  LinearStaticOptions options;
  options.linear_solver.kind = state.range(0) == 0 ? LinearSolverKind::CholmodSupernodal
                                                   : LinearSolverKind::EigenSimplicialLDLT;
  const FillReducingOrdering orderings[] = {FillReducingOrdering::Automatic,
                                            FillReducingOrdering::Metis, FillReducingOrdering::Amd,
                                            FillReducingOrdering::Nesdis};
  options.linear_solver.ordering = orderings[state.range(3)];
  Timings t;
  FactorizationInfo info;
  int unknowns = 0;
  for (auto _ : state) {
    LinearStaticAnalysis analysis(*model, options);
    auto start = std::chrono::steady_clock::now();
    analysis.assemble();
    t.assembly_s = seconds_since(start);
    const SolveOutcome factored = analysis.factorize();
    if (!factored.ok()) {
      state.SkipWithError(factored.reason.c_str());
      break;
    }
    t.analyze_s = analysis.timings().analyze_s;
    t.factorize_s = analysis.timings().factorize_s;
    start = std::chrono::steady_clock::now();
    const Eigen::VectorXd f = analysis.reduced_load(model->loads);
    const Eigen::VectorXd u = analysis.solve_reduced(f);
    benchmark::DoNotOptimize(u.data());
    t.solve_s = seconds_since(start);
    t.setup_s = analysis.timings().setup_s;
    info = analysis.linear_solver().info();
    unknowns = analysis.dof_map().n_free();
    state.SetIterationTime(t.factorize_s);
  }
  state.counters["unknowns"] = unknowns;
  state.counters["setup_s"] = t.setup_s;
  state.counters["assembly_s"] = t.assembly_s;
  state.counters["analyze_s"] = t.analyze_s;
  state.counters["factorize_s"] = t.factorize_s;
  state.counters["solve_s"] = t.solve_s;
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

BENCHMARK_MAIN();
