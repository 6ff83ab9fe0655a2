#include "solver/linear_solver.hpp"

#include "solver/fill_reducing_ordering.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

namespace cs::solver {

/// What LinearSolver::Impl holds. Named, not file-local: a class with linkage holds them.
namespace linear_solver_parts {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Eigen's CHOLMOD supernodal LL', with access to the CHOLMOD factor (for the pivot ratio
/// estimate, the permutation of a failed pivot and the selected ordering).
class SupernodalLLT : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  cholmod_factor* factor() const { return m_cholmodFactor; }

  /// analyzePattern() with a given fill-reducing permutation (cholmod_analyze_p); the common
  /// must select CHOLMOD_GIVEN.
  void analyze_given(const SparseMatrix& A, std::vector<int>& perm) {
    cholmod_common& c = this->cholmod();  // (m_cholmod is private in CholmodSupernodalLLT)
    if (m_cholmodFactor != nullptr) {
      cholmod_free_factor(&m_cholmodFactor, &c);
      m_cholmodFactor = nullptr;
    }
    cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
    m_cholmodFactor = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &c);
    this->m_isInitialized = true;
    this->m_info = Eigen::Success;
    m_analysisIsOk = true;
    m_factorizationIsOk = false;
  }
};

/// A fingerprint of a sparsity pattern: size, nonzeros and a hash of the index arrays.
struct PatternKey {
  long n = -1;
  long nnz = -1;
  std::uint64_t hash = 0;
  bool operator==(const PatternKey&) const = default;
};

}  // namespace linear_solver_parts

namespace {

using linear_solver_parts::PatternKey;
using linear_solver_parts::SparseMatrix;
using linear_solver_parts::SupernodalLLT;

PatternKey pattern_key(const SparseMatrix& A) {
  PatternKey key{A.rows(), A.nonZeros(), 1469598103934665603ull};
  auto mix = [&key](const int* p, long count) {
    for (long i = 0; i < count; ++i) {
      key.hash ^= static_cast<std::uint32_t>(p[i]);
      key.hash *= 1099511628211ull;
    }
  };
  mix(A.outerIndexPtr(), A.outerSize() + 1);
  mix(A.innerIndexPtr(), A.nonZeros());
  return key;
}

const char* cholmod_ordering_name(int ordering) {
  switch (ordering) {
    case CHOLMOD_NATURAL:
      return "natural";
    case CHOLMOD_GIVEN:
      return "given";
    case CHOLMOD_AMD:
      return "AMD";
    case CHOLMOD_METIS:
      return "METIS";
    case CHOLMOD_NESDIS:
      return "NESDIS";
    case CHOLMOD_COLAMD:
      return "COLAMD";
    case CHOLMOD_POSTORDERED:
      return "natural, postordered";
    default:
      return "unknown";
  }
}

void configure(cholmod_common& c, FillReducingOrdering ordering) {
  c.print = 0;         // failures are reported as statuses, not printed
  c.metis_memory = 0;  // never silently fall back from METIS to AMD
  switch (ordering) {
    case FillReducingOrdering::Automatic:  // without supervariables: CHOLMOD's own strategy
      c.nmethods = 0;
      break;
    case FillReducingOrdering::Metis:
      c.nmethods = 1;
      c.method[0].ordering = CHOLMOD_METIS;
      break;
    case FillReducingOrdering::Nesdis:
      c.nmethods = 1;
      c.method[0].ordering = CHOLMOD_NESDIS;
      break;
    case FillReducingOrdering::Amd:
      c.nmethods = 1;
      c.method[0].ordering = CHOLMOD_AMD;
      break;
    case FillReducingOrdering::CholmodDefault:
      c.nmethods = 0;
      break;
    case FillReducingOrdering::Best:
      c.nmethods = 3;
      c.method[0].ordering = CHOLMOD_AMD;
      c.method[1].ordering = CHOLMOD_METIS;
      c.method[2].ordering = CHOLMOD_NESDIS;
      break;
  }
  c.postorder = 1;
}

/// CHOLMOD's symbolic analysis of A with the requested ordering. With supervariables, METIS
/// runs on their graph and its permutation is given to CHOLMOD; Automatic then follows
/// CHOLMOD's own strategy (AMD; METIS too when AMD's fill is high; the fewer flops win).
/// Returns whether the node-graph METIS permutation is the one analyzed.
bool cholmod_analysis(SupernodalLLT& llt, const SparseMatrix& A, FillReducingOrdering ordering,
                      const std::vector<int>& supervariables) {
  cholmod_common& c = llt.cholmod();
  const bool groups = static_cast<long>(supervariables.size()) == A.rows();
  auto analyze_metis_quotient = [&] {
    std::vector<int> perm = metis_quotient_ordering(A, supervariables);
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
    llt.analyze_given(A, perm);
  };
  if (groups && ordering == FillReducingOrdering::Metis) {
    analyze_metis_quotient();
    return true;
  }
  if (!groups || ordering != FillReducingOrdering::Automatic) {
    configure(c, ordering);
    std::unique_lock<std::mutex> turn;  // every ordering but AMD may call METIS
    if (ordering != FillReducingOrdering::Amd)
      turn = metis_turn();
    llt.analyzePattern(A);
    return false;
  }
  configure(c, FillReducingOrdering::Amd);
  llt.analyzePattern(A);
  const double amd_flops = c.fl;
  const double amd_lnz = c.lnz;
  const bool amd_ok = llt.factor() != nullptr && c.status >= CHOLMOD_OK;
  if (!amd_ok || amd_flops / amd_lnz < 500.0 || amd_lnz / static_cast<double>(A.nonZeros()) < 5.0) {
    return false;  // AMD's fill is fine (CHOLMOD's test)
  }
  analyze_metis_quotient();
  if (llt.factor() != nullptr && c.status >= CHOLMOD_OK && c.fl <= amd_flops)
    return true;
  configure(c, FillReducingOrdering::Amd);
  llt.analyzePattern(A);
  return false;
}

}  // namespace

const char* to_string(LinearSolverKind kind) {
  return kind == LinearSolverKind::CholmodSupernodal ? "CHOLMOD supernodal LL'"
                                                     : "Eigen SimplicialLDLT";
}

const char* to_string(FillReducingOrdering ordering) {
  switch (ordering) {
    case FillReducingOrdering::Automatic:
      return "automatic (AMD, or METIS if AMD's fill is high)";
    case FillReducingOrdering::Metis:
      return "METIS";
    case FillReducingOrdering::Nesdis:
      return "NESDIS";
    case FillReducingOrdering::Amd:
      return "AMD";
    case FillReducingOrdering::CholmodDefault:
      return "CHOLMOD default";
    case FillReducingOrdering::Best:
      return "best of AMD, METIS, NESDIS";
  }
  return "unknown";
}

struct LinearSolver::Impl {
  std::optional<SupernodalLLT> cholmod;
  std::optional<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>> ldlt;
  std::vector<int> supervariables;
  PatternKey analyzed;
  bool analyzed_ok = false;
  bool factorized = false;
};

LinearSolver::LinearSolver(LinearSolverOptions options)
    : options_(options), impl_(std::make_unique<Impl>()) {
  info_.kind = options.kind;
  if (options.kind == LinearSolverKind::CholmodSupernodal) {
    impl_->cholmod.emplace();
    configure(impl_->cholmod->cholmod(), options.ordering);
  } else {
    impl_->ldlt.emplace();
  }
}

LinearSolver::~LinearSolver() = default;
LinearSolver::LinearSolver(LinearSolver&&) noexcept = default;
LinearSolver& LinearSolver::operator=(LinearSolver&&) noexcept = default;

bool LinearSolver::is_factorized() const {
  return impl_->factorized;
}

void LinearSolver::set_supervariables(std::vector<int> group_of_equation) {
  impl_->supervariables = std::move(group_of_equation);
}

SolveOutcome LinearSolver::analyze(const SparseMatrix& A) {
  impl_->factorized = false;
  impl_->analyzed_ok = false;
  info_.n = static_cast<int>(A.rows());
  info_.nnz_matrix = A.nonZeros();
  ++info_.analyze_count;
  if (A.rows() != A.cols()) {
    return {SolveStatus::SolverFailure,
            fmt::format("matrix is {} x {}, not square", A.rows(), A.cols())};
  }
  if (impl_->cholmod) {
    SupernodalLLT& llt = *impl_->cholmod;
    cholmod_common& c = llt.cholmod();
    bool quotient = false;
    try {
      quotient = cholmod_analysis(llt, A, options_.ordering, impl_->supervariables);
    } catch (const std::exception& e) {
      return {SolveStatus::SolverFailure,
              fmt::format("fill-reducing ordering failed: {}", e.what())};
    }
    if (llt.factor() == nullptr || c.status < CHOLMOD_OK) {
      return {SolveStatus::SolverFailure,
              fmt::format("CHOLMOD symbolic analysis failed (status {}{})", c.status,
                          c.status == CHOLMOD_OUT_OF_MEMORY ? ", out of memory" : "")};
    }
    const int selected = c.selected < 0 ? 0 : c.selected;
    info_.ordering =
        quotient ? "METIS (node graph)" : cholmod_ordering_name(c.method[selected].ordering);
    if (!quotient && llt.factor()->ordering != c.method[selected].ordering) {
      info_.ordering += fmt::format(" (factor: {})", cholmod_ordering_name(llt.factor()->ordering));
    }
    info_.nnz_factor = c.lnz;
    info_.flops = c.fl;
    info_.supernodal = llt.factor()->is_super != 0;
  } else {
    impl_->ldlt->analyzePattern(A);
    info_.ordering = "AMD (Eigen)";
    info_.supernodal = false;
    info_.flops = 0.0;
  }
  impl_->analyzed = pattern_key(A);
  impl_->analyzed_ok = true;
  return {SolveStatus::Ok, ""};
}

SolveOutcome LinearSolver::factorize(const SparseMatrix& A) {
  impl_->factorized = false;
  if (!impl_->analyzed_ok) {
    return {SolveStatus::SolverFailure, "factorize() called without a successful analyze()"};
  }
  ++info_.factorize_count;
  SolveOutcome out{SolveStatus::Ok, ""};
  if (impl_->cholmod) {
    SupernodalLLT& llt = *impl_->cholmod;
    llt.factorize(A);
    cholmod_common& c = llt.cholmod();
    const cholmod_factor* L = llt.factor();
    if (c.status < CHOLMOD_OK) {
      return {SolveStatus::SolverFailure,
              fmt::format("CHOLMOD factorization failed (status {}{})", c.status,
                          c.status == CHOLMOD_OUT_OF_MEMORY ? ", out of memory" : "")};
    }
    if (llt.info() != Eigen::Success || L->minor < L->n) {
      const int k = static_cast<int>(L->minor);
      const int* perm = static_cast<const int*>(L->Perm);
      out.failed_equation = perm != nullptr ? perm[k] : k;
      out.status = SolveStatus::NotPositiveDefinite;
      out.reason = fmt::format(
          "the stiffness matrix is not positive definite: CHOLMOD met a "
          "non-positive pivot at equation {} (pivot {} of {})",
          out.failed_equation, k, L->n);
      return out;
    }
    info_.nnz_factor = c.lnz;
    info_.pivot_ratio = cholmod_rcond(const_cast<cholmod_factor*>(L), &c);
  } else {
    auto& ldlt = *impl_->ldlt;
    ldlt.factorize(A);
    const Eigen::VectorXd D = ldlt.vectorD();
    const auto& pinv = ldlt.permutationPinv().indices();
    if (D.size() != A.rows()) {
      return {SolveStatus::SolverFailure, "SimplicialLDLT factorization failed"};
    }
    info_.nnz_factor = static_cast<double>(ldlt.matrixL().nestedExpression().nonZeros()) + D.size();
    for (int k = 0; k < D.size(); ++k) {
      if (!(D[k] > 0.0)) {
        out.failed_equation = pinv.size() == D.size() ? pinv[k] : k;
        out.status = D[k] == 0.0 ? SolveStatus::Singular : SolveStatus::NotPositiveDefinite;
        out.reason = fmt::format("the stiffness matrix is {}: LDL' pivot {} = {} at equation {}",
                                 D[k] == 0.0 ? "singular" : "not positive definite", k, D[k],
                                 out.failed_equation);
        return out;
      }
    }
    info_.pivot_ratio = D.size() > 0 ? D.minCoeff() / D.maxCoeff() : 1.0;
  }
  if (!(info_.pivot_ratio >= options_.min_pivot_ratio)) {
    out.status = SolveStatus::Singular;
    out.reason = fmt::format(
        "the stiffness matrix is numerically singular: pivot ratio "
        "estimate {:.3g} < {:.3g} (an unrestrained rigid-body motion or "
        "mechanism)",
        info_.pivot_ratio, options_.min_pivot_ratio);
    return out;
  }
  impl_->factorized = true;
  return out;
}

bool LinearSolver::is_analyzed_for(const SparseMatrix& A) const {
  return impl_->analyzed_ok && pattern_key(A) == impl_->analyzed;
}

SolveOutcome LinearSolver::compute(const SparseMatrix& A) {
  if (!is_analyzed_for(A)) {
    SolveOutcome analyzed = analyze(A);
    if (!analyzed.ok())
      return analyzed;
  }
  return factorize(A);
}

Eigen::MatrixXd LinearSolver::solve(const Eigen::MatrixXd& B) const {
  if (!impl_->factorized) {
    throw std::logic_error("LinearSolver::solve: no successful factorization");
  }
  if (impl_->cholmod)
    return impl_->cholmod->solve(B);
  return impl_->ldlt->solve(B);
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
  if (!impl_->factorized) {
    throw std::logic_error("LinearSolver::solve: no successful factorization");
  }
  if (impl_->cholmod)
    return impl_->cholmod->solve(b);
  return impl_->ldlt->solve(b);
}

}  // namespace cs::solver
