#include "solver/contact/condensation.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <cholmod.h>
#include <fmt/format.h>
#include <Eigen/Cholesky>

#include "solver/contact/backward_solve_subset.hpp"
#include "solver/contact/dense_kernels.hpp"
#include "solver/elimination_postorder.hpp"
#include "solver/fill_reducing_ordering.hpp"
#include "solver/linear_solver.hpp"
#include "solver/principal_submatrix.hpp"
#include "solver/spare_cores.hpp"
#include "solver/sparse_sum.hpp"

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

/// The symmetric matrix Delta added to K on the contact DOFs: diagonal d_k = K_kk and a chain
/// e_k = K-scale / 4 between consecutive contact DOFs (diagonally dominant, so positive
/// definite). The chain connects the contact DOFs of every body (an indenter's and a block's are
/// not coupled in K), which keeps them last through CHOLMOD's postorder.
struct ContactDiagonal {
  Eigen::VectorXd d;  ///< Delta_kk
  Eigen::VectorXd e;  ///< Delta_{k,k+1} = Delta_{k+1,k}
};

/// A0 = K + Delta (Delta on the contact DOFs).
Eigen::SparseMatrix<double> raised_matrix(const Eigen::SparseMatrix<double>& K,
                                          const std::vector<int>& contact_dofs,
                                          ContactDiagonal& delta) {
  const int nc = static_cast<int>(contact_dofs.size());
  delta.d.resize(nc);
  delta.e = Eigen::VectorXd::Zero(std::max(0, nc - 1));
  for (int k = 0; k < nc; ++k) {
    const double kk = K.coeff(contact_dofs[k], contact_dofs[k]);
    delta.d[k] = kk > 0.0 ? kk : 1.0;
  }
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(2 * nc);
  for (int k = 0; k < nc; ++k) {
    t.emplace_back(contact_dofs[k], contact_dofs[k], delta.d[k]);
    if (k + 1 < nc) {
      delta.e[k] = 0.25 * std::min(delta.d[k], delta.d[k + 1]);
      t.emplace_back(contact_dofs[k + 1], contact_dofs[k], delta.e[k]);  // lower: row > col
    }
  }
  Eigen::SparseMatrix<double> D(K.rows(), K.cols());
  D.setFromTriplets(t.begin(), t.end());
  return sparse_sum(K, D);
}

/// A0 is not positive definite: its pivot at `equation` (-1: not known) failed.
SolveOutcome not_positive_definite(int equation) {
  SolveOutcome out{SolveStatus::NotPositiveDefinite,
                   fmt::format("the elastic stiffness with the contact DOFs held is not positive "
                               "definite{}: a body is held neither by prescribed displacements "
                               "nor by its contact surface",
                               equation >= 0 ? fmt::format(" (pivot at equation {})", equation)
                                             : std::string())};
  out.failed_equation = equation;
  return out;
}

/// A0's factor has the pivot ratio `rcond`, too small to trust.
SolveOutcome numerically_singular(double rcond) {
  return {SolveStatus::Singular,
          fmt::format("the elastic stiffness with the contact DOFs held is numerically singular "
                      "(pivot ratio {:.3g}): a body is held neither by prescribed displacements "
                      "nor by its contact surface",
                      rcond)};
}

/// The number of distinct groups >= 0.
int count_groups(const std::vector<int>& group) {
  std::vector<char> seen;
  int count = 0;
  for (int g : group) {
    if (g < 0)
      continue;
    if (g >= static_cast<int>(seen.size()))
      seen.resize(g + 1, 0);
    count += seen[g] ? 0 : 1;
    seen[g] = 1;
  }
  return count;
}

/// A failed or numerically singular factorization as a status naming the likely cause.
SolveOutcome check_factor(const cholmod_factor& L, const cholmod_common& c) {
  if (c.status < CHOLMOD_OK && c.status != CHOLMOD_NOT_POSDEF) {
    return {SolveStatus::SolverFailure,
            fmt::format("CHOLMOD factorization failed (status {})", c.status)};
  }
  const int* P = static_cast<const int*>(L.Perm);
  if (L.minor < L.n)
    return not_positive_definite(P[L.minor]);
  const double rcond =
      cholmod_rcond(const_cast<cholmod_factor*>(&L), const_cast<cholmod_common*>(&c));
  if (!(rcond > 1e-15))
    return numerically_singular(rcond);
  return {SolveStatus::Ok, ""};
}

/// The trailing nc x nc block of a supernodal LL' factor (lower triangular, dense), read from the
/// supernodes' column-major blocks (rows of a supernode are sorted, its diagonal block first).
Eigen::MatrixXd trailing_block(const cholmod_factor& L, int nc) {
  const int first = static_cast<int>(L.n) - nc;
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(nc, nc);
  const int* super = static_cast<const int*>(L.super);
  const int* pi = static_cast<const int*>(L.pi);
  const int* px = static_cast<const int*>(L.px);
  const int* rows = static_cast<const int*>(L.s);
  const double* x = static_cast<const double*>(L.x);
  for (size_t s = 0; s < L.nsuper; ++s) {
    const int k1 = super[s];
    const int k2 = super[s + 1];
    if (k2 <= first)
      continue;
    const int nsrow = pi[s + 1] - pi[s];
    for (int j = std::max(k1, first); j < k2; ++j) {
      const double* col = x + px[s] + static_cast<size_t>(j - k1) * nsrow;
      for (int r = j - k1; r < nsrow; ++r)
        block(rows[pi[s] + r] - first, j - first) = col[r];
    }
  }
  return block;
}

/// From this many equations on, the trailing-block path orders by METIS directly.
constexpr Eigen::Index kMetisFrom = 200000;

}  // namespace

/// The two sides' condensations onto their borders and the border's dense factor
/// (compute_sides).
struct DofCondensation::Sides {
  std::array<DofCondensation, 2> side;
  /// Per side: local equation -> A0's equation (the side's own, increasing, then its border).
  std::array<std::vector<int>, 2> global;
  /// Per side: the position in `border` of each equation of its border (the border equations
  /// that an entry of A0 couples with the side).
  std::array<std::vector<int>, 2> at;
  std::vector<int> border;   ///< A0's equations of the border: the separator, increasing, then c
  std::vector<int> side_of;  ///< per A0 equation: 0 or 1, 2 on the separator, -1 in c
  std::vector<int> local;    ///< per A0 equation on a side: its local equation there
  std::vector<int> border_position;  ///< per A0 equation: its position in border, or -1
  std::vector<char> touches;         ///< per border equation: bit k if it couples with side k
  Eigen::MatrixXd L;                 ///< the Cholesky factor of S_b (lower), separator first
  Eigen::VectorXd z;                 ///< L^{-1} g_b, g_b the border's condensed load

  int n_border() const { return static_cast<int>(border.size()); }
  int n_own(int k) const { return static_cast<int>(global[k].size() - at[k].size()); }

  /// From side_of: the border (separator, then `contact_dofs`), each side's equations and
  /// border.
  void partition(const Eigen::SparseMatrix<double>& A0, const std::vector<int>& contact_dofs) {
    const int n = static_cast<int>(A0.rows());
    local.assign(n, -1);
    border_position.assign(n, -1);
    for (int eq = 0; eq < n; ++eq) {
      const int k = side_of[eq];
      if (k == 2) {
        border_position[eq] = n_border();
        border.push_back(eq);
      } else if (k >= 0) {
        local[eq] = static_cast<int>(global[k].size());
        global[k].push_back(eq);
      }
    }
    for (int eq : contact_dofs) {
      border_position[eq] = n_border();
      border.push_back(eq);
    }
    touches.assign(n_border(), 0);
    const auto on_side = [this](int eq) { return side_of[eq] == 0 || side_of[eq] == 1; };
    for (int j = 0; j < n; ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A0, j); it; ++it) {
        const int r = static_cast<int>(it.row());
        if (border_position[j] >= 0 && on_side(r))
          touches[border_position[j]] |= static_cast<char>(1 << side_of[r]);
        if (border_position[r] >= 0 && on_side(j))
          touches[border_position[r]] |= static_cast<char>(1 << side_of[j]);
      }
    }
    for (int k = 0; k < 2; ++k) {
      for (int b = 0; b < n_border(); ++b) {
        if (touches[b] & (1 << k)) {
          at[k].push_back(b);
          global[k].push_back(border[b]);
        }
      }
    }
  }

  /// S_b = A0_bb + sum_k (S_k - A0[b_k, b_k]), the sides condensed: A0_bb less both sides'
  /// couplings (A0[b_k, b_k] is in S_k).
  Eigen::MatrixXd border_block(const Eigen::SparseMatrix<double>& A0) const {
    const int nb = n_border();
    Eigen::MatrixXd Sb = Eigen::MatrixXd::Zero(nb, nb);
    for (int k = 0; k < 2; ++k)
      Sb(at[k], at[k]) += side[k].schur();
    for (int b = 0; b < nb; ++b) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A0, border[b]); it; ++it) {
        const int a = border_position[it.row()];
        if (a < 0)
          continue;
        const int both = touches[a] & touches[b];  // the sides whose S_k holds A0_ab
        const double v = (1 - (both & 1) - ((both >> 1) & 1)) * it.value();
        Sb(a, b) += v;
        if (a != b)
          Sb(b, a) += v;
      }
    }
    return Sb;
  }

  /// Side k's load: f on its own equations, zero on its border (whose load is added once).
  Eigen::VectorXd side_load(int k, const Eigen::VectorXd& f) const {
    Eigen::VectorXd fk = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(global[k].size()));
    for (int l = 0; l < n_own(k); ++l)
      fk[l] = f[global[k][l]];
    return fk;
  }

  /// z = L^{-1} g_b, g_b = f_b + the sides' condensed loads (their loads given).
  void condense_load(const Eigen::VectorXd& f) {
    z.resize(n_border());
    for (int b = 0; b < n_border(); ++b)
      z[b] = f[border[b]];
    for (int k = 0; k < 2; ++k)
      z(at[k]) += side[k].condensed_load();
    L.triangularView<Eigen::Lower>().solveInPlace(z);
  }

  /// The field for the border's values x_b: x_b on the border, each side's own equations from
  /// its recovery (those of its part of `subset` when one is given); NaN elsewhere.
  Eigen::VectorXd recover(const Eigen::VectorXd& x_b, const RecoverySubset* subset,
                          Eigen::Index n) const {
    Eigen::VectorXd u = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
    u(border) = x_b;
    for (int k = 0; k < 2; ++k) {
      const Eigen::VectorXd x_k = x_b(at[k]);
      const Eigen::VectorXd u_k =
          subset != nullptr ? side[k].recover(x_k, subset->sides[k]) : side[k].recover(x_k);
      if (subset != nullptr) {
        for (int l : subset->sides[k].equations) {
          if (l < n_own(k))
            u[global[k][l]] = u_k[l];
        }
      } else {
        for (int l = 0; l < n_own(k); ++l)
          u[global[k][l]] = u_k[l];
      }
    }
    return u;
  }
};

struct DofCondensation::Impl {
  // Trailing-block path: CHOLMOD directly (given permutation, access to the factor's blocks).
  cholmod_common common{};
  cholmod_factor* L = nullptr;
  bool started = false;
  // Two-sides path (compute_sides).
  std::unique_ptr<Sides> sides;
  // Reference path: the FE core's linear solver.
  std::optional<LinearSolver> solver;
  Eigen::VectorXd f;
  /// Trailing-block path: y0 = L^{-1} P f, whose interior part every recovery shares.
  Eigen::VectorXd y0;

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

  /// The node of each equation of A0 (the equation itself without nodes), and -1 for the contact
  /// DOFs c: the interior's groups for the quotient ordering.
  static std::vector<int> interior_groups(const DofCondensationInput& in,
                                          const std::vector<char>& is_contact) {
    const int n = static_cast<int>(is_contact.size());
    const bool by_node = static_cast<int>(in.node_of_equation.size()) == n;
    std::vector<int> group(n);
    for (int eq = 0; eq < n; ++eq)
      group[eq] = is_contact[eq] ? -1 : by_node ? in.node_of_equation[eq] : eq;
    return group;
  }

  /// Constrained AMD (CAMD) on the node (quotient) graph of the whole matrix, the contact DOFs
  /// constrained last: AMD's ordering of the interior then accounts for the fill the contact
  /// DOFs bring (ordering them last without telling AMD would fill every surface column).
  bool order_camd(const Eigen::SparseMatrix<double>& A0, const DofCondensationInput& in,
                  const std::vector<char>& is_contact, std::vector<int>& perm) {
    const int n = static_cast<int>(A0.rows());
    const bool by_node = static_cast<int>(in.node_of_equation.size()) == n;
    // Vertices: (node, interior|contact) pairs, numbered by first appearance.
    std::vector<int> vertex(n);
    std::map<std::pair<int, int>, int> vertex_of;
    std::vector<int> member_set;
    for (int eq = 0; eq < n; ++eq) {
      const std::pair<int, int> key{by_node ? in.node_of_equation[eq] : eq, is_contact[eq]};
      const auto [it, fresh] = vertex_of.emplace(key, static_cast<int>(member_set.size()));
      if (fresh)
        member_set.push_back(is_contact[eq]);
      vertex[eq] = it->second;
    }
    const int nv = static_cast<int>(member_set.size());
    std::vector<std::vector<int>> members(nv), upper(nv);
    for (int eq = 0; eq < n; ++eq) {
      members[vertex[eq]].push_back(eq);
      for (Eigen::SparseMatrix<double>::InnerIterator it(A0, eq); it; ++it) {
        const int a = vertex[eq], b = vertex[it.row()];
        if (a != b)
          upper[std::min(a, b)].push_back(std::max(a, b));
      }
    }
    std::vector<int> outer(nv + 1, 0), inner;
    for (int v = 0; v < nv; ++v) {
      std::vector<int>& adj = upper[v];
      std::sort(adj.begin(), adj.end());
      adj.erase(std::unique(adj.begin(), adj.end()), adj.end());
      inner.push_back(v);  // the diagonal, then the neighbours w > v
      inner.insert(inner.end(), adj.begin(), adj.end());
      outer[v + 1] = static_cast<int>(inner.size());
      std::vector<int>().swap(adj);
    }
    std::vector<double> ones(inner.size(), 1.0);
    cholmod_sparse Q{};
    Q.nrow = Q.ncol = static_cast<size_t>(nv);
    Q.nzmax = inner.size();
    Q.p = outer.data();
    Q.i = inner.data();
    Q.x = ones.data();
    Q.stype = -1;
    Q.itype = CHOLMOD_INT;
    Q.xtype = CHOLMOD_REAL;
    Q.dtype = CHOLMOD_DOUBLE;
    Q.sorted = 1;
    Q.packed = 1;
    std::vector<int> vperm(nv);
    if (nv > 0 && !cholmod_camd(&Q, nullptr, 0, member_set.data(), vperm.data(), &common)) {
      return false;
    }
    perm.clear();
    perm.reserve(n);
    for (int v : vperm) {
      for (int eq : members[v])
        perm.push_back(eq);
    }
    return true;
  }

  /// METIS nested dissection on the node graph of the interior (the FE core's quotient
  /// ordering), then c.
  bool order_metis(const Eigen::SparseMatrix<double>& A0, const DofCondensationInput& in,
                   const std::vector<char>& is_contact, std::vector<int>& perm) {
    try {
      perm = metis_quotient_ordering(A0, interior_groups(in, is_contact));
    } catch (const std::exception&) {
      return false;
    }
    perm.insert(perm.end(), in.contact_dofs.begin(), in.contact_dofs.end());
    return true;
  }

  /// Symbolic analysis of A0 in the order `perm` (its last nc entries the contact DOFs c), with
  /// the interior postordered here (elimination_postorder.hpp) so that c stays last and CHOLMOD
  /// analyzes once without postordering. Returns the symbolic factor or nullptr.
  cholmod_factor* analyze(const Eigen::SparseMatrix<double>& A0, const std::vector<int>& perm,
                          int nc) {
    std::vector<int> order =
        postordered_leading_block(A0, perm, static_cast<int>(perm.size()) - nc);
    cholmod_sparse A = view_lower(A0);
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_GIVEN;
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.postorder = 0;
    return cholmod_analyze_p(&A, order.data(), nullptr, 0, &common);
  }

  /// Whether the ordering is METIS's alone (the policy below).
  static bool metis_only(const Eigen::SparseMatrix<double>& A0, const DofCondensationInput& in) {
    return in.ordering == FillReducingOrdering::Metis ||
           (in.ordering != FillReducingOrdering::Amd && A0.rows() >= kMetisFrom);
  }

  /// The ordering policy. Small systems: CAMD on the node graph, then (as CHOLMOD's default
  /// strategy does) METIS where CAMD's fill is high (flops / nnz(L) >= 500 and nnz(L) / nnz(A)
  /// >= 5), keeping the cheaper. Large systems (>= kMetisFrom equations): METIS alone, since
  /// there CAMD with c last needs 2-3x METIS's flops (measured: S_1_7 fine Q4, 5.4e5 equations:
  /// CAMD 0.9 s analysis + 7.4e10 flops, METIS 3.2 s analysis + 2.3e10 flops).
  SolveOutcome order_and_analyze(const Eigen::SparseMatrix<double>& A0,
                                 const DofCondensationInput& in,
                                 const std::vector<char>& is_contact) {
    if (L != nullptr)
      cholmod_free_factor(&L, &common);
    const int nc = static_cast<int>(in.contact_dofs.size());
    std::vector<int> perm;
    const auto failed = [this] {
      return SolveOutcome{
          SolveStatus::SolverFailure,
          fmt::format("CHOLMOD symbolic analysis failed (status {})", common.status)};
    };
    if (metis_only(A0, in)) {
      if (!order_metis(A0, in, is_contact, perm) || (L = analyze(A0, perm, nc)) == nullptr) {
        return failed();
      }
      return {SolveStatus::Ok, ""};
    }
    if (!order_camd(A0, in, is_contact, perm) || (L = analyze(A0, perm, nc)) == nullptr) {
      return failed();
    }
    const double camd_flops = common.fl;
    const double camd_lnz = common.lnz;
    if (in.ordering != FillReducingOrdering::Amd && camd_flops / camd_lnz >= 500.0 &&
        camd_lnz / static_cast<double>(A0.nonZeros()) >= 5.0 &&
        order_metis(A0, in, is_contact, perm)) {
      cholmod_factor* F = analyze(A0, perm, nc);
      if (F != nullptr && common.fl < camd_flops) {
        cholmod_free_factor(&L, &common);
        L = F;
      } else if (F != nullptr) {
        cholmod_free_factor(&F, &common);
        common.fl = camd_flops;
        common.lnz = camd_lnz;
      }
    }
    return {SolveStatus::Ok, ""};
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
  impl_->f = in.f;
  const auto start = Clock::now();
  ContactDiagonal delta;
  Eigen::SparseMatrix<double> raised;
  if (in.hold_contact_dofs) {
    raised = raised_matrix(in.K_lower, contact_dofs_, delta);
  } else {
    delta.d = Eigen::VectorXd::Zero(nc);
    delta.e = Eigen::VectorXd::Zero(std::max(0, nc - 1));
  }
  const Eigen::SparseMatrix<double>& A0 = in.hold_contact_dofs ? raised : in.K_lower;
  delta_d_ = std::move(delta.d);
  delta_e_ = std::move(delta.e);
  timings_.assemble_s = seconds_since(start);
  return method_ == CondensationMethod::MultipleRightHandSides
             ? compute_reference(A0)
             : compute_trailing(A0, in, is_contact);
}

SolveOutcome DofCondensation::compute_reference(const Eigen::SparseMatrix<double>& A0) {
  Impl& im = *impl_;
  const int n = static_cast<int>(A0.rows());
  const int nc = n_contact_dofs();
  im.solver.emplace();
  auto start = Clock::now();
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
  S_ = Xcc.llt().solve(Eigen::MatrixXd::Identity(nc, nc));  // S + Delta
  subtract_delta();
  update_load(im.f);
  timings_.condense_s = seconds_since(start);
  return {SolveStatus::Ok, ""};
}

SolveOutcome DofCondensation::compute_trailing(const Eigen::SparseMatrix<double>& A0,
                                               const DofCondensationInput& in,
                                               const std::vector<char>& is_contact) {
  Impl& im = *impl_;
  im.start();
  cholmod_common& c = im.common;
  const int n = static_cast<int>(A0.rows());
  const int nc = n_contact_dofs();
  im.sides.reset();
  if (Impl::metis_only(A0, in) &&
      count_groups(Impl::interior_groups(in, is_contact)) >= in.substructure_from) {
    return compute_sides(A0, in, is_contact);
  }
  auto start = Clock::now();
  const SolveOutcome analyzed = im.order_and_analyze(A0, in, is_contact);
  timings_.analyze_s = seconds_since(start);
  if (!analyzed.ok())
    return analyzed;
  cholmod_sparse A0_view = view_lower(A0);
  start = Clock::now();
  cholmod_factorize(&A0_view, im.L, &c);
  timings_.factorize_s = seconds_since(start);
  factor_nnz_ = c.lnz;
  factor_flops_ = c.fl;
  SolveOutcome checked = check_factor(*im.L, c);
  if (!checked.ok())
    return checked;

  start = Clock::now();
  // The trailing block of the factor (in the factor's tail order): S + Delta = L_cc L_cc^T,
  // permuted back to contact_dofs_ order.
  const int* P = static_cast<const int*>(im.L->Perm);
  tail_position_.resize(nc);  // position in the factor's tail -> index in contact_dofs_
  for (int k = 0; k < nc; ++k)
    tail_position_[k] = position_[P[n - nc + k]];
  L_tail_ = trailing_block(*im.L, nc);
  schur_from_tail();
  update_load(in.f);
  timings_.condense_s = seconds_since(start);
  return {SolveStatus::Ok, ""};
}

void DofCondensation::schur_from_tail() {
  const int nc = n_contact_dofs();
  Eigen::MatrixXd SDt;
  dense::lower_outer_product(L_tail_, SDt);
  S_.resize(nc, nc);
  for (int a = 0; a < nc; ++a) {
    for (int b = 0; b < nc; ++b)
      S_(tail_position_[a], tail_position_[b]) = SDt(a, b);
  }
  subtract_delta();
}

SolveOutcome DofCondensation::compute_sides(const Eigen::SparseMatrix<double>& A0,
                                            const DofCondensationInput& in,
                                            const std::vector<char>& is_contact) {
  const int n = static_cast<int>(A0.rows());
  const int nc = n_contact_dofs();
  auto start = Clock::now();
  auto sides = std::make_unique<Sides>();
  Sides& s = *sides;
  try {
    s.side_of = quotient_bisection(A0, Impl::interior_groups(in, is_contact));
  } catch (const std::exception& e) {
    return {SolveStatus::SolverFailure, fmt::format("the interior's separator: {}", e.what())};
  }
  s.partition(A0, contact_dofs_);
  const int nb = s.n_border();
  const double bisect_s = seconds_since(start);

  // Each side condensed onto the border: A0[k+b] is positive definite as A0 is, so no Delta.
  std::array<SolveOutcome, 2> outcome;
  const auto condense_side = [&](int k) {
    const std::vector<int>& global = s.global[k];
    const Eigen::SparseMatrix<double> Ak = principal_lower(A0, global);
    const Eigen::VectorXd fk = s.side_load(k, in.f);
    std::vector<int> border(s.at[k].size());
    std::iota(border.begin(), border.end(), s.n_own(k));
    std::vector<int> node_of_equation;
    if (static_cast<int>(in.node_of_equation.size()) == n) {
      for (int eq : global)
        node_of_equation.push_back(in.node_of_equation[eq]);
    }
    DofCondensationInput side_in{Ak, fk, border, node_of_equation, in.ordering};
    side_in.substructure_from = std::numeric_limits<int>::max();
    side_in.hold_contact_dofs = false;
    outcome[k] = s.side[k].compute(side_in);
  };
  run_both([&] { condense_side(0); }, [&] { condense_side(1); });
  for (int k = 0; k < 2; ++k) {
    if (outcome[k].failed_equation >= 0)
      return not_positive_definite(s.global[k][outcome[k].failed_equation]);
    if (!outcome[k].ok())
      return outcome[k];
  }
  const CondensationTimings& t0 = s.side[0].timings();
  const CondensationTimings& t1 = s.side[1].timings();
  timings_.analyze_s = bisect_s + std::max(t0.analyze_s, t1.analyze_s);
  timings_.factorize_s = std::max(t0.factorize_s, t1.factorize_s);

  // S_b's Cholesky factor, the separator first.
  start = Clock::now();
  Eigen::MatrixXd Sb = s.border_block(A0);
  const double norm1 = Sb.cwiseAbs().colwise().sum().maxCoeff();
  s.L = std::move(Sb);
  if (!dense::cholesky_in_place(s.L))
    return not_positive_definite(-1);
  const double rcond = dense::cholesky_rcond(s.L, norm1);
  if (!(rcond > 1e-15))
    return numerically_singular(rcond);
  factor_nnz_ = s.side[0].factor_nonzeros() + s.side[1].factor_nonzeros() + 0.5 * nb * (nb + 1.0);
  factor_flops_ = s.side[0].factor_flops() + s.side[1].factor_flops() + std::pow(nb, 3) / 3.0;
  L_tail_ = s.L.bottomRightCorner(nc, nc);
  tail_position_.resize(nc);
  std::iota(tail_position_.begin(), tail_position_.end(), 0);
  impl_->sides = std::move(sides);
  schur_from_tail();
  condense_sides_load();  // the sides hold their loads already
  timings_.condense_s = std::max(t0.condense_s, t1.condense_s) + seconds_since(start);
  return {SolveStatus::Ok, ""};
}

Eigen::VectorXd DofCondensation::delta_times(const Eigen::VectorXd& u_c) const {
  Eigen::VectorXd out = delta_d_.cwiseProduct(u_c);
  for (Eigen::Index k = 0; k < delta_e_.size(); ++k) {
    out[k] += delta_e_[k] * u_c[k + 1];
    out[k + 1] += delta_e_[k] * u_c[k];
  }
  return out;
}

void DofCondensation::subtract_delta() {
  S_.diagonal() -= delta_d_;
  for (Eigen::Index k = 0; k < delta_e_.size(); ++k) {
    S_(k, k + 1) -= delta_e_[k];
    S_(k + 1, k) -= delta_e_[k];
  }
}

void DofCondensation::update_load(const Eigen::VectorXd& f) {
  Impl& im = *impl_;
  im.f = f;
  const int nc = n_contact_dofs();
  f_c_.resize(nc);
  if (im.solver) {  // f_c = (S + Delta) (A0^{-1} f)_c
    const Eigen::VectorXd x = im.solver->solve(f);
    Eigen::VectorXd x_c(nc);
    for (int k = 0; k < nc; ++k)
      x_c[k] = x[contact_dofs_[k]];
    f_c_ = S_ * x_c + delta_times(x_c);
    return;
  }
  if (im.sides) {
    for (int k = 0; k < 2; ++k)
      im.sides->side[k].update_load(im.sides->side_load(k, f));
    condense_sides_load();
    return;
  }
  // y = L^{-1} P f; f_c = L_cc y_c.
  cholmod_dense fb = view_vector(f);
  cholmod_dense* Pf = cholmod_solve(CHOLMOD_P, im.L, &fb, &im.common);
  cholmod_dense* y = cholmod_solve(CHOLMOD_L, im.L, Pf, &im.common);
  im.y0 = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(y->x), im.L->n);
  const Eigen::VectorXd y_c = im.y0.tail(nc);
  cholmod_free_dense(&Pf, &im.common);
  cholmod_free_dense(&y, &im.common);
  const Eigen::VectorXd ft = L_tail_.triangularView<Eigen::Lower>() * y_c;
  for (int a = 0; a < nc; ++a)
    f_c_[tail_position_[a]] = ft[a];
}

void DofCondensation::condense_sides_load() {
  Sides& s = *impl_->sides;
  s.condense_load(impl_->f);
  const int nc = n_contact_dofs();
  f_c_ = L_tail_.triangularView<Eigen::Lower>() * s.z.tail(nc);  // tail order = c's order
}

Eigen::VectorXd DofCondensation::border_values(const Eigen::VectorXd& u_c) const {
  // As backward_right_side() on the border's dense factor: L^T x = [z_s; L_cc^T u_c] has
  // x_c = u_c and x_s in equilibrium with it.
  const Sides& s = *impl_->sides;
  const int nc = n_contact_dofs();
  Eigen::VectorXd x = s.z;
  x.tail(nc) = L_tail_.triangularView<Eigen::Lower>().transpose() * u_c;
  s.L.triangularView<Eigen::Lower>().transpose().solveInPlace(x);
  x.tail(nc) = u_c;  // exact on c
  return x;
}

Eigen::VectorXd DofCondensation::backward_right_side(const Eigen::VectorXd& u_c) const {
  // With c last in the factor, L y = P [f_i; r_c] leaves the interior of y at y0 = L^{-1} P f
  // whatever r_c is, and L^T (P x) = y has x_c = u_c exactly when y_c = L_cc^T u_c (tail
  // order): one backward solve instead of a forward and a backward one.
  const int nc = n_contact_dofs();
  Eigen::VectorXd u_tail(nc);
  for (int a = 0; a < nc; ++a)
    u_tail[a] = u_c[tail_position_[a]];
  Eigen::VectorXd y = impl_->y0;
  y.tail(nc) = L_tail_.triangularView<Eigen::Lower>().transpose() * u_tail;
  return y;
}

Eigen::VectorXd DofCondensation::recover(const Eigen::VectorXd& u_c) const {
  Impl& im = *impl_;
  if (im.sides)
    return im.sides->recover(border_values(u_c), nullptr,
                             static_cast<Eigen::Index>(position_.size()));
  if (im.solver) {
    // x = A0^{-1} [f_i; f_c(original) - f_c(condensed) + (S + Delta) u_c] has x_c = u_c and
    // the interior in equilibrium with it.
    Eigen::VectorXd rhs = im.f;
    const Eigen::VectorXd SDu = S_ * u_c + delta_times(u_c);
    for (int k = 0; k < n_contact_dofs(); ++k) {
      rhs[contact_dofs_[k]] += SDu[k] - f_c_[k];
    }
    Eigen::VectorXd u = im.solve(rhs);
    for (int k = 0; k < n_contact_dofs(); ++k)
      u[contact_dofs_[k]] = u_c[k];  // exact on c
    return u;
  }
  Eigen::VectorXd y = backward_right_side(u_c);
  const int nc = n_contact_dofs();
  cholmod_dense yv = view_vector(y);
  cholmod_dense* Px = cholmod_solve(CHOLMOD_Lt, im.L, &yv, &im.common);
  cholmod_dense* x = cholmod_solve(CHOLMOD_Pt, im.L, Px, &im.common);
  Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), y.size());
  cholmod_free_dense(&Px, &im.common);
  cholmod_free_dense(&x, &im.common);
  for (int k = 0; k < nc; ++k)
    u[contact_dofs_[k]] = u_c[k];  // exact on c
  return u;
}

RecoverySubset DofCondensation::subset(const std::vector<int>& equations) const {
  const Impl& im = *impl_;
  if (im.sides) {
    const Sides& s = *im.sides;
    std::array<std::vector<int>, 2> wanted;
    for (int eq : equations) {
      if (eq < 0 || eq >= static_cast<int>(position_.size()))
        throw std::invalid_argument(
            fmt::format("DofCondensation::subset: equation {} of {}", eq, position_.size()));
      const int k = s.side_of[eq];
      if (k == 0 || k == 1)
        wanted[k].push_back(s.local[eq]);
    }
    RecoverySubset out;
    out.equations = s.border;
    for (int k = 0; k < 2; ++k) {
      out.sides.push_back(s.side[k].subset(wanted[k]));
      for (int l : out.sides.back().equations)
        out.equations.push_back(s.global[k][l]);
    }
    std::sort(out.equations.begin(), out.equations.end());
    out.equations.erase(std::unique(out.equations.begin(), out.equations.end()),
                        out.equations.end());
    return out;
  }
  if (im.solver || im.L == nullptr)
    return {};
  // Factor column k holds equation Perm[k].
  const auto* perm = static_cast<const int*>(im.L->Perm);
  std::vector<int> column_of(im.L->n);
  for (int k = 0; k < static_cast<int>(im.L->n); ++k)
    column_of[perm[k]] = k;
  std::vector<int> columns;
  columns.reserve(equations.size() + contact_dofs_.size());
  for (int eq : equations) {
    if (eq < 0 || eq >= static_cast<int>(im.L->n))
      throw std::invalid_argument(
          fmt::format("DofCondensation::subset: equation {} of {}", eq, im.L->n));
    columns.push_back(column_of[eq]);
  }
  for (int eq : contact_dofs_)
    columns.push_back(column_of[eq]);
  RecoverySubset out;
  out.backward = std::make_shared<const BackwardSolveSubset>(*im.L, columns);
  for (int k : out.backward->columns())
    out.equations.push_back(perm[k]);
  std::sort(out.equations.begin(), out.equations.end());
  return out;
}

Eigen::VectorXd DofCondensation::recover(const Eigen::VectorXd& u_c,
                                         const RecoverySubset& subset) const {
  const Impl& im = *impl_;
  if (im.sides && subset.sides.size() == 2)
    return im.sides->recover(border_values(u_c), &subset,
                             static_cast<Eigen::Index>(position_.size()));
  if (!subset.backward || im.solver)
    return recover(u_c);
  // As recover(u_c), the backward solve over the subset's supernodes only.
  Eigen::VectorXd y = backward_right_side(u_c);
  subset.backward->solve(*im.L, y.data());
  const int nc = n_contact_dofs();
  const auto* perm = static_cast<const int*>(im.L->Perm);
  Eigen::VectorXd u = Eigen::VectorXd::Constant(y.size(), std::numeric_limits<double>::quiet_NaN());
  for (int k : subset.backward->columns())
    u[perm[k]] = y[k];
  for (int k = 0; k < nc; ++k)
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
                                                const Eigen::VectorXd& mu,
                                                const RecoverySubset* subset) const {
  Eigen::VectorXd u_c = dofs.condensed_load() + Bt_ * mu;
  dense::cholesky_solve(L_, u_c);
  return subset != nullptr ? dofs.recover(u_c, *subset) : dofs.recover(u_c);
}

}  // namespace cs::solver
