#include "solver/linear_static.hpp"

#include <chrono>

#include <fmt/format.h>

#include "solver/load_vector.hpp"
#include "solver/rigid_body_modes.hpp"

namespace cs::solver {
namespace {

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

const Model& validated(const Model& model) {
  validate(model);
  return model;
}

Timings difference(const Timings& after, const Timings& before) {
  return {after.setup_s - before.setup_s, after.assembly_s - before.assembly_s,
          after.analyze_s - before.analyze_s, after.factorize_s - before.factorize_s,
          after.solve_s - before.solve_s};
}

}  // namespace

LinearStaticAnalysis::LinearStaticAnalysis(const Model& model, LinearStaticOptions options)
    : model_(validated(model)),
      options_(options),
      dofs_(model_),
      assembler_(model_, dofs_),
      solver_(options.linear_solver) {
  // The DOFs of a node are one supervariable of the fill-reducing ordering.
  std::vector<int> node_of_equation(dofs_.n_free());
  for (int k = 0; k < dofs_.n_free(); ++k)
    node_of_equation[k] = dofs_.free_dofs()[k] / 2;
  solver_.set_supervariables(std::move(node_of_equation));
  timings_.setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - created_).count();
}

void LinearStaticAnalysis::assemble() {
  const Stopwatch clock;
  assembler_.assemble(K_);
  assembled_ = true;
  factorized_ = false;
  timings_.assembly_s += clock.seconds();
}

void LinearStaticAnalysis::update_prescribed_values() {
  dofs_.update_prescribed_values(model_);
}

SolveOutcome LinearStaticAnalysis::check_rigid_body_modes() const {
  const std::vector<UnrestrainedBody> free = find_unrestrained_bodies(model_, dofs_);
  if (free.empty())
    return {SolveStatus::Ok, ""};
  return {SolveStatus::Singular,
          "singular stiffness: " + describe(free) + " (prescribe displacements that hold it)"};
}

void LinearStaticAnalysis::explain_failure(SolveOutcome& outcome) const {
  const int eq = outcome.failed_equation;
  if (eq < 0 || eq >= dofs_.n_free())
    return;
  const int dof = dofs_.free_dofs()[eq];
  const int node = dof / 2;
  std::string body = "no element";
  const Mesh& mesh = model_.mesh;
  for (int e = 0; e < mesh.n_elements() && body == "no element"; ++e) {
    for (int a = 0; a < mesh.n_element_nodes(); ++a) {
      if (mesh.elements[e][a] == node) {
        body = fmt::format("body '{}'", mesh.body_names[mesh.element_body[e]]);
        break;
      }
    }
  }
  outcome.reason +=
      fmt::format(" = node {} component {} ({}, at ({:.6g}, {:.6g}))", node,
                  dof % 2 == 0 ? "x|r" : "z", body, mesh.nodes[node].x(), mesh.nodes[node].y());
}

SolveOutcome LinearStaticAnalysis::factorize_matrix(const Eigen::SparseMatrix<double>& A) {
  factorized_ = false;
  if (!solver_.is_analyzed_for(A)) {
    const Stopwatch clock;
    last_factorization_ = solver_.analyze(A);
    timings_.analyze_s += clock.seconds();
    if (!last_factorization_.ok())
      return last_factorization_;
  }
  const Stopwatch clock;
  last_factorization_ = solver_.factorize(A);
  timings_.factorize_s += clock.seconds();
  if (!last_factorization_.ok()) {
    explain_failure(last_factorization_);
    return last_factorization_;
  }
  factorized_ = true;
  return last_factorization_;
}

SolveOutcome LinearStaticAnalysis::factorize() {
  if (!assembled_)
    assemble();
  factorized_extra_ = false;
  if (options_.check_rigid_body_modes) {
    SolveOutcome check = check_rigid_body_modes();
    if (!check.ok()) {
      factorized_ = false;
      last_factorization_ = check;
      return check;
    }
  }
  return factorize_matrix(K_.K_ff);
}

SolveOutcome LinearStaticAnalysis::factorize_with(const Eigen::SparseMatrix<double>& P_lower) {
  if (!assembled_)
    assemble();
  if (P_lower.rows() != K_.K_ff.rows() || P_lower.cols() != K_.K_ff.cols()) {
    return {SolveStatus::SolverFailure,
            fmt::format("factorize_with: P is {} x {}, K_ff is {} x {}", P_lower.rows(),
                        P_lower.cols(), K_.K_ff.rows(), K_.K_ff.cols())};
  }
  const Eigen::SparseMatrix<double> A = K_.K_ff + P_lower;
  factorized_extra_ = true;
  return factorize_matrix(A);
}

Eigen::MatrixXd LinearStaticAnalysis::solve_reduced(const Eigen::MatrixXd& B) const {
  return solver_.solve(B);
}

Eigen::VectorXd LinearStaticAnalysis::external_load(const LoadCase& loads) const {
  validate(model_, loads);
  return assemble_load_vector(model_, loads);
}

namespace {

Eigen::VectorXd reduced_from_external(const DofMap& dofs, const StiffnessMatrices& K,
                                      const Eigen::VectorXd& f_external) {
  Eigen::VectorXd u_c(dofs.n_constrained());
  for (int k = 0; k < dofs.n_constrained(); ++k) {
    u_c[k] = dofs.prescribed_values()[dofs.constrained_dofs()[k]];
  }
  const Eigen::VectorXd coupling = K.K_cg.transpose() * u_c;  // K_gc u_c, global
  return dofs.restrict_to_free(f_external - coupling);
}

}  // namespace

Eigen::VectorXd LinearStaticAnalysis::reduced_load(const LoadCase& loads) const {
  return reduced_from_external(dofs_, K_, external_load(loads));
}

Eigen::VectorXd LinearStaticAnalysis::reactions(const Eigen::VectorXd& u,
                                                const Eigen::VectorXd& f_external) const {
  const Eigen::VectorXd Ku_c = K_.K_cg * u;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs_.n_dofs());
  for (int k = 0; k < dofs_.n_constrained(); ++k) {
    const int dof = dofs_.constrained_dofs()[k];
    r[dof] = Ku_c[k] - f_external[dof];
  }
  return r;
}

std::vector<LinearStaticResult> LinearStaticAnalysis::solve(
    const std::vector<LoadCase>& load_cases) {
  const Timings before = timings_;
  std::vector<LinearStaticResult> results(load_cases.size());
  // Load vectors (validated) before anything expensive.
  std::vector<Eigen::VectorXd> f_external;
  {
    const Stopwatch clock;
    for (const LoadCase& loads : load_cases)
      f_external.push_back(external_load(loads));
    timings_.assembly_s += clock.seconds();
  }
  if (!assembled_)
    assemble();
  if (!factorized_ || factorized_extra_)
    factorize();
  if (!factorized_) {
    for (auto& r : results) {
      r.outcome = last_factorization_;
      r.timings = difference(timings_, before);
      r.factorization = solver_.info();
    }
    return results;
  }
  const Stopwatch clock;
  Eigen::MatrixXd rhs(dofs_.n_free(), static_cast<Eigen::Index>(load_cases.size()));
  for (std::size_t i = 0; i < load_cases.size(); ++i) {
    rhs.col(static_cast<Eigen::Index>(i)) = reduced_from_external(dofs_, K_, f_external[i]);
  }
  const Eigen::MatrixXd u_free = solver_.solve(rhs);
  for (std::size_t i = 0; i < load_cases.size(); ++i) {
    LinearStaticResult& r = results[i];
    r.displacement = dofs_.expand(u_free.col(static_cast<Eigen::Index>(i)));
    r.reaction = reactions(r.displacement, f_external[i]);
    if (!r.displacement.allFinite()) {
      r.outcome = {SolveStatus::SolverFailure, "the solution is not finite", -1};
      r.displacement.resize(0);
      r.reaction.resize(0);
    } else {
      r.outcome = {SolveStatus::Ok, "", -1};
    }
    r.factorization = solver_.info();
  }
  timings_.solve_s += clock.seconds();
  for (auto& r : results)
    r.timings = difference(timings_, before);
  return results;
}

LinearStaticResult LinearStaticAnalysis::solve() {
  return std::move(solve(std::vector<LoadCase>{model_.loads}).front());
}

LinearStaticResult solve_linear_static(const Model& model, LinearStaticOptions options) {
  LinearStaticAnalysis analysis(model, options);
  LinearStaticResult result = analysis.solve();
  result.timings.setup_s = analysis.timings().setup_s;
  return result;
}

}  // namespace cs::solver
