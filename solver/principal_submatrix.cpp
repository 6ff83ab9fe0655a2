#include "solver/principal_submatrix.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

namespace cs::solver {

Eigen::SparseMatrix<double> principal_lower(const Eigen::SparseMatrix<double>& A_lower,
                                            const std::vector<int>& global) {
  const int m = static_cast<int>(global.size());
  std::vector<int> local(A_lower.rows(), -1);
  for (int l = 0; l < m; ++l)
    local[global[l]] = l;
  // Each entry goes under its smaller local index; a column's rows are then sorted in place.
  Eigen::SparseMatrix<double> out(m, m);
  std::vector<int> count(m, 0);
  for (int l = 0; l < m; ++l) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A_lower, global[l]); it; ++it) {
      const int r = local[it.row()];
      if (r >= 0)
        ++count[std::min(r, l)];
    }
  }
  out.reserve(count);
  for (int l = 0; l < m; ++l) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(A_lower, global[l]); it; ++it) {
      const int r = local[it.row()];
      if (r >= 0)
        out.insertBackUncompressed(std::max(r, l), std::min(r, l)) = it.value();
    }
  }
  out.makeCompressed();
  std::vector<std::pair<int, double>> column;
  for (int j = 0; j < m; ++j) {
    int* rows = out.innerIndexPtr() + out.outerIndexPtr()[j];
    double* values = out.valuePtr() + out.outerIndexPtr()[j];
    const int size = out.outerIndexPtr()[j + 1] - out.outerIndexPtr()[j];
    if (std::is_sorted(rows, rows + size))
      continue;
    column.clear();
    for (int k = 0; k < size; ++k)
      column.emplace_back(rows[k], values[k]);
    std::sort(column.begin(), column.end());
    for (int k = 0; k < size; ++k)
      std::tie(rows[k], values[k]) = column[k];
  }
  return out;
}

}  // namespace cs::solver
