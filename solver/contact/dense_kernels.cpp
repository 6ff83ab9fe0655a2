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
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda,
             const int* ipiv, double* b, const int* ldb, int* info);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm,
             double* rcond, double* work, int* iwork, int* info);
double dlange_(const char* norm, const int* m, const int* n, const double* a, const int* lda,
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

namespace {

/// Below this a block's reciprocal condition estimate does not stand for A's (the block can be
/// near singular where A is not): LDL^T decides.
constexpr double kBlockRcondFloor = 1e-10;

double norm1_lower(const Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  std::vector<double> work(n);
  return n == 0 ? 0.0 : dlansy_("1", "L", &n, A.data(), &n, work.data());
}

/// The submatrix of A's rows `r` and columns `c` (A's lower triangle read, symmetric).
Eigen::MatrixXd block(const Eigen::MatrixXd& A, const std::vector<int>& r,
                      const std::vector<int>& c) {
  Eigen::MatrixXd out(r.size(), c.size());
  for (std::size_t j = 0; j < c.size(); ++j) {
    for (std::size_t i = 0; i < r.size(); ++i)
      out(i, j) = r[i] >= c[j] ? A(r[i], c[j]) : A(c[j], r[i]);
  }
  return out;
}

}  // namespace

bool SymmetricFactorization::factorize(const Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  pivots_.resize(0);
  positive_.clear();
  negative_.clear();
  rcond_ = 0.0;
  method_ = SymmetricMethod::cholesky;
  if (n == 0) {
    factor_.resize(0, 0);
    rcond_ = 1.0;
    return true;
  }
  const double anorm = norm1_lower(A);
  std::vector<int> negative;
  for (int j = 0; j < n; ++j) {
    if (A(j, j) < 0.0)
      negative.push_back(j);
  }
  if (negative.empty()) {
    factor_ = A;
    if (cholesky_in_place(factor_)) {
      rcond_ = cholesky_rcond(factor_, anorm);
      return true;
    }
  } else if (factorize_quasi_definite(A, negative)) {
    return true;
  }
  return factorize_bunch_kaufman(A, anorm);
}

bool SymmetricFactorization::factorize_quasi_definite(const Eigen::MatrixXd& A,
                                                      const std::vector<int>& negative) {
  std::vector<int> positive;
  for (int j = 0, k = 0; j < static_cast<int>(A.rows()); ++j) {
    if (k < static_cast<int>(negative.size()) && negative[k] == j)
      ++k;
    else
      positive.push_back(j);
  }
  L_N_ = -block(A, negative, negative);
  const double norm_N = norm1_lower(L_N_);
  if (!cholesky_in_place(L_N_))
    return false;
  const double rcond_N = cholesky_rcond(L_N_, norm_N);
  C_ = block(A, negative, positive);
  lower_triangular_solve(L_N_, C_);
  Eigen::MatrixXd CtC;
  gram(C_, CtC);
  factor_ = block(A, positive, positive) + CtC;
  const double norm_S = norm1_lower(factor_);
  if (!cholesky_in_place(factor_))
    return false;
  const double rcond_S = cholesky_rcond(factor_, norm_S);
  if (!(std::min(rcond_N, rcond_S) > kBlockRcondFloor))
    return false;
  rcond_ = std::min(rcond_N, rcond_S);
  positive_ = std::move(positive);
  negative_ = negative;
  method_ = SymmetricMethod::quasi_definite;
  return true;
}

bool SymmetricFactorization::factorize_bunch_kaufman(const Eigen::MatrixXd& A, double anorm) {
  const int n = static_cast<int>(A.rows());
  method_ = SymmetricMethod::bunch_kaufman;
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
  switch (method_) {
    case SymmetricMethod::cholesky:
      cholesky_solve(factor_, b);
      return;
    case SymmetricMethod::quasi_definite: {
      // y_N = L_N^{-1} b_N;  L_S L_S^T x_P = b_P + C^T y_N;  x_N = L_N^{-T} (C x_P - y_N).
      Eigen::MatrixXd y_N(negative_.size(), 1);
      for (std::size_t k = 0; k < negative_.size(); ++k)
        y_N(k, 0) = b[negative_[k]];
      lower_triangular_solve(L_N_, y_N);
      Eigen::VectorXd x_P(positive_.size());
      for (std::size_t k = 0; k < positive_.size(); ++k)
        x_P[k] = b[positive_[k]];
      x_P.noalias() += C_.transpose() * y_N.col(0);
      cholesky_solve(factor_, x_P);
      Eigen::VectorXd x_N = C_ * x_P - y_N.col(0);
      L_N_.triangularView<Eigen::Lower>().transpose().solveInPlace(x_N);
      for (std::size_t k = 0; k < positive_.size(); ++k)
        b[positive_[k]] = x_P[k];
      for (std::size_t k = 0; k < negative_.size(); ++k)
        b[negative_[k]] = x_N[k];
      return;
    }
    case SymmetricMethod::bunch_kaufman: {
      const int nrhs = 1;
      int info = 0;
      dsytrs_("L", &n, &nrhs, factor_.data(), &n, pivots_.data(), b.data(), &n, &info);
      return;
    }
  }
}

Eigen::MatrixXd& GeneralLu::matrix(int n) {
  lu_.resize(n, n);
  return lu_;
}

bool GeneralLu::factorize() {
  const int n = static_cast<int>(lu_.rows());
  rcond_ = 0.0;
  pivots_.resize(n);
  if (n == 0) {
    rcond_ = 1.0;
    return true;
  }
  const double anorm = dlange_("1", &n, &n, lu_.data(), &n, nullptr);  // no work for "1"
  int info = 0;
  dgetrf_(&n, &n, lu_.data(), &n, pivots_.data(), &info);
  if (info != 0)
    return false;
  std::vector<double> work(4 * n);
  std::vector<int> iwork(n);
  dgecon_("1", &n, lu_.data(), &n, &anorm, &rcond_, work.data(), iwork.data(), &info);
  return info == 0;
}

void GeneralLu::solve_transposed_in_place(Eigen::VectorXd& b) const {
  const int n = static_cast<int>(lu_.rows());
  if (n == 0)
    return;
  const int nrhs = 1;
  int info = 0;
  dgetrs_("T", &n, &nrhs, lu_.data(), &n, pivots_.data(), b.data(), &n, &info);
}

}  // namespace cs::solver::dense
