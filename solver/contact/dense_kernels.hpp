#pragma once
// The dense BLAS-3 / LAPACK kernels of the condensed contact problem, on Eigen column-major
// matrices, calling the system BLAS/LAPACK (OpenBLAS, multithreaded) that CHOLMOD links.
// Eigen's own dense kernels are single-threaded and several times slower on these sizes.

#include <vector>

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

/// How a SymmetricFactorization factored its matrix.
enum class SymmetricMethod {
  cholesky,        ///< A = L L^T (A positive definite)
  quasi_definite,  ///< two Cholesky factorizations of a quasi-definite A (below)
  bunch_kaufman,   ///< A = L D L^T with 1x1 and 2x2 pivots (dsytrf), any nonsingular A
};

/// A symmetric matrix factorized by the cheapest of three methods that holds:
///   - Cholesky, where A is positive definite;
///   - quasi-definite: with N the rows of a negative diagonal and P the others,
///       A = [A_PP A_PN; A_NP A_NN],  -A_NN = L_N L_N^T,  C = L_N^{-1} A_NP,
///       A_PP + C^T C = L_S L_S^T,
///     where -A_NN and that Schur complement are positive definite. The condensed contact
///     system is so (an open row's law term is -1 against a compliance rho^{1/2} W rho^{1/2} < I,
///     a closed row's is >= 0), and is indefinite whenever a row is open;
///   - else Bunch-Kaufman LDL^T (dsytrf).
/// Each solves A x = b to round-off. Cholesky costs about half of LDL^T, which on these small
/// matrices also pays a pivot search per column and a slower condition estimate.
class SymmetricFactorization {
 public:
  /// Factorizes A (its lower triangle is read). Returns false if A is exactly singular.
  bool factorize(const Eigen::MatrixXd& A);
  /// Reciprocal condition number estimate in the 1-norm (0 if exactly singular); for the
  /// quasi-definite method the smaller of its two blocks' (A is singular exactly when one of
  /// them is; a block estimate below 1e-10 hands A to LDL^T, whose estimate is A's own).
  double rcond() const { return rcond_; }
  SymmetricMethod method() const { return method_; }
  /// Solves A x = b in place.
  void solve_in_place(Eigen::VectorXd& b) const;

 private:
  bool factorize_quasi_definite(const Eigen::MatrixXd& A, const std::vector<int>& negative);
  bool factorize_bunch_kaufman(const Eigen::MatrixXd& A, double anorm);

  SymmetricMethod method_ = SymmetricMethod::cholesky;
  Eigen::MatrixXd factor_;                ///< L (Cholesky), L_S (quasi-definite) or LDL^T's factor
  Eigen::MatrixXd L_N_, C_;               ///< quasi-definite: L_N and C = L_N^{-1} A_NP
  std::vector<int> positive_, negative_;  ///< quasi-definite: the rows of P and of N
  Eigen::VectorXi pivots_;                ///< LDL^T's pivots
  double rcond_ = 0.0;
};

/// A general square matrix factorized in place by LU with partial pivoting (LAPACK dgetrf),
/// P A = L U, for the frictional contact system, which is not symmetric. The matrix is filled
/// through matrix() and factorized where it lies, so that one workspace serves every iteration.
class GeneralLu {
 public:
  /// The n x n matrix to fill before factorize() (resized, contents unspecified).
  Eigen::MatrixXd& matrix(int n);
  /// Factorizes the matrix in place. Returns false if it is exactly singular.
  bool factorize();
  /// Reciprocal condition number estimate in the 1-norm (0 if exactly singular).
  double rcond() const { return rcond_; }
  /// Solves A^T x = b in place, A the matrix factorized.
  void solve_transposed_in_place(Eigen::VectorXd& b) const;

 private:
  Eigen::MatrixXd lu_;
  Eigen::VectorXi pivots_;
  double rcond_ = 0.0;
};

}  // namespace cs::solver::dense
