#include "solver/contact/backward_solve_subset.hpp"

#include <algorithm>
#include <stdexcept>

extern "C" {
void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a,
            const int* lda, const double* x, const int* incx, const double* beta, double* y,
            const int* incy);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a,
            const int* lda, double* x, const int* incx);
}

namespace cs::solver {
namespace {

/// The layout of supernode s of a CHOLMOD supernodal factor: columns k1 .. k2 - 1, nsrow rows
/// (the first nscol of them the supernode's own columns), values column-major from px.
struct Supernode {
  int k1, nscol, nsrow;
  const int* rows;   ///< nsrow row indices
  const double* px;  ///< nsrow x nscol values, leading dimension nsrow
};

Supernode supernode(const cholmod_factor& L, int s) {
  const auto* super = static_cast<const int*>(L.super);
  const auto* pi = static_cast<const int*>(L.pi);
  const auto* px = static_cast<const int*>(L.px);
  return {super[s], super[s + 1] - super[s], pi[s + 1] - pi[s],
          static_cast<const int*>(L.s) + pi[s], static_cast<const double*>(L.x) + px[s]};
}

}  // namespace

BackwardSolveSubset::BackwardSolveSubset(const cholmod_factor& L, const std::vector<int>& columns) {
  if (!L.is_super || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT)
    throw std::invalid_argument("BackwardSolveSubset: a real supernodal factor with int indices");
  const int nsuper = static_cast<int>(L.nsuper);
  const auto* super = static_cast<const int*>(L.super);
  std::vector<int> super_of(L.n);
  for (int s = 0; s < nsuper; ++s)
    std::fill(super_of.begin() + super[s], super_of.begin() + super[s + 1], s);
  std::vector<char> wanted(nsuper, 0);
  std::vector<int> stack;
  for (int k : columns) {
    if (k < 0 || k >= static_cast<int>(L.n))
      throw std::invalid_argument("BackwardSolveSubset: a column outside the factor");
    stack.push_back(super_of[k]);
  }
  // Every row below a supernode's own columns is an ancestor: mark them all, transitively.
  while (!stack.empty()) {
    const int s = stack.back();
    stack.pop_back();
    if (wanted[s])
      continue;
    wanted[s] = 1;
    const Supernode sn = supernode(L, s);
    for (int r = sn.nscol; r < sn.nsrow; ++r) {
      if (!wanted[super_of[sn.rows[r]]])
        stack.push_back(super_of[sn.rows[r]]);
    }
  }
  for (int s = nsuper - 1; s >= 0; --s) {
    if (!wanted[s])
      continue;
    supernodes_.push_back(s);
    for (int k = super[s]; k < super[s + 1]; ++k)
      columns_.push_back(k);
  }
  std::sort(columns_.begin(), columns_.end());
}

void BackwardSolveSubset::solve(const cholmod_factor& L, double* x) const {
  const double minus_one = -1.0, one = 1.0;
  const int inc = 1;
  std::vector<double> e;
  for (int s : supernodes_) {
    const Supernode sn = supernode(L, s);
    const int below = sn.nsrow - sn.nscol;
    e.resize(static_cast<std::size_t>(below));
    for (int r = 0; r < below; ++r)
      e[r] = x[sn.rows[sn.nscol + r]];
    double* x1 = x + sn.k1;
    dgemv_("C", &below, &sn.nscol, &minus_one, sn.px + sn.nscol, &sn.nsrow, e.data(), &inc, &one,
           x1, &inc);
    dtrsv_("L", "C", "N", &sn.nscol, sn.px, &sn.nsrow, x1, &inc);
  }
}

}  // namespace cs::solver
