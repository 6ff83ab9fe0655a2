#include "solver/sparse_sum.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace cs::solver {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// A column of a CSC matrix: its rows and values, [begin, end).
struct Column {
  const int* row;
  const double* value;
  int size;
};

Column column(const SparseMatrix& A, int j) {
  const int begin = A.outerIndexPtr()[j];
  const int end = A.isCompressed() ? A.outerIndexPtr()[j + 1] : begin + A.innerNonZeroPtr()[j];
  return {A.innerIndexPtr() + begin, A.valuePtr() + begin, end - begin};
}

/// The entries of the union of two columns' rows.
int union_size(const Column& a, const Column& b) {
  int n = 0;
  for (int p = 0, q = 0; p < a.size || q < b.size; ++n) {
    if (q == b.size || (p < a.size && a.row[p] < b.row[q]))
      ++p;
    else if (p == a.size || b.row[q] < a.row[p])
      ++q;
    else
      ++p, ++q;
  }
  return n;
}

/// Writes the merged column a + b at `row`, `value`.
void merge(const Column& a, const Column& b, int* row, double* value) {
  for (int p = 0, q = 0; p < a.size || q < b.size; ++row, ++value) {
    if (q == b.size || (p < a.size && a.row[p] < b.row[q])) {
      *row = a.row[p];
      *value = a.value[p++] + 0.0;
    } else if (p == a.size || b.row[q] < a.row[p]) {
      *row = b.row[q];
      *value = 0.0 + b.value[q++];
    } else {
      *row = a.row[p];
      *value = a.value[p++] + b.value[q++];
    }
  }
}

}  // namespace

SparseMatrix sparse_sum(const SparseMatrix& K, const SparseMatrix& D) {
  if (K.rows() != D.rows() || K.cols() != D.cols()) {
    throw std::invalid_argument(fmt::format("sparse_sum: a {} x {} matrix and a {} x {} one",
                                            K.rows(), K.cols(), D.rows(), D.cols()));
  }
  const int n = static_cast<int>(K.cols());
  std::vector<int> start(n + 1, 0);
  for (int j = 0; j < n; ++j) {
    const Column k = column(K, j), d = column(D, j);
    start[j + 1] = start[j] + (d.size == 0 ? k.size : union_size(k, d));
  }
  SparseMatrix S(K.rows(), K.cols());
  S.resizeNonZeros(start[n]);
  std::copy(start.begin(), start.end(), S.outerIndexPtr());
  int* rows = S.innerIndexPtr();
  double* values = S.valuePtr();
  for (int j = 0; j < n; ++j) {
    const Column k = column(K, j), d = column(D, j);
    if (d.size == 0) {
      std::copy(k.row, k.row + k.size, rows + start[j]);
      std::transform(k.value, k.value + k.size, values + start[j],
                     [](double v) { return v + 0.0; });
    } else {
      merge(k, d, rows + start[j], values + start[j]);
    }
  }
  return S;
}

}  // namespace cs::solver
