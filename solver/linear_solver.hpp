#pragma once
// The sparse symmetric positive definite solver of the reduced system: CHOLMOD's supernodal
// Cholesky through Eigen's CholmodSupport (default), or Eigen's SimplicialLDLT (comparison).
//
// Usage: analyze(A) once per sparsity pattern (fill-reducing ordering and symbolic
// factorization), factorize(A) whenever the values change, solve(B) for any number of
// right-hand sides (one column each) with one factorization. compute(A) analyzes only when
// the pattern differs from the analyzed one.
//
// A is the LOWER TRIANGLE of the symmetric matrix, compressed column storage, rows sorted
// (StiffnessMatrices::K_ff).
//
// Failures are statuses, not NaNs: a non-positive pivot gives NotPositiveDefinite (with the
// failed equation in the original numbering); a factor whose pivot ratio estimate is below
// LinearSolverOptions::min_pivot_ratio gives Singular.

#include <memory>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solver/solve_status.hpp"

namespace cs::solver {

/// The factorization used for the reduced system.
enum class LinearSolverKind {
  CholmodSupernodal,    ///< CHOLMOD supernodal LL' (BLAS-3 on supernodes; the default)
  EigenSimplicialLDLT,  ///< Eigen's SimplicialLDLT with AMD ordering (for comparison)
};

/// The fill-reducing ordering CHOLMOD tries (ignored by EigenSimplicialLDLT, which uses AMD).
enum class FillReducingOrdering {
  Automatic,       ///< the default, CHOLMOD's strategy with the node-graph METIS: AMD; if its
                   ///< fill is high (flops/nnz(L) >= 500 and nnz(L)/nnz(A) >= 5, CHOLMOD's
                   ///< test) also METIS (on the supervariable graph when set); the one with
                   ///< fewer flops is kept. Small systems get AMD's fast analysis, large 2D
                   ///< meshes METIS's lower fill.
  Metis,           ///< METIS nested dissection always (least fill on large 2D FE meshes); on the
                   ///< supervariable (node) graph when supervariables are set, else CHOLMOD's
  Nesdis,          ///< CHOLMOD's nested dissection (METIS + constrained minimum degree)
  Amd,             ///< approximate minimum degree only
  CholmodDefault,  ///< CHOLMOD's own default: AMD, then METIS if AMD's fill is high
  Best,            ///< try AMD, METIS and NESDIS, keep the least fill (slowest analysis)
};

const char* to_string(LinearSolverKind kind);
const char* to_string(FillReducingOrdering ordering);

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::CholmodSupernodal;
  FillReducingOrdering ordering = FillReducingOrdering::Automatic;
  /// A factor whose smallest-to-largest pivot ratio estimate (CHOLMOD's rcond for LL', the
  /// ratio of diagonal entries of D for LDL') is below this is reported Singular. Measured on
  /// blocks: a floating block gives 5e-14 to 2e-13; a held one 0.05 to 0.1; a bonded stiff
  /// indenter (E ratio 1e6) 6e-8 to 3e-7, independent of the mesh size. Large penalty terms
  /// (factorize_with) lower healthy values in proportion: lower the threshold with them. A
  /// backstop only: LinearStaticAnalysis finds unrestrained bodies first, by name.
  double min_pivot_ratio = 1e-10;
};

/// What the last analysis and factorization did.
struct FactorizationInfo {
  LinearSolverKind kind = LinearSolverKind::CholmodSupernodal;
  int n = 0;                 ///< equations
  long nnz_matrix = 0;       ///< nonzeros of the lower triangle of A
  double nnz_factor = 0.0;   ///< nonzeros of L (CHOLMOD: fundamental, without amalgamation)
  double flops = 0.0;        ///< factorization flop count (CHOLMOD's estimate; 0 for LDL')
  std::string ordering;      ///< the fill-reducing ordering actually selected
  bool supernodal = false;   ///< whether the factor is supernodal
  double pivot_ratio = 0.0;  ///< min/max pivot estimate of the last factorization
  int analyze_count = 0;     ///< symbolic analyses done so far
  int factorize_count = 0;   ///< numeric factorizations done so far
};

class LinearSolver {
 public:
  explicit LinearSolver(LinearSolverOptions options = {});
  ~LinearSolver();
  LinearSolver(LinearSolver&&) noexcept;
  LinearSolver& operator=(LinearSolver&&) noexcept;
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// Declares supervariables: equations with the same group (e.g. the DOFs of one node) are
  /// ordered together, and the METIS ordering is computed on the group graph (several times
  /// faster than on the equation graph). Used by the next analyze(); an empty vector clears.
  void set_supervariables(std::vector<int> group_of_equation);

  /// Fill-reducing ordering and symbolic factorization of the pattern of A (lower triangle).
  SolveOutcome analyze(const Eigen::SparseMatrix<double>& A_lower);

  /// Numeric factorization of A, whose pattern must be the analyzed one.
  SolveOutcome factorize(const Eigen::SparseMatrix<double>& A_lower);

  /// analyze(A) if A's pattern is not the analyzed one, then factorize(A).
  SolveOutcome compute(const Eigen::SparseMatrix<double>& A_lower);

  /// Whether A's pattern is the one last analyzed successfully (factorize(A) is allowed).
  bool is_analyzed_for(const Eigen::SparseMatrix<double>& A_lower) const;

  /// Whether the last factorization succeeded (solve() is allowed).
  bool is_factorized() const;

  /// X = A^{-1} B for every column of B, with the current factorization. Throws
  /// std::logic_error if there is none.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  const LinearSolverOptions& options() const { return options_; }
  const FactorizationInfo& info() const { return info_; }

 private:
  struct Impl;
  LinearSolverOptions options_;
  FactorizationInfo info_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cs::solver
