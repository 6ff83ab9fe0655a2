#pragma once
// Linear static analysis of a Model: assemble, factorize, solve, reactions; and the hooks a
// contact algorithm needs to add its terms and re-solve with the same factorization.
//
// The reduced system over the free DOFs (prescribed displacements eliminated, see DofMap) is
//   K_ff u_f = f_f - K_fc u_c,
// and the reactions are r_c = K_cf u_f + K_cc u_c - f_c (per unit thickness | per radian).
//
// How contact plugs in (solver/contact/, later): keep one LinearStaticAnalysis per model.
//   - assemble() once; stiffness().K_ff is the lower triangle of K_ff in the DofMap's equation
//     numbering; reduced_load(loads) is f_f - K_fc u_c; dof_map().equation(2 n + c) maps a
//     node's DOF to its equation (-1 if prescribed: contact terms there are dropped or moved to
//     the right-hand side with the prescribed value).
//   - Penalty / augmented Lagrangian: build the contact stiffness P (lower triangle, same
//     size) and call factorize_with(P): K_ff + P is factorized, its symbolic analysis reused
//     while the active set (hence the pattern) is unchanged. Solve with solve_reduced().
//   - Lagrange multipliers / MPC: factorize() K_ff once, then solve_reduced(C^T) for the
//     constraint columns (one factorization, many right-hand sides) and the small dense Schur
//     complement C K_ff^{-1} C^T in the contact code.
//   - expand(u_f) gives the global displacement, reactions(u, loads) the reactions, and
//     stress recovery (stress_recovery.hpp) takes the global displacement.
//   - find_unrestrained_bodies(model, dof_map, {{indenter, block}}) checks rigid-body modes
//     with the contact pair counted as a coupling.

#include <chrono>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solver/assembly.hpp"
#include "solver/dof_map.hpp"
#include "solver/linear_solver.hpp"
#include "solver/model.hpp"
#include "solver/solve_status.hpp"

namespace cs::solver {

/// Wall-clock seconds spent in each phase (cumulative over the analysis' lifetime for the
/// phases it repeats; the result of a solve reports that solve's phases).
struct Timings {
  double setup_s = 0.0;      ///< validation, DOF map, sparsity pattern and scatter map
  double assembly_s = 0.0;   ///< element matrices, K_ff and K_cg values, load vectors
  double analyze_s = 0.0;    ///< fill-reducing ordering, symbolic factorization
  double factorize_s = 0.0;  ///< numeric factorization
  double solve_s = 0.0;      ///< triangular solves, expansion, reactions
};

/// The result of a linear static solve. On failure `displacement` and `reaction` are empty.
struct LinearStaticResult {
  SolveOutcome outcome;          ///< status and, on failure, the reason
  Eigen::VectorXd displacement;  ///< global, size 2 n_nodes (DOF 2 n + c)
  Eigen::VectorXd reaction;      ///< global: K u - f at prescribed DOFs, 0 at free DOFs
  Timings timings;
  FactorizationInfo factorization;

  bool ok() const { return outcome.ok(); }
  SolveStatus status() const { return outcome.status; }
  /// Displacement (u_x|r, u_z) of node n.
  Eigen::Vector2d displacement_at(int node) const {
    return {displacement[2 * node], displacement[2 * node + 1]};
  }
};

struct LinearStaticOptions {
  LinearSolverOptions linear_solver;
  /// Check every body (group of connected bodies) for unrestrained rigid-body modes before
  /// factorizing, and report the body by name (solve() and factorize() only).
  bool check_rigid_body_modes = true;
};

class LinearStaticAnalysis {
 public:
  /// Validates the model (throws ModelError), builds the DOF map and the sparsity pattern.
  /// `model` must outlive the analysis; it may change values (materials, coordinates,
  /// prescribed values, loads) but not its mesh topology or its set of prescribed DOFs.
  explicit LinearStaticAnalysis(const Model& model, LinearStaticOptions options = {});

  /// Assembles (if not yet), factorizes K_ff (if not yet, or if the factorization held is
  /// that of factorize_with) and solves for model.loads.
  LinearStaticResult solve();

  /// Solves every load case with one factorization (one multi-column solve).
  std::vector<LinearStaticResult> solve(const std::vector<LoadCase>& load_cases);

  // --- steps, for repeated solves and for contact -------------------------------------------

  /// Recomputes K_ff and K_cg (e.g. after a material change). Invalidates the factorization;
  /// the symbolic analysis is kept (same pattern). Throws ModelError for an inverted element.
  void assemble();

  /// Re-evaluates the prescribed displacement values (same prescribed DOFs).
  void update_prescribed_values();

  /// Factorizes K_ff (assembling first if needed); analyzes the pattern only the first time.
  SolveOutcome factorize();

  /// Factorizes K_ff + P for a contact (or any) term P: lower triangle, n_free x n_free.
  /// The pattern of the sum is analyzed only when it differs from the last analyzed one.
  /// No rigid-body check (the caller knows the couplings P adds).
  SolveOutcome factorize_with(const Eigen::SparseMatrix<double>& P_lower);

  /// X = (current factored matrix)^{-1} B, one column per right-hand side.
  Eigen::MatrixXd solve_reduced(const Eigen::MatrixXd& B) const;

  /// f_f - K_fc u_c for a load case (size n_free). Requires assemble().
  Eigen::VectorXd reduced_load(const LoadCase& loads) const;
  /// The global external force vector of a load case (size 2 n_nodes).
  Eigen::VectorXd external_load(const LoadCase& loads) const;
  /// The global displacement from the free part (prescribed values filled in).
  Eigen::VectorXd expand(const Eigen::VectorXd& u_free) const { return dofs_.expand(u_free); }
  /// Global reactions K u - f at prescribed DOFs (0 elsewhere) for global u and global f.
  Eigen::VectorXd reactions(const Eigen::VectorXd& u, const Eigen::VectorXd& f_external) const;

  const Model& model() const { return model_; }
  const DofMap& dof_map() const { return dofs_; }
  /// K_ff (lower triangle) and K_cg. Valid after assemble().
  const StiffnessMatrices& stiffness() const { return K_; }
  bool is_assembled() const { return assembled_; }
  const LinearSolver& linear_solver() const { return solver_; }
  /// Cumulative timings of this analysis.
  const Timings& timings() const { return timings_; }

 private:
  SolveOutcome check_rigid_body_modes() const;
  SolveOutcome factorize_matrix(const Eigen::SparseMatrix<double>& A);
  /// Names the node, component and body of a failed equation in the outcome's reason.
  void explain_failure(SolveOutcome& outcome) const;

  std::chrono::steady_clock::time_point created_ = std::chrono::steady_clock::now();
  const Model& model_;
  LinearStaticOptions options_;
  DofMap dofs_;
  Assembler assembler_;
  StiffnessMatrices K_;
  LinearSolver solver_;
  Timings timings_;
  bool assembled_ = false;
  bool factorized_ = false;        ///< the solver holds a successful factorization ...
  bool factorized_extra_ = false;  ///< ... of K_ff + P (factorize_with) rather than K_ff
  SolveOutcome last_factorization_;
};

/// One-shot convenience: LinearStaticAnalysis(model, options).solve().
LinearStaticResult solve_linear_static(const Model& model, LinearStaticOptions options = {});

}  // namespace cs::solver
