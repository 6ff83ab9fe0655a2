#pragma once
// Runs the cases of one group on one built model: the problem is built and assembled once,
// and each case (algorithm, contact discretization, contact settings) is a contact solve on
// the shared ContactAnalysis, which in turn shares constraint rows and condensations.

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <Eigen/Core>

#include "solver/contact/contact_analysis.hpp"
#include "solver/linear_static.hpp"
#include "solver/stress_recovery.hpp"
#include "suites/problem_setup.hpp"
#include "suites/runner.hpp"

namespace cs::suites {

/// The solver settings a case selects: the study's algorithm and discretization names mapped
/// to the solver's (LMP and PLM both to the Lagrange multiplier method, PLM with tangential
/// multipliers and LMP with a tangential penalty: they differ only with friction), with FKN,
/// FTOLN and the pinball from the case's parameters, and mu, FKT, FTOLT for a friction problem
/// (suites/friction_cases.hpp). Throws SuiteInputError for MPC with friction.
solver::ContactSettings contact_settings(const CaseSpec& spec);

/// The nodal stress recovery a case selects (the Q8 extrapolation rule keeps its default).
solver::StressRecoveryOptions recovery_options(const CaseSpec& spec);

class ProblemExecutor final : public GroupExecutor {
 public:
  /// Builds the problem of `representative` and its elastic analysis (not yet assembled).
  explicit ProblemExecutor(const CaseSpec& representative);
  /// Runs cases on a setup built elsewhere (e.g. a problem in other units,
  /// suites/problem_scaling.hpp): the same sampling and grading as a built case. The cases
  /// run must be of the setup's problem, mesh, element and target (and parameters); their
  /// algorithm, discretization, recovery and contact settings are free, as for a group.
  explicit ProblemExecutor(ProblemSetup setup);
  ~ProblemExecutor() override;

  CaseResult run(const CaseSpec& spec) override;

  /// The setup the cases run on.
  const ProblemSetup& setup() const { return *setup_; }
  /// Cases run after this call recover the whole displacement field. By default a case
  /// recovers it only where its grading reads it (the sampled surface's patches, the contact
  /// rows and, under load control, the support), NaN elsewhere: call this first for
  /// last_displacement(), last_stresses() or vtu_document().
  void recover_whole_field();
  /// The displacement of the last case run (empty if it produced none; see
  /// recover_whole_field()).
  const Eigen::VectorXd& last_displacement() const { return last_u_; }
  /// The nodal stresses of the last case run over the whole mesh, if it produced values
  /// (recovered on first call: a case itself recovers only its sampled surface). Throws
  /// std::logic_error after a case run without recover_whole_field().
  const std::optional<solver::StressField>& last_stresses();
  /// How many contact solves the cases run so far took: a case that only recovers another way,
  /// or whose solve would repeat a recent one (contact_solution), takes none.
  int contact_solves() const { return contact_solves_; }
  /// The model with the displacement and nodal stresses of the last case run as a .vtu
  /// document, with `comment` as an XML comment at its top (none when empty). Throws
  /// std::runtime_error if the last case produced no values.
  std::string vtu_document(std::string_view comment = {});

 private:
  /// The contact solution of `spec`: solved, or the last one when only the recovery differs
  /// (the matrix puts a case's recoveries next to each other), or a recent one of the same
  /// model that solving would repeat step for step (solver::repeats_solve: PLM after LMP
  /// without friction, PM after an AL solve that needed no augmentation; its settings are then
  /// that solve's).
  const solver::ContactResult& contact_solution(const CaseSpec& spec);
  /// One contact solve of the model: under load control, over the load steps, or at once.
  solver::ContactResult solve(const solver::ContactSettings& settings);
  solver::ContactResult solve_with_load_control(const solver::ContactSettings& settings);
  double support_reaction(const Eigen::VectorXd& u) const;
  /// The contact analysis, made on first use, recovering what the cases read.
  solver::ContactAnalysis& contact_analysis();
  /// The sampled surface's elements and patches, found on first use.
  const solver::SurfaceStressRecovery& surface_recovery();
  /// The nodes whose displacement a case reads: the sampled surface's patches and, under load
  /// control, the elements at the support whose reaction is the load.
  std::vector<int> read_nodes();
  /// The load the interface must carry (check_interface), computed once.
  double applied_load();

  std::unique_ptr<ProblemSetup> setup_;  // stable address: the analyses keep references to it
  std::unique_ptr<solver::LinearStaticAnalysis> elastic_;
  std::unique_ptr<solver::ContactAnalysis> contact_;
  Eigen::VectorXd last_u_;
  std::optional<solver::StressField> last_stresses_;  ///< whole mesh, on demand
  solver::StressRecoveryOptions last_recovery_;
  /// The sampled surface's elements and patches, found on the first case.
  std::optional<solver::SurfaceStressRecovery> surface_recovery_;
  /// A solve and the model it belongs to: its case's id but for the algorithm and recovery.
  struct RecentSolution {
    std::string model_key;
    solver::ContactResult result;
  };
  /// The matrix runs one algorithm over every contact discretization (ns, ss, mortar) before
  /// the next, AL before PM and LMP before PLM: the last three solves.
  static constexpr std::size_t kRecentSolutions = 3;
  std::deque<RecentSolution> recent_;
  /// The last case's id (recovery spr) and its solution, one of recent_ (a deque keeps its
  /// other elements in place when the oldest is dropped).
  std::optional<std::pair<std::string, const solver::ContactResult*>> last_contact_;
  int contact_solves_ = 0;
  std::optional<double> applied_load_;
  bool whole_field_ = false;
};

/// The factory the runner uses.
std::unique_ptr<GroupExecutor> make_problem_executor(const CaseSpec& representative);

}  // namespace cs::suites
