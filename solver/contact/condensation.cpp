#include "solver/contact/condensation.hpp"

#include <algorithm>
#include <cstdio>
#include <chrono>
#include <optional>
#include <vector>

#include <cholmod.h>
#include <fmt/format.h>
#include <Eigen/Cholesky>

#include "solver/contact/dense_kernels.hpp"
#include "solver/linear_solver.hpp"

namespace cs::solver {

namespace {

using Clock = std::chrono::steady_clock;
using RowMajorSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A CHOLMOD view (no copy) of an Eigen lower-triangular CSC matrix.
cholmod_sparse view_lower(const Eigen::SparseMatrix<double>& A) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

/// A CHOLMOD view (no copy) of a vector.
cholmod_dense view_vector(const Eigen::VectorXd& v) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(v.size());
  d.ncol = 1;
  d.nzmax = static_cast<size_t>(v.size());
  d.d = static_cast<size_t>(v.size());
  d.x = const_cast<double*>(v.data());
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

/// A0 = K + D on the contact DOFs (a copy of K with its diagonal raised there).
Eigen::SparseMatrix<double> raised_matrix(const Eigen::SparseMatrix<double>& K,
                                          const std::vector<int>& contact_dofs,
                                          Eigen::VectorXd& D) {
  Eigen::SparseMatrix<double> A0 = K;
  D.resize(static_cast<Eigen::Index>(contact_dofs.size()));
  for (std::size_t k = 0; k < contact_dofs.size(); ++k) {
    const int j = contact_dofs[k];
    double& diag = A0.coeffRef(j, j);  // the first entry of a sorted lower column
    D[static_cast<Eigen::Index>(k)] = diag > 0.0 ? diag : 1.0;
    diag += D[static_cast<Eigen::Index>(k)];
  }
  A0.makeCompressed();
  return A0;
}

/// The lower-triangular pattern of the graph whose vertices are the nodes with interior DOFs
/// (or the interior DOFs themselves), from the lower pattern of A. vertex_of[eq] is the vertex
/// of an interior equation, -1 for a contact equation.
Eigen::SparseMatrix<double> interior_graph(const Eigen::SparseMatrix<double>& A,
                                           const std::vector<int>& vertex_of, int n_vertices) {
  std::vector<std::vector<int>> dofs_of(n_vertices);
  for (int eq = 0; eq < static_cast<int>(vertex_of.size()); ++eq) {
    if (vertex_of[eq] >= 0)
      dofs_of[vertex_of[eq]].push_back(eq);
  }
  std::vector<int> outer(n_vertices + 1, 0), inner, mark(n_vertices, -1);
  inner.reserve(static_cast<size_t>(A.nonZeros() / 3));
  for (int v = 0; v < n_vertices; ++v) {
    mark[v] = v;
    inner.push_back(v);  // the diagonal
    for (int eq : dofs_of[v]) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, eq); it; ++it) {
        const int w = vertex_of[it.row()];
        if (w > v && mark[w] != v) {
          mark[w] = v;
          inner.push_back(w);
        }
      }
    }
    std::sort(inner.begin() + outer[v], inner.end());
    outer[v + 1] = static_cast<int>(inner.size());
  }
  std::vector<double> values(inner.size(), 1.0);
  return Eigen::Map<Eigen::SparseMatrix<double>>(n_vertices, n_vertices,
                                                 static_cast<Eigen::Index>(inner.size()),
                                                 outer.data(), inner.data(), values.data());
}

}  // namespace

struct DofCondensation::Impl {
  // Trailing-block path: CHOLMOD directly (given permutation, access to the factor's blocks).
  cholmod_common common{};
  cholmod_factor* L = nullptr;
  bool started = false;
  // Reference path: the FE core's linear solver.
  std::optional<LinearSolver> solver;
  Eigen::VectorXd f;

  ~Impl() {
    if (started) {
      if (L != nullptr)
        cholmod_free_factor(&L, &common);
      cholmod_finish(&common);
    }
  }

  void start() {
    if (!started) {
      cholmod_start(&common);
      started = true;
    }
  }

  /// x = A0^{-1} b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) {
    if (solver)
      return solver->solve(b);
    cholmod_dense bv = view_vector(b);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, L, &bv, &common);
    Eigen::VectorXd out = Eigen::Map<Eigen::VectorXd>(static_cast<double*>(x->x), b.size());
    cholmod_free_dense(&x, &common);
    return out;
  }

  /// Orders the interior by METIS on its (node) graph, then the contact DOFs.
  SolveOutcome order(const Eigen::SparseMatrix<double>& A0, const DofCondensationInput& in,
                     const std::vector<char>& is_contact, std::vector<int>& perm) {
    const int n = static_cast<int>(A0.rows());
    const bool by_node = static_cast<int>(in.node_of_equation.size()) == n;
    std::vector<int> vertex_of(n, -1), first_dof_of_vertex;
    std::vector<int> vertex_of_node;
    int n_vertices = 0;
    for (int eq = 0; eq < n; ++eq) {
      if (is_contact[eq])
        continue;
      if (by_node) {
        const int node = in.node_of_equation[eq];
        if (node >= static_cast<int>(vertex_of_node.size()))
          vertex_of_node.resize(node + 1, -1);
        if (vertex_of_node[node] < 0)
          vertex_of_node[node] = n_vertices++;
        vertex_of[eq] = vertex_of_node[node];
      } else {
        vertex_of[eq] = n_vertices++;
      }
    }
    perm.clear();
    perm.reserve(n);
    if (n_vertices > 0) {
      const Eigen::SparseMatrix<double> G = interior_graph(A0, vertex_of, n_vertices);
      cholmod_sparse Gv = view_lower(G);
      std::vector<int> vperm(n_vertices);
      if (!cholmod_metis(&Gv, nullptr, 0, 0, vperm.data(), &common)) {
        return {SolveStatus::SolverFailure,
                fmt::format("METIS ordering failed (CHOLMOD status {})", common.status)};
      }
      std::vector<std::vector<int>> dofs_of(n_vertices);
      for (int eq = 0; eq < n; ++eq) {
        if (vertex_of[eq] >= 0)
          dofs_of[vertex_of[eq]].push_back(eq);
      }
      for (int k = 0; k < n_vertices; ++k) {
        for (int eq : dofs_of[vperm[k]])
          perm.push_back(eq);
      }
    }
    for (int eq : in.contact_dofs)
      perm.push_back(eq);
    return {SolveStatus::Ok, ""};
  }

  /// Symbolic analysis with the given order; CHOLMOD's postorder is kept if it leaves the contact
  /// DOFs last (it does when their Schur complement is connected), else dropped.
  bool analyze(cholmod_sparse* A, std::vector<int>& perm, int nc) {
    for (int postorder : {1, 0}) {
      if (L != nullptr)
        cholmod_free_factor(&L, &common);
      common.nmethods = 1;
      common.method[0].ordering = CHOLMOD_GIVEN;
      common.postorder = postorder;
      common.supernodal = CHOLMOD_SUPERNODAL;
      L = cholmod_analyze_p(A, perm.data(), nullptr, 0, &common);
      if (L == nullptr)
        return false;
      const int n = static_cast<int>(L->n);
      const int* P = static_cast<const int*>(L->Perm);
      std::vector<char> tail(n, 0);
      for (int k = n - nc; k < n; ++k)
        tail[perm[k]] = 1;
      bool last = true;
      for (int k = n - nc; k < n && last; ++k)
        last = tail[P[k]] != 0;
      if (last)
        return true;
    }
    return false;
  }
};

DofCondensation::DofCondensation(CondensationMethod method)
    : method_(method), impl_(std::make_unique<Impl>()) {}
DofCondensation::~DofCondensation() = default;
DofCondensation::DofCondensation(DofCondensation&&) noexcept = default;
DofCondensation& DofCondensation::operator=(DofCondensation&&) noexcept = default;

SolveOutcome DofCondensation::compute(const DofCondensationInput& in) {
  timings_ = {};
  const int n = static_cast<int>(in.K_lower.rows());
  contact_dofs_ = in.contact_dofs;
  const int nc = static_cast<int>(contact_dofs_.size());
  position_.assign(n, -1);
  std::vector<char> is_contact(n, 0);
  for (int k = 0; k < nc; ++k) {
    position_[contact_dofs_[k]] = k;
    is_contact[contact_dofs_[k]] = 1;
  }
  Impl& im = *impl_;
  im.f = in.f;
  auto start = Clock::now();
  const Eigen::SparseMatrix<double> A0 = raised_matrix(in.K_lower, contact_dofs_, D_);
  timings_.assemble_s = seconds_since(start);

  if (method_ == CondensationMethod::MultipleRightHandSides) {
    im.solver.emplace();
    start = Clock::now();
    SolveOutcome out = im.solver->analyze(A0);
    timings_.analyze_s = seconds_since(start);
    if (!out.ok())
      return out;
    start = Clock::now();
    out = im.solver->factorize(A0);
    timings_.factorize_s = seconds_since(start);
    if (!out.ok()) {
      out.reason = "the elastic stiffness with the contact DOFs held: " + out.reason;
      return out;
    }
    factor_nnz_ = im.solver->info().nnz_factor;
    factor_flops_ = im.solver->info().flops;
    start = Clock::now();
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, nc);
    for (int k = 0; k < nc; ++k)
      E(contact_dofs_[k], k) = 1.0;
    const Eigen::MatrixXd X = im.solver->solve(E);  // A0^{-1} E_c
    Eigen::MatrixXd Xcc(nc, nc);
    for (int k = 0; k < nc; ++k)
      Xcc.row(k) = X.row(contact_dofs_[k]);
    Xcc = 0.5 * (Xcc + Xcc.transpose()).eval();
    const Eigen::MatrixXd SD = Xcc.llt().solve(Eigen::MatrixXd::Identity(nc, nc));  // S + D
    S_ = SD;
    S_.diagonal() -= D_;
    update_load(in.f);
    timings_.condense_s = seconds_since(start);
    return {SolveStatus::Ok, ""};
  }

  // Trailing-block path.
  im.start();
  cholmod_common& c = im.common;
  start = Clock::now();
  std::vector<int> perm;
  SolveOutcome ordered = im.order(A0, in, is_contact, perm);
  if (!ordered.ok())
    return ordered;
  cholmod_sparse A0_view = view_lower(A0);
  const bool analyzed = im.analyze(&A0_view, perm, nc);
  timings_.analyze_s = seconds_since(start);
  if (!analyzed || c.status < CHOLMOD_OK) {
    return {SolveStatus::SolverFailure,
            fmt::format("CHOLMOD symbolic analysis failed (status {})", c.status)};
  }
  start = Clock::now();
  cholmod_factorize(&A0_view, im.L, &c);
  timings_.factorize_s = seconds_since(start);
  factor_nnz_ = c.lnz;
  factor_flops_ = c.fl;
  if (c.status < CHOLMOD_OK && c.status != CHOLMOD_NOT_POSDEF) {
    return {SolveStatus::SolverFailure,
            fmt::format("CHOLMOD factorization failed (status {})", c.status)};
  }
  const int* P = static_cast<const int*>(im.L->Perm);
  if (im.L->minor < im.L->n) {
    SolveOutcome out{SolveStatus::NotPositiveDefinite,
                     fmt::format("the elastic stiffness with the contact DOFs held is not positive "
                                 "definite (pivot at equation {}): a body is held neither by "
                                 "prescribed displacements nor by its contact surface",
                                 P[im.L->minor])};
    out.failed_equation = P[im.L->minor];
    return out;
  }
  const double rcond = cholmod_rcond(im.L, &c);
  if (!(rcond > 1e-15)) {
    return {SolveStatus::Singular,
            fmt::format("the elastic stiffness with the contact DOFs held is numerically singular "
                        "(pivot ratio {:.3g}): a body is held neither by prescribed displacements "
                        "nor by its contact surface",
                        rcond)};
  }

  start = Clock::now();
  // The trailing block of the factor, in the order of P's tail; then back to contact_dofs_.
  const int first = n - nc;
  std::vector<int> tail_position(nc);  // position in P's tail -> index in contact_dofs_
  for (int k = 0; k < nc; ++k)
    tail_position[k] = position_[P[first + k]];
  Eigen::MatrixXd Lt = Eigen::MatrixXd::Zero(nc, nc);
  const int* super = static_cast<const int*>(im.L->super);
  const int* pi = static_cast<const int*>(im.L->pi);
  const int* px = static_cast<const int*>(im.L->px);
  const int* rows = static_cast<const int*>(im.L->s);
  const double* x = static_cast<const double*>(im.L->x);
  for (size_t s = 0; s < im.L->nsuper; ++s) {
    const int k1 = super[s];
    const int k2 = super[s + 1];
    if (k2 <= first)
      continue;
    const int nsrow = pi[s + 1] - pi[s];
    for (int j = std::max(k1, first); j < k2; ++j) {
      const double* col = x + px[s] + static_cast<size_t>(j - k1) * nsrow;
      for (int r = j - k1; r < nsrow; ++r)
        Lt(rows[pi[s] + r] - first, j - first) = col[r];
    }
  }
  // S + D = L_cc L_cc^T, permuted from the factor's tail order to contact_dofs_ order.
  Eigen::MatrixXd SDt;
  dense::lower_outer_product(Lt, SDt);
  S_.resize(nc, nc);
  for (int a = 0; a < nc; ++a) {
    for (int b = 0; b < nc; ++b)
      S_(tail_position[a], tail_position[b]) = SDt(a, b);
  }
  L_tail_ = std::move(Lt);
  tail_position_ = std::move(tail_position);
  update_load(in.f);
  S_.diagonal() -= D_;
  timings_.condense_s = seconds_since(start);
  return {SolveStatus::Ok, ""};
}

void DofCondensation::update_load(const Eigen::VectorXd& f) {
  Impl& im = *impl_;
  im.f = f;
  const int nc = n_contact_dofs();
  f_c_.resize(nc);
  if (im.solver) {  // f_c = (S + D) (A0^{-1} f)_c
    const Eigen::VectorXd x = im.solver->solve(f);
    Eigen::VectorXd x_c(nc);
    for (int k = 0; k < nc; ++k)
      x_c[k] = x[contact_dofs_[k]];
    f_c_ = S_ * x_c + D_.cwiseProduct(x_c);
    return;
  }
  // y = L^{-1} P f; f_c = L_cc y_c.
  const int first = static_cast<int>(im.L->n) - nc;
  cholmod_dense fb = view_vector(f);
  cholmod_dense* Pf = cholmod_solve(CHOLMOD_P, im.L, &fb, &im.common);
  cholmod_dense* y = cholmod_solve(CHOLMOD_L, im.L, Pf, &im.common);
  const Eigen::VectorXd y_c =
      Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(y->x) + first, nc);
  cholmod_free_dense(&Pf, &im.common);
  cholmod_free_dense(&y, &im.common);
  const Eigen::VectorXd ft = L_tail_.triangularView<Eigen::Lower>() * y_c;
  for (int a = 0; a < nc; ++a)
    f_c_[tail_position_[a]] = ft[a];
}

Eigen::VectorXd DofCondensation::recover(const Eigen::VectorXd& u_c) const {
  // x = A0^{-1} [f_i; f_c(original) - f_c(condensed) + (S + D) u_c] has x_c = u_c and the
  // interior in equilibrium with it.
  Eigen::VectorXd rhs = impl_->f;
  const Eigen::VectorXd SDu = S_ * u_c + D_.cwiseProduct(u_c);
  for (int k = 0; k < n_contact_dofs(); ++k) {
    rhs[contact_dofs_[k]] += SDu[k] - f_c_[k];
  }
  Eigen::VectorXd u = impl_->solve(rhs);
  for (int k = 0; k < n_contact_dofs(); ++k)
    u[contact_dofs_[k]] = u_c[k];  // exact on c
  return u;
}

SolveOutcome ConstraintCondensation::compute(const DofCondensation& dofs, const RowMajorSparse& B,
                                             const Eigen::VectorXd& rho) {
  const auto start = Clock::now();
  const int nc = dofs.n_contact_dofs();
  const int m = static_cast<int>(B.rows());
  // M = S + B^T R B on the contact DOFs; B^T dense on them.
  L_ = dofs.schur();
  Bt_ = Eigen::MatrixXd::Zero(nc, m);
  std::vector<std::pair<int, double>> row;
  for (int j = 0; j < m; ++j) {
    row.clear();
    for (RowMajorSparse::InnerIterator e(B, j); e; ++e) {
      const int k = dofs.position(static_cast<int>(e.col()));
      if (k < 0) {
        return {SolveStatus::SolverFailure,
                fmt::format("constraint row {} touches equation {}, which is not a contact DOF", j,
                            e.col())};
      }
      row.emplace_back(k, e.value());
      Bt_(k, j) += e.value();
    }
    for (auto [a, va] : row) {
      for (auto [b, vb] : row)
        L_(a, b) += rho[j] * va * vb;
    }
  }
  const double norm1 = L_.cwiseAbs().colwise().sum().maxCoeff();
  if (!dense::cholesky_in_place(L_) || !(dense::cholesky_rcond(L_, norm1) > 1e-15)) {
    seconds_ = seconds_since(start);
    return {SolveStatus::NotPositiveDefinite,
            "the condensed stiffness with every candidate contact active is not positive "
            "definite: the candidate contact points do not hold a body that nothing else holds"};
  }
  Eigen::MatrixXd Z = Bt_;
  dense::lower_triangular_solve(L_, Z);  // Z = L^{-1} B^T
  dense::gram(Z, W_);                    // W = Z^T Z = B M^{-1} B^T
  update_load(dofs);
  seconds_ = seconds_since(start);
  return {SolveStatus::Ok, ""};
}

void ConstraintCondensation::update_load(const DofCondensation& dofs) {
  Eigen::VectorXd t = dofs.condensed_load();
  dense::cholesky_solve(L_, t);  // M^{-1} f_c
  d_ = Bt_.transpose() * t;
}

Eigen::VectorXd ConstraintCondensation::recover(const DofCondensation& dofs,
                                                const Eigen::VectorXd& mu) const {
  Eigen::VectorXd u_c = dofs.condensed_load() + Bt_ * mu;
  dense::cholesky_solve(L_, u_c);
  return dofs.recover(u_c);
}

}  // namespace cs::solver
