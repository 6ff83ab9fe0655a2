#include "solver/contact/dense_kernels.hpp"

#include <algorithm>
#include <vector>

extern "C" {
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* beta, double* c, const int* ldc);
void dsytrf_(const char* uplo, const int* n, double* a, const int* lda, int* ipiv, double* work,
             const int* lwork, int* info);
void dsytrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda,
             const int* ipiv, double* b, const int* ldb, int* info);
void dsycon_(const char* uplo, const int* n, const double* a, const int* lda, const int* ipiv,
             const double* anorm, double* rcond, double* work, int* iwork, int* info);
void dlauum_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dpotrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda,
             double* b, const int* ldb, int* info);
void dpocon_(const char* uplo, const int* n, const double* a, const int* lda, const double* anorm,
             double* rcond, double* work, int* iwork, int* info);
double dlansy_(const char* norm, const char* uplo, const int* n, const double* a, const int* lda,
               double* work);
}

namespace cs::solver::dense {

void lower_triangular_solve(const Eigen::MatrixXd& L, Eigen::MatrixXd& B) {
  const int m = static_cast<int>(B.rows());
  const int n = static_cast<int>(B.cols());
  if (m == 0 || n == 0)
    return;
  const double one = 1.0;
  const int lda = static_cast<int>(L.outerStride());
  const int ldb = static_cast<int>(B.outerStride());
  dtrsm_("L", "L", "N", "N", &m, &n, &one, L.data(), &lda, B.data(), &ldb);
}

void gram(const Eigen::MatrixXd& Z, Eigen::MatrixXd& C) {
  const int n = static_cast<int>(Z.cols());
  const int k = static_cast<int>(Z.rows());
  C.setZero(n, n);
  if (n == 0 || k == 0)
    return;
  const double one = 1.0;
  const double zero = 0.0;
  const int lda = static_cast<int>(Z.outerStride());
  const int ldc = static_cast<int>(C.outerStride());
  dsyrk_("L", "T", &n, &k, &one, Z.data(), &lda, &zero, C.data(), &ldc);
  C.triangularView<Eigen::StrictlyUpper>() = C.transpose();
}

void lower_outer_product(const Eigen::MatrixXd& L, Eigen::MatrixXd& C) {
  const int n = static_cast<int>(L.rows());
  // U = J L J (J the reversal) is upper triangular and L L^T = J (U U^T) J.
  C = L.reverse();
  C.triangularView<Eigen::StrictlyLower>().setZero();
  if (n > 0) {
    int info = 0;
    dlauum_("U", &n, C.data(), &n, &info);
  }
  C.triangularView<Eigen::StrictlyLower>() = C.transpose();
  C = C.reverse().eval();
}

bool cholesky_in_place(Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  if (n == 0)
    return true;
  int info = 0;
  dpotrf_("L", &n, A.data(), &n, &info);
  A.triangularView<Eigen::StrictlyUpper>().setZero();
  return info == 0;
}

void cholesky_solve(const Eigen::MatrixXd& L, Eigen::VectorXd& b) {
  const int n = static_cast<int>(L.rows());
  if (n == 0)
    return;
  const int nrhs = 1;
  int info = 0;
  dpotrs_("L", &n, &nrhs, L.data(), &n, b.data(), &n, &info);
}

double cholesky_rcond(const Eigen::MatrixXd& L, double norm1) {
  const int n = static_cast<int>(L.rows());
  if (n == 0)
    return 1.0;
  double rcond = 0.0;
  std::vector<double> work(3 * n);
  std::vector<int> iwork(n);
  int info = 0;
  dpocon_("L", &n, L.data(), &n, &norm1, &rcond, work.data(), iwork.data(), &info);
  return rcond;
}

bool SymmetricFactorization::factorize(const Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  pivots_.resize(0);
  rcond_ = 0.0;
  if (n == 0) {
    factor_.resize(0, 0);
    rcond_ = 1.0;
    return true;
  }
  std::vector<double> norm_work(n);
  const double anorm = dlansy_("1", "L", &n, A.data(), &n, norm_work.data());
  factor_ = A;
  if (cholesky_in_place(factor_)) {
    rcond_ = cholesky_rcond(factor_, anorm);
    return true;
  }
  factor_ = A;
  pivots_.resize(n);
  int info = 0;
  int lwork = -1;
  double query = 0.0;
  dsytrf_("L", &n, factor_.data(), &n, pivots_.data(), &query, &lwork, &info);
  lwork = std::max(1, static_cast<int>(query));
  std::vector<double> work(lwork);
  dsytrf_("L", &n, factor_.data(), &n, pivots_.data(), work.data(), &lwork, &info);
  if (info != 0)
    return false;
  std::vector<double> con_work(2 * n);
  std::vector<int> iwork(n);
  dsycon_("L", &n, factor_.data(), &n, pivots_.data(), &anorm, &rcond_, con_work.data(),
          iwork.data(), &info);
  return info == 0;
}

void SymmetricFactorization::solve_in_place(Eigen::VectorXd& b) const {
  const int n = static_cast<int>(factor_.rows());
  if (n == 0)
    return;
  if (positive_definite()) {
    cholesky_solve(factor_, b);
    return;
  }
  const int nrhs = 1;
  int info = 0;
  dsytrs_("L", &n, &nrhs, factor_.data(), &n, pivots_.data(), b.data(), &n, &info);
}

}  // namespace cs::solver::dense
