#pragma once
// The dense BLAS-3 / LAPACK kernels of the condensed contact problem, on Eigen column-major
// matrices, calling the system BLAS/LAPACK (OpenBLAS, multithreaded) that CHOLMOD links.
// Eigen's own dense kernels are single-threaded and several times slower on these sizes.

#include <Eigen/Core>

namespace cs::solver::dense {

/// Solves L X = B in place (B := L^{-1} B), L lower triangular with a non-unit diagonal.
void lower_triangular_solve(const Eigen::MatrixXd& L, Eigen::MatrixXd& B);

/// C := Z^T Z (full symmetric result).
void gram(const Eigen::MatrixXd& Z, Eigen::MatrixXd& C);

/// C := L L^T for L lower triangular (its upper part is ignored); full symmetric result.
/// n^3 / 3 flops (LAPACK dlauum on the reversed matrix).
void lower_outer_product(const Eigen::MatrixXd& L, Eigen::MatrixXd& C);

/// Cholesky factorization in place: A (lower triangle read) := L, upper part zeroed. Returns
/// false if A is not positive definite.
bool cholesky_in_place(Eigen::MatrixXd& A);

/// Solves L L^T x = b in place for the Cholesky factor L.
void cholesky_solve(const Eigen::MatrixXd& L, Eigen::VectorXd& b);

/// Reciprocal condition number estimate (1-norm) of L L^T from its Cholesky factor, given the
/// 1-norm of the original matrix.
double cholesky_rcond(const Eigen::MatrixXd& L, double norm1);

/// A symmetric matrix factorized by Cholesky when it is positive definite (the condensed
/// contact systems mostly are: a compliance plus non-negative law terms), else by Bunch-Kaufman
/// LDL^T (dsytrf). Cholesky costs about half as much; both solve A x = b to round-off.
class SymmetricFactorization {
 public:
  /// Factorizes A (its lower triangle is read). Returns false if A is exactly singular.
  bool factorize(const Eigen::MatrixXd& A);
  /// Reciprocal condition number estimate in the 1-norm (0 if exactly singular).
  double rcond() const { return rcond_; }
  /// Whether the Cholesky factorization served (false: LDL^T).
  bool positive_definite() const { return pivots_.size() == 0; }
  /// Solves A x = b in place.
  void solve_in_place(Eigen::VectorXd& b) const;

 private:
  Eigen::MatrixXd factor_;
  Eigen::VectorXi pivots_;  ///< LDL^T's pivots; empty for Cholesky
  double rcond_ = 0.0;
};

}  // namespace cs::solver::dense
