#pragma once
// Static condensation of the elastic system onto the contact DOFs, then onto the contact
// constraints: every contact algorithm works on a small dense problem, and one sparse
// factorization serves every discretization and algorithm of a model.
//
// Stage 1, DofCondensation (one per model and contact DOF set c): the reduced elastic system
// K u = f (free DOFs) is split into the contact DOFs c (every DOF a candidate constraint may
// touch) and the rest i. Fixing c clamps every body, so K_ii is positive definite even when
// K is singular (the study's blocks are held vertically by the indenter alone). With a small
// symmetric Delta on c (diag K_cc plus a diagonally dominated chain between consecutive contact
// DOFs; it makes A0 = K + Delta positive definite and changes only the c-c block),
//   S = K_cc - K_ci K_ii^{-1} K_ic   (Schur complement, |c| x |c|, dense, positive semidefinite)
//   f_c = f_c - K_ci K_ii^{-1} f_i   (condensed load)
// and for any u_c the interior u_i = K_ii^{-1} (f_i - K_ic u_c) is one solve with A0.
//   - TrailingFactorBlock: order c last, factor A0 once with CHOLMOD (supernodal LL'); the
//     trailing block of the factor gives S + Delta = L_cc L_cc^T and f_c = L_cc y_c,
//     y = L^{-1} P f. One factorization, one forward solve, dense BLAS-3 on the c block.
//     Ordering (on the node graph, 2 DOFs per vertex): below 2e5 equations constrained AMD
//     (CAMD) with c last, which accounts for the fill c brings, and where its fill is high
//     (CHOLMOD's criterion) also METIS, keeping the cheaper; from 2e5 equations METIS nested
//     dissection of the rest (the FE core's quotient ordering) with c appended. With METIS,
//     ordering c last costs about 20% more factorization flops than the unconstrained ordering
//     on these meshes; CHOLMOD's postorder is kept where it leaves c last.
//     Two sides (from DofCondensationInput::substructure_from interior vertices, with METIS): a
//     vertex separator s of the interior's graph leaves two sides 0 and 1 that no entry of A0
//     couples. The border b = s + c; side k's border b_k is the part of b that an entry couples
//     with side k. Each principal submatrix A0[k+b_k] is positive definite (A0 is) and is
//     condensed onto b_k as above, each side on its own core when one is idle:
//       S_k = A0[b_k,b_k] - A0[b_k,k] A0[k,k]^{-1} A0[k,b_k],
//       S_b = A0_bb + sum_k (S_k - A0[b_k,b_k])   (scattered into b),
//     and the dense Cholesky factor of S_b, s first and c last, has the trailing block L_cc.
//     Both sides' numeric factorizations run at once; the values do not depend on it.
//   - MultipleRightHandSides: factor A0 in the solver's own ordering and solve for the |c| unit
//     columns: S + Delta = ((A0^{-1})_cc)^{-1}. The simple reference (memory n x |c|).
//
// Stage 2, ConstraintCondensation (one per constraint row set): the m rows g = g0 + B u, forces
// lambda (S u_c = f_c + B^T lambda). With R = diag(rho) > 0 (rho = the rows' stiffness scale),
// M = S + B^T R B is positive definite when the candidate rows hold every body the prescribed
// DOFs leave free, and M u_c = f_c + B^T (lambda + R B u_c) gives, with mu = lambda + R(g - g0):
//   u_c = M^{-1} (f_c + B^T mu),   g - g0 = d + W mu,   W = B M^{-1} B^T,   d = B M^{-1} f_c:
// an exact rewriting (R changes nothing in the answer) on which the active-set loop runs
// (solver/contact/active_set_solver.hpp).

#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solver/contact/contact_options.hpp"
#include "solver/linear_solver.hpp"
#include "solver/solve_status.hpp"

namespace cs::solver {

class BackwardSolveSubset;

/// The equations of the free displacement a caller reads (DofCondensation::subset): recover()
/// with it gives only those entries (and the contact DOFs').
struct RecoverySubset {
  std::shared_ptr<const BackwardSolveSubset> backward;  ///< one factor's backward solve
  std::vector<RecoverySubset> sides;  ///< or each side's, when the sides were factored apart
  std::vector<int> equations;         ///< the entries given, increasing
  /// Whether recover() with it gives the whole field (nothing to prune).
  bool whole_field() const { return !backward && sides.empty(); }
};

/// Wall-clock seconds of the condensation's phases. Where the two sides of a separator are
/// factored at once, a phase counts the longer side's time.
struct CondensationTimings {
  double assemble_s = 0.0;   ///< A0 = K + D, the node graph
  double analyze_s = 0.0;    ///< fill-reducing ordering and symbolic factorization
  double factorize_s = 0.0;  ///< numeric factorization of A0
  double condense_s = 0.0;   ///< S and f_c from the factor (dense BLAS-3)
  double total() const { return assemble_s + analyze_s + factorize_s + condense_s; }
};

/// The interior vertices from which DofCondensationInput's default condenses two sides apart.
/// Condensing a side onto its border factors and multiplies out the border's dense block, so the
/// sides cost about 4 b^3 / 3 flops more than one factor (b: a side's border, separator and
/// contact DOFs; 2.9e10 on S(1/7) F Q8, b = 2,783, against 2.0e11 for the factorization): worth
/// it only where the sparse factorization dominates, the largest models.
inline constexpr int kSubstructureFrom = 500'000;

/// What stage 1 reads. The references must outlive DofCondensation::compute.
struct DofCondensationInput {
  const Eigen::SparseMatrix<double>& K_lower;  ///< K (n x n), lower triangle, CSC, sorted rows
  const Eigen::VectorXd& f;                    ///< load (n)
  const std::vector<int>& contact_dofs;        ///< c: equation indices, increasing, unique
  /// Optional: the node of every equation (size n), so that the ordering runs on the node
  /// graph (half the vertices, a quarter of the edges); empty: the DOF graph.
  const std::vector<int>& node_of_equation;
  /// TrailingFactorBlock's ordering: CholmodDefault = the policy below (CAMD, METIS if its fill
  /// is high; METIS from 2e5 equations); Amd = CAMD only; Metis = METIS only.
  FillReducingOrdering ordering = FillReducingOrdering::CholmodDefault;
  /// TrailingFactorBlock with a METIS ordering, from this many vertices of the interior's graph
  /// on: the two sides of a vertex separator are condensed apart, each onto the separator and c
  /// (at once when a spare core is idle, spare_cores.hpp), and the separator is then eliminated
  /// from the sum in a dense block. The values are the same on one core or two.
  int substructure_from = kSubstructureFrom;
  /// false: K is positive definite as given (a side of a larger A0) and Delta is zero.
  bool hold_contact_dofs = true;
};

/// Stage 1: the elastic system condensed onto the contact DOFs.
class DofCondensation {
 public:
  explicit DofCondensation(CondensationMethod method = CondensationMethod::TrailingFactorBlock);
  ~DofCondensation();
  DofCondensation(DofCondensation&&) noexcept;
  DofCondensation& operator=(DofCondensation&&) noexcept;
  DofCondensation(const DofCondensation&) = delete;
  DofCondensation& operator=(const DofCondensation&) = delete;

  /// Factorizes A0 and computes S and f_c. Returns Ok, or NotPositiveDefinite / Singular (K_ii
  /// is not positive definite: a body is held neither by prescribed DOFs nor by the contact
  /// DOFs) or SolverFailure, with a reason.
  SolveOutcome compute(const DofCondensationInput& input);

  /// Replaces the load f (same matrix): recomputes f_c with one forward solve. For a changed
  /// load case or changed prescribed displacements (f = f_f - K_fc u_c).
  void update_load(const Eigen::VectorXd& f);

  /// The contact DOFs (equation indices), in the order of S's rows.
  const std::vector<int>& contact_dofs() const { return contact_dofs_; }
  /// Position of equation `eq` among the contact DOFs, or -1.
  int position(int eq) const { return position_[eq]; }
  /// S (|c| x |c|).
  const Eigen::MatrixXd& schur() const { return S_; }
  /// f_c (|c|).
  const Eigen::VectorXd& condensed_load() const { return f_c_; }
  /// The free displacement with contact part u_c and the interior in equilibrium.
  Eigen::VectorXd recover(const Eigen::VectorXd& u_c) const;
  /// The subset of recover() that gives the entries of `equations` (free equation indices) and
  /// of the contact DOFs: the backward solve visits only the factor's supernodes those entries
  /// need (solver/contact/backward_solve_subset.hpp), on each side's factor where the sides
  /// were factored apart. The reference method gives the whole field (whole_field()).
  RecoverySubset subset(const std::vector<int>& equations) const;
  /// recover(u_c) at subset.equations only, bit for bit; the other entries are NaN. With a
  /// subset.whole_field(), recover(u_c).
  Eigen::VectorXd recover(const Eigen::VectorXd& u_c, const RecoverySubset& subset) const;

  int n_contact_dofs() const { return static_cast<int>(contact_dofs_.size()); }
  double factor_nonzeros() const { return factor_nnz_; }
  /// Flop count of the numeric factorization (CHOLMOD's estimate).
  double factor_flops() const { return factor_flops_; }
  const CondensationTimings& timings() const { return timings_; }
  CondensationMethod method() const { return method_; }

 private:
  struct Impl;
  struct Sides;
  SolveOutcome compute_reference(const Eigen::SparseMatrix<double>& A0);
  SolveOutcome compute_trailing(const Eigen::SparseMatrix<double>& A0,
                                const DofCondensationInput& in,
                                const std::vector<char>& is_contact);
  SolveOutcome compute_sides(const Eigen::SparseMatrix<double>& A0, const DofCondensationInput& in,
                             const std::vector<char>& is_contact);
  /// S = L_tail L_tail^T - Delta, from the trailing block L_tail_ (tail_position_'s order).
  void schur_from_tail();
  /// Two sides: f_c from the sides' condensed loads of the load impl_->f.
  void condense_sides_load();
  /// Two sides: the border's values (separator, then c) for contact values u_c.
  Eigen::VectorXd border_values(const Eigen::VectorXd& u_c) const;

  CondensationMethod method_;
  std::unique_ptr<Impl> impl_;
  std::vector<int> contact_dofs_;
  std::vector<int> position_;
  Eigen::MatrixXd S_;
  Eigen::VectorXd f_c_;
  Eigen::VectorXd delta_d_;  ///< Delta on c: diagonal (see condensation.cpp)
  Eigen::VectorXd delta_e_;  ///< Delta on c: chain between consecutive contact DOFs
  /// Delta u_c.
  Eigen::VectorXd delta_times(const Eigen::VectorXd& u_c) const;
  /// Trailing-block path: the y of L^T (P x) = y whose solution has x_c = u_c.
  Eigen::VectorXd backward_right_side(const Eigen::VectorXd& u_c) const;
  /// S -= Delta.
  void subtract_delta();
  Eigen::MatrixXd L_tail_;          ///< trailing factor block, in the factor's tail order
  std::vector<int> tail_position_;  ///< tail order -> index in contact_dofs_
  double factor_nnz_ = 0.0;
  double factor_flops_ = 0.0;
  CondensationTimings timings_;
};

/// Stage 2: the condensed problem on the constraint rows.
class ConstraintCondensation {
 public:
  /// B: m x n_free (columns among dofs.contact_dofs()), rho: m, > 0. Returns Ok, or
  /// NotPositiveDefinite with a reason (the rows do not hold a body K leaves free).
  SolveOutcome compute(const DofCondensation& dofs,
                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& B,
                       const Eigen::VectorXd& rho);

  /// W = B M^{-1} B^T (m x m, symmetric positive semidefinite).
  const Eigen::MatrixXd& W() const { return W_; }
  /// d = B M^{-1} f_c (m).
  const Eigen::VectorXd& d() const { return d_; }
  /// Recomputes d after DofCondensation::update_load.
  void update_load(const DofCondensation& dofs);
  /// The free displacement for the condensed unknowns mu (via stage 1's recovery), at
  /// `subset`'s equations only when it is given (DofCondensation::recover).
  Eigen::VectorXd recover(const DofCondensation& dofs, const Eigen::VectorXd& mu,
                          const RecoverySubset* subset = nullptr) const;
  double condense_seconds() const { return seconds_; }

 private:
  Eigen::MatrixXd L_;   ///< Cholesky factor of M (lower)
  Eigen::MatrixXd Bt_;  ///< B^T on the contact DOFs (|c| x m), dense
  Eigen::MatrixXd W_;
  Eigen::VectorXd d_;
  double seconds_ = 0.0;
};

}  // namespace cs::solver
