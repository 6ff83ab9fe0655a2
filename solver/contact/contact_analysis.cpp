#include "solver/contact/contact_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "solver/contact/active_set_solver.hpp"
#include "solver/contact/augmented_lagrangian.hpp"
#include "solver/contact/contact_error.hpp"
#include "solver/contact/contact_node_results.hpp"
#include "solver/contact/frictional_active_set.hpp"
#include "solver/contact/lagrange_multiplier.hpp"
#include "solver/contact/mortar.hpp"
#include "solver/contact/multipoint_constraint.hpp"
#include "solver/contact/node_to_surface.hpp"
#include "solver/contact/penalty.hpp"
#include "solver/contact/surface_to_surface.hpp"

namespace cs::solver {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The algorithm dispatch: the one place that maps ContactAlgorithm to its implementation.
AlgorithmOutcome run_algorithm(const AlgorithmInput& in) {
  switch (in.settings.algorithm) {
    case ContactAlgorithm::Penalty:
      return solve_penalty(in);
    case ContactAlgorithm::AugmentedLagrangian:
      return solve_augmented_lagrangian(in);
    case ContactAlgorithm::LagrangeMultiplier:
      return solve_lagrange_multiplier(in);
    case ContactAlgorithm::MultipointConstraint:
      return solve_multipoint_constraint(in);
  }
  throw ContactError("contact: unknown algorithm");
}

/// A node's slip counts as held by supports when its free DOFs' share of it is below this.
constexpr double kHeldSlipShare = 1e-9;

/// The frictional algorithm dispatch: the one place that maps ContactAlgorithm to its
/// frictional implementation (validate() rejects MPC with friction).
AlgorithmOutcome run_frictional_algorithm(const FrictionalInput& in) {
  switch (in.settings.algorithm) {
    case ContactAlgorithm::Penalty:
      return solve_penalty_frictional(in);
    case ContactAlgorithm::AugmentedLagrangian:
      return solve_augmented_lagrangian_frictional(in);
    case ContactAlgorithm::LagrangeMultiplier:
      return solve_lagrange_multiplier_frictional(in);
    case ContactAlgorithm::MultipointConstraint:
      break;
  }
  throw ContactError("contact: friction is not defined for MPC (tied constraints have no slip)");
}

/// Throws ContactError unless `previous` is empty or belongs to the rows `set` of kind `kind`.
void check_history(const FrictionHistory& previous, ConstraintRows kind, const ConstraintSet& set) {
  if (previous.empty())
    return;
  if (previous.rows != kind || previous.slip_s.size() != set.n_rows() ||
      previous.force_t.size() != set.n_rows() ||
      previous.node_slip.size() != static_cast<Eigen::Index>(set.nodes.size())) {
    throw ContactError(fmt::format(
        "contact: the friction history of {} {} rows does not belong to the {} {} rows of these "
        "settings",
        previous.slip_s.size(), to_string(previous.rows), set.n_rows(), to_string(kind)));
  }
}

}  // namespace

ConstraintRows constraint_rows(const ContactSettings& s) {
  switch (s.discretization) {
    case ContactDiscretization::NodeToSurface:
      return ConstraintRows::NodeToSurface;
    case ContactDiscretization::Mortar:
      return ConstraintRows::Mortar;
    case ContactDiscretization::SurfaceToSurface:
      return s.algorithm == ContactAlgorithm::Penalty ||
                     s.algorithm == ContactAlgorithm::AugmentedLagrangian
                 ? ConstraintRows::GaussPoints
                 : ConstraintRows::NodalWeightedGaps;
  }
  throw ContactError("contact: unknown discretization");
}

/// Stage 1 of one pinball: the condensation onto the contact DOFs of every row kind.
struct ContactAnalysis::DofStage {
  DofCondensation condensation;
  SolveOutcome outcome;
  std::optional<RecoverySubset> subset;  ///< recover_only_at's, made on first use
  explicit DofStage(CondensationMethod method) : condensation(method) {}
};

/// Stage 2 of one row kind and pinball: the condensation onto its candidate rows.
struct ContactAnalysis::RowStage {
  std::vector<int> candidates;                          ///< row indices within the pinball
  std::vector<int> candidate_of_row;                    ///< row -> index in candidates, or -1
  Eigen::SparseMatrix<double, Eigen::RowMajor> B_free;  ///< candidate rows, free columns
  Eigen::VectorXd g0;     ///< reference gaps incl. prescribed displacements (candidates)
  Eigen::VectorXd rho;    ///< (E / h) w per candidate: regularization and stiffness scale
  Eigen::VectorXd depth;  ///< h per candidate
  ConstraintCondensation condensation;
  SolveOutcome outcome;
  double force_floor = 0.0;
};

ContactAnalysis::ContactAnalysis(LinearStaticAnalysis& elastic, ContactPair pair)
    : elastic_(elastic),
      pair_(std::move(pair)),
      surface_(elastic.model(), pair_.contact_surface, "contact surface"),
      target_(make_target(elastic.model(), pair_.target)) {}

ContactAnalysis::~ContactAnalysis() = default;

const ConstraintSet& ContactAnalysis::constraints(ConstraintRows rows) {
  auto it = constraints_.find(rows);
  if (it != constraints_.end())
    return it->second;
  const int n_dofs = 2 * elastic_.model().mesh.n_nodes();
  ConstraintSet set;
  switch (rows) {
    case ConstraintRows::NodeToSurface:
      set = node_to_surface_constraints(surface_, target_, n_dofs, pair_.gap_normal);
      break;
    case ConstraintRows::GaussPoints:
      set = surface_to_surface_constraints(surface_, target_, n_dofs,
                                           SurfaceToSurfaceRows::GaussPoints, pair_.gap_normal);
      break;
    case ConstraintRows::NodalWeightedGaps:
      set = surface_to_surface_constraints(
          surface_, target_, n_dofs, SurfaceToSurfaceRows::NodalWeightedGaps, pair_.gap_normal);
      break;
    case ConstraintRows::Mortar:
      set = mortar_constraints(surface_, target_, n_dofs, pair_.gap_normal);
      break;
  }
  return constraints_.emplace(rows, std::move(set)).first->second;
}

bool ContactAnalysis::movable(const ConstraintSet& set, int j) const {
  const DofMap& dofs = elastic_.dof_map();
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(set.B, j); e; ++e) {
    if (dofs.equation(static_cast<int>(e.col())) >= 0)
      return true;
  }
  return false;
}

std::vector<int> ContactAnalysis::candidates(const ConstraintSet& set,
                                             const SearchExtent& extent) const {
  const Eigen::VectorXd g_start = set.g0 + set.B * elastic_.dof_map().prescribed_values();
  std::vector<int> rows;
  for (int j = 0; j < set.n_rows(); ++j) {
    // A row whose every DOF is prescribed cannot move: it is no contact candidate.
    if (within_search(g_start[j], set.rows[j].depth_h, extent) && movable(set, j))
      rows.push_back(j);
  }
  return rows;
}

ContactAnalysis::StageKey ContactAnalysis::dof_key(const StageKey& key) {
  return {ConstraintRows::NodeToSurface, key.pinball, key.reach, key.method, key.frictional};
}

void ContactAnalysis::evict_grown_stages(const StageKey& keep) {
  const auto grown_other = [&](const StageKey& k) {
    return k.reach != k.pinball && (k.pinball != keep.pinball || k.reach != keep.reach);
  };
  std::erase_if(row_stages_, [&](const auto& entry) { return grown_other(entry.first); });
  std::erase_if(dof_stages_, [&](const auto& entry) { return grown_other(entry.first); });
}

ContactAnalysis::DofStage& ContactAnalysis::dof_stage(const StageKey& row_key,
                                                      ContactResult& result) {
  const StageKey key = dof_key(row_key);
  auto it = dof_stages_.find(key);
  if (it != dof_stages_.end()) {
    result.timings.condensation_reused = true;
    return *it->second;
  }
  if (key.reach != key.pinball)
    evict_grown_stages(key);
  if (!elastic_.is_assembled())
    elastic_.assemble();
  if (load_f_.size() == 0) {
    load_f_ = elastic_.reduced_load(elastic_.model().loads);
    prescribed_ = elastic_.dof_map().prescribed_values();
  }
  const DofMap& dofs = elastic_.dof_map();
  // The contact DOFs: every free DOF a candidate row of any row kind touches (and, for
  // friction, its tangential twin).
  std::vector<char> touched(dofs.n_free(), 0);
  const auto touch = [&](const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows, int j) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(rows, j); e; ++e) {
      const int eq = dofs.equation(static_cast<int>(e.col()));
      if (eq >= 0)
        touched[eq] = 1;
    }
  };
  for (ConstraintRows rows : {ConstraintRows::NodeToSurface, ConstraintRows::GaussPoints,
                              ConstraintRows::NodalWeightedGaps, ConstraintRows::Mortar}) {
    const ConstraintSet& set = constraints(rows);
    for (int j : candidates(set, key.extent())) {
      touch(set.B, j);
      if (key.frictional)
        touch(set.T, j);
    }
  }
  std::vector<int> contact_dofs, node_of_equation(dofs.n_free());
  for (int eq = 0; eq < dofs.n_free(); ++eq) {
    if (touched[eq])
      contact_dofs.push_back(eq);
    node_of_equation[eq] = dofs.free_dofs()[eq] / 2;
  }
  // The frictionless and the frictional stage are one when their contact DOFs coincide (e.g. a
  // curved or meshed target, whose rows touch both components already): same input, same
  // factorization.
  StageKey twin = key;
  twin.frictional = !key.frictional;
  const auto other = dof_stages_.find(twin);
  if (other != dof_stages_.end() && other->second->condensation.contact_dofs() == contact_dofs) {
    result.timings.condensation_reused = true;
    return *dof_stages_.emplace(key, other->second).first->second;
  }
  auto stage = std::make_shared<DofStage>(key.method);
  stage->outcome = stage->condensation.compute(
      {elastic_.stiffness().K_ff, load_f_, contact_dofs, node_of_equation});
  const CondensationTimings& t = stage->condensation.timings();
  result.timings.condensation_s += t.total();
  result.timings.analyze_s = t.analyze_s;
  result.timings.factorize_s = t.factorize_s;
  result.timings.condense_s += t.condense_s;
  return *dof_stages_.emplace(key, std::move(stage)).first->second;
}

ContactAnalysis::RowStage& ContactAnalysis::row_stage(const StageKey& key, ContactResult& result) {
  auto it = row_stages_.find(key);
  if (it != row_stages_.end()) {
    result.timings.condensation_reused = true;
    return *it->second;
  }
  const ConstraintSet& set = constraints(key.rows);
  auto stage = std::make_unique<RowStage>();
  RowStage& rs = *stage;
  rs.candidates = candidates(set, key.extent());
  if (rs.candidates.empty()) {
    const Eigen::VectorXd g_start = set.g0 + set.B * elastic_.dof_map().prescribed_values();
    double closest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < set.n_rows(); ++j) {
      closest = std::min(closest, std::abs(g_start[j]) / set.rows[j].depth_h);
    }
    throw ContactError(
        fmt::format("contact: the {} never comes within the pinball of contact "
                    "surface '{}' (closest point at {:.3g} h > pinball {} h)",
                    describe(target_), surface_.name(), closest, key.pinball));
  }
  DofStage& ds = dof_stage(key, result);
  fill_row_stage(key, set, rs);
  if (!ds.outcome.ok()) {
    rs.outcome = ds.outcome;
  } else {
    rs.outcome = rs.condensation.compute(ds.condensation, rs.B_free, rs.rho);
    result.timings.condensation_s += rs.condensation.condense_seconds();
    result.timings.condense_s += rs.condensation.condense_seconds();
  }
  return *row_stages_.emplace(key, std::move(stage)).first->second;
}

void ContactAnalysis::fill_row_stage(const StageKey& key, const ConstraintSet& set,
                                     RowStage& rs) const {
  const DofMap& dofs = elastic_.dof_map();
  const Eigen::VectorXd g_start = set.g0 + set.B * dofs.prescribed_values();
  const int m = static_cast<int>(rs.candidates.size());
  const int n_rows = key.frictional ? 2 * m : m;  // friction: the tangential twins follow
  rs.candidate_of_row.assign(set.n_rows(), -1);
  rs.g0.resize(n_rows);
  rs.rho.resize(n_rows);
  rs.depth.resize(m);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int a = 0; a < m; ++a) {
    const int j = rs.candidates[a];
    const ContactConstraint& row = set.rows[j];
    rs.candidate_of_row[j] = a;
    rs.g0[a] = g_start[j];
    rs.rho[a] = row.stiffness_scale();
    rs.depth[a] = row.depth_h;
    rs.force_floor = std::max(rs.force_floor, 1e-12 * row.stiffness_scale() * row.depth_h);
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(set.B, j); e; ++e) {
      const int eq = dofs.equation(static_cast<int>(e.col()));
      if (eq >= 0)
        triplets.emplace_back(a, eq, e.value());
    }
  }
  if (key.frictional) {  // r = -s = -(s0 + T u): the force on the DOFs is -T^T lambda_T
    const Eigen::VectorXd s_start = set.s0 + set.T * dofs.prescribed_values();
    for (int a = 0; a < m; ++a) {
      const int j = rs.candidates[a];
      rs.g0[m + a] = -s_start[j];
      rs.rho[m + a] = rs.rho[a];
      if (tangent_held(set.rows[j]))
        continue;  // an empty row: no shear (frictional_active_set.hpp)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(set.T, j); e; ++e) {
        const int eq = dofs.equation(static_cast<int>(e.col()));
        if (eq >= 0)
          triplets.emplace_back(m + a, eq, -e.value());
      }
    }
  }
  rs.B_free.resize(n_rows, dofs.n_free());
  rs.B_free.setFromTriplets(triplets.begin(), triplets.end());
  rs.B_free.makeCompressed();
}

bool ContactAnalysis::tangent_held(const ContactConstraint& row) const {
  if (row.node < 0)
    return false;
  // The node's own slip (its node-to-surface tangential row) involves no free DOF, but for
  // round-off (a target normal a few 1e-11 off the axis gives the held node's slip a 1e-11
  // share of its free normal DOF).
  const ConstraintSet& ns = constraints_.at(ConstraintRows::NodeToSurface);
  const DofMap& dofs = elastic_.dof_map();
  double all = 0.0, free = 0.0;
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(ns.T, row.node); e; ++e) {
    all = std::max(all, std::abs(e.value()));
    if (dofs.equation(static_cast<int>(e.col())) >= 0)
      free = std::max(free, std::abs(e.value()));
  }
  return free <= kHeldSlipShare * all;
}

void ContactAnalysis::recover_only_at(std::vector<int> nodes) {
  recovered_nodes_ = std::move(nodes);
  for (auto& [key, ds] : dof_stages_)
    ds->subset.reset();
}

std::vector<int> ContactAnalysis::read_equations() {
  const DofMap& dofs = elastic_.dof_map();
  std::vector<char> read(dofs.n_free(), 0);
  const auto mark = [&](int dof) {
    const int eq = dofs.equation(dof);
    if (eq >= 0)
      read[eq] = 1;
  };
  for (int node : recovered_nodes_) {
    mark(2 * node);
    mark(2 * node + 1);
  }
  using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  for (ConstraintRows rows : {ConstraintRows::NodeToSurface, ConstraintRows::GaussPoints,
                              ConstraintRows::NodalWeightedGaps, ConstraintRows::Mortar}) {
    const ConstraintSet& set = constraints(rows);
    for (const RowMajor* m : {&set.B, &set.T}) {
      for (int j = 0; j < m->outerSize(); ++j) {
        for (RowMajor::InnerIterator e(*m, j); e; ++e)
          mark(static_cast<int>(e.col()));
      }
    }
  }
  std::vector<int> out;
  for (int eq = 0; eq < dofs.n_free(); ++eq) {
    if (read[eq])
      out.push_back(eq);
  }
  return out;
}

const RecoverySubset* ContactAnalysis::recovery_subset(const StageKey& key) {
  if (recovered_nodes_.empty())
    return nullptr;
  DofStage& ds = *dof_stages_.at(dof_key(key));
  if (!ds.subset)
    ds.subset = ds.condensation.subset(read_equations());
  return &*ds.subset;
}

void ContactAnalysis::refresh_loads() {
  if (dof_stages_.empty())
    return;
  const Eigen::VectorXd f = elastic_.reduced_load(elastic_.model().loads);
  const Eigen::VectorXd& u_prescribed = elastic_.dof_map().prescribed_values();
  if (u_prescribed != prescribed_) {
    // The reference gaps (and slips) move with prescribed contact DOFs; a changed candidate set
    // needs new stages, an unchanged one only new reference values.
    for (auto& [key, rs] : row_stages_) {
      const ConstraintSet& set = constraints(key.rows);
      if (candidates(set, key.extent()) != rs->candidates) {
        row_stages_.clear();
        dof_stages_.clear();
        load_f_.resize(0);
        return;
      }
      const int m = static_cast<int>(rs->candidates.size());
      const Eigen::VectorXd g_start = set.g0 + set.B * u_prescribed;
      for (int a = 0; a < m; ++a) {
        rs->g0[a] = g_start[rs->candidates[a]];
      }
      if (key.frictional) {
        const Eigen::VectorXd s_start = set.s0 + set.T * u_prescribed;
        for (int a = 0; a < m; ++a)
          rs->g0[m + a] = -s_start[rs->candidates[a]];
      }
    }
    prescribed_ = u_prescribed;
  }
  if (f != load_f_) {
    load_f_ = f;
    const DofStage* updated = nullptr;  // a shared stage appears under both of its keys
    for (auto& [key, ds] : dof_stages_) {
      if (ds->outcome.ok() && ds.get() != updated)
        ds->condensation.update_load(load_f_);
      updated = ds.get();
    }
    for (auto& [key, rs] : row_stages_) {
      const DofStage& ds = *dof_stages_.at(dof_key(key));
      if (rs->outcome.ok())
        rs->condensation.update_load(ds.condensation);
    }
  }
}

AlgorithmOutcome ContactAnalysis::run_frictionless(const ContactSettings& settings,
                                                   const RowStage& cd) const {
  const CondensedProblem problem{cd.condensation.W(), cd.condensation.d(), cd.rho, cd.g0,
                                 cd.force_floor};
  const Eigen::VectorXd kp = settings.fkn * cd.rho;
  const AlgorithmInput input{problem, kp, cd.depth, settings,
                             std::vector<char>(cd.candidates.size(), 1)};
  return run_algorithm(input);
}

AlgorithmOutcome ContactAnalysis::run_frictional(const ContactSettings& settings,
                                                 const FrictionHistory& previous,
                                                 const RowStage& cd) const {
  const int m = static_cast<int>(cd.candidates.size());
  Eigen::VectorXd s_prev = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd t_prev = Eigen::VectorXd::Zero(m);
  if (!previous.empty()) {
    for (int a = 0; a < m; ++a) {
      s_prev[a] = previous.slip_s[cd.candidates[a]];
      t_prev[a] = previous.force_t[cd.candidates[a]];
    }
  }
  const CondensedProblem problem{cd.condensation.W(), cd.condensation.d(), cd.rho, cd.g0,
                                 cd.force_floor};
  const Eigen::VectorXd kp = settings.fkn * cd.rho.head(m);
  std::vector<char> states(2 * m, kStickCode);  // every candidate closed and sticking
  std::fill(states.begin(), states.begin() + m, 1);
  const FrictionalInput input{problem, kp, cd.depth, settings, s_prev, t_prev, states};
  return run_frictional_algorithm(input);
}

ContactResult ContactAnalysis::solve(const ContactSettings& settings) {
  return solve(settings, FrictionHistory{});
}

ContactResult ContactAnalysis::solve(const ContactSettings& settings,
                                     const FrictionHistory& previous) {
  validate(settings);
  const auto start = Clock::now();
  refresh_loads();
  ContactResult result;
  result.settings = settings;
  const ConstraintRows kind = constraint_rows(settings);
  if (constraints_.size() < 4) {  // every row kind: the contact DOFs are their union
    const auto t0 = Clock::now();
    for (ConstraintRows rows : {ConstraintRows::NodeToSurface, ConstraintRows::GaussPoints,
                                ConstraintRows::NodalWeightedGaps, ConstraintRows::Mortar}) {
      constraints(rows);
    }
    result.timings.constraints_s = seconds_since(t0);
  }
  const bool frictional = settings.frictional();
  if (frictional)
    check_history(previous, kind, constraints(kind));
  // The search starts at the pinball and grows while points approach (contact_search.hpp).
  StageKey key{kind, settings.pinball, settings.pinball, settings.condensation, frictional};
  for (SearchReview review = solve_round(settings, previous, key, result); review.grows();
       review = solve_round(settings, previous, key, result)) {
    key.reach = review.reach;
  }
  result.timings.total_s = seconds_since(start);
  return result;
}

SearchReview ContactAnalysis::solve_round(const ContactSettings& settings,
                                          const FrictionHistory& previous, const StageKey& key,
                                          ContactResult& result) {
  const ConstraintSet& set = constraints(key.rows);
  RowStage& cd = row_stage(key, result);
  const DofStage& ds = *dof_stages_.at(dof_key(key));
  result.n_constraints = set.n_rows();
  result.n_candidates = static_cast<int>(cd.candidates.size());
  result.n_contact_dofs = ds.condensation.n_contact_dofs();
  if (!cd.outcome.ok()) {
    result.status = ContactStatus::NotConverged;
    result.failure = ContactFailure::SingularSystem;
    result.reason = cd.outcome.reason;
    result.displacement.resize(0);
    result.nodes.clear();
    return {};
  }

  auto t0 = Clock::now();
  const AlgorithmOutcome out =
      key.frictional ? run_frictional(settings, previous, cd) : run_frictionless(settings, cd);
  result.timings.iterations_s += seconds_since(t0);
  result.status = out.status;
  result.failure = out.failure;
  result.reason = out.reason;
  result.residual = out.residual;
  result.active_set_iterations += out.iterations;
  result.augmentations += out.augmentations;
  if (!out.has_solution())
    return {};
  t0 = Clock::now();
  const SearchReview review = recover_results(settings, previous, key, cd, ds, out, result);
  result.timings.recovery_s += seconds_since(t0);
  return review;
}

SearchReview ContactAnalysis::recover_results(const ContactSettings& settings,
                                              const FrictionHistory& previous, const StageKey& key,
                                              const RowStage& cd, const DofStage& ds,
                                              const AlgorithmOutcome& out, ContactResult& result) {
  const ConstraintSet& set = constraints(key.rows);
  const RecoverySubset* subset = recovery_subset(key);
  const Eigen::VectorXd u_free = cd.condensation.recover(ds.condensation, out.step.mu, subset);
  result.displacement = elastic_.expand(u_free);
  result.displacement_complete = subset == nullptr || subset->whole_field();
  const bool finite =
      result.displacement_complete ? u_free.allFinite() : u_free(subset->equations).allFinite();
  if (!finite) {
    result.displacement.resize(0);
    result.status = ContactStatus::NotConverged;
    result.failure = ContactFailure::NonFinite;
    result.reason = "the recovered displacement is not finite";
    return {};
  }
  // Row quantities over every row (candidates carry the algorithm's forces and flags; a
  // frictional outcome's first m entries are the normal rows').
  const Eigen::VectorXd gap = set.g0 + set.B * result.displacement;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(set.n_rows());
  std::vector<char> active(set.n_rows(), 0);
  for (int a = 0; a < static_cast<int>(cd.candidates.size()); ++a) {
    lambda[cd.candidates[a]] = out.step.lambda[a];
    active[cd.candidates[a]] = out.active.empty() ? 0 : out.active[a];
  }
  const RowState rows{gap, lambda, active, cd.candidate_of_row};
  SearchReview review;
  if (settings.algorithm != ContactAlgorithm::MultipointConstraint && result.converged()) {
    const Eigen::VectorXd g_start = set.g0 + set.B * elastic_.dof_map().prescribed_values();
    const std::function<bool(int)> can_move = [&](int j) { return movable(set, j); };
    review = review_search(set, {gap, g_start, cd.candidate_of_row, can_move}, key.extent());
    if (review.grows())
      return review;  // solved again over the grown search: these values are not the answer
    if (!review.miss.empty()) {
      result.status = ContactStatus::NotConverged;
      result.failure = ContactFailure::ContactBeyondPinball;
      result.reason = review.miss;
    }
  }
  const Eigen::VectorXd node_gap =
      set.nodal
          ? Eigen::VectorXd(gap.head(static_cast<Eigen::Index>(set.nodes.size())))
          : Eigen::VectorXd(constraints(ConstraintRows::NodeToSurface).g0 +
                            constraints(ConstraintRows::NodeToSurface).B * result.displacement);
  result.nodes = node_results(set, rows, node_gap);
  result.max_tension = largest_tension(set, lambda);
  if (settings.frictional())
    recover_friction(previous, set, cd, out, rows, result);
  for (const ContactNodeResult& r : result.nodes) {
    if (r.closed)
      result.contact_extent = std::max(result.contact_extent, r.position.x());
    result.peak_pressure = std::max(result.peak_pressure, r.pressure);
    result.total_normal_force += r.force;
    result.peak_shear = std::max(result.peak_shear, std::abs(r.shear));
  }
  return review;
}

void ContactAnalysis::recover_friction(const FrictionHistory& previous, const ConstraintSet& set,
                                       const RowStage& cd, const AlgorithmOutcome& out,
                                       const RowState& rows, ContactResult& result) {
  const int m = static_cast<int>(cd.candidates.size());
  FrictionHistory& h = result.friction_history;
  h.rows = constraint_rows(result.settings);
  h.slip_s = set.s0 + set.T * result.displacement;
  h.force_t = Eigen::VectorXd::Zero(set.n_rows());
  std::vector<FrictionState> state(set.n_rows(), FrictionState::Open);
  for (int a = 0; a < m; ++a) {
    h.force_t[cd.candidates[a]] = out.step.lambda[m + a];
    state[cd.candidates[a]] = out.friction[a];
  }
  const ConstraintSet& ns = constraints(ConstraintRows::NodeToSurface);
  const Eigen::Index n_nodes = static_cast<Eigen::Index>(set.nodes.size());
  h.node_slip = set.nodal ? Eigen::VectorXd(h.slip_s.head(n_nodes))
                          : Eigen::VectorXd(ns.s0 + ns.T * result.displacement);
  const Eigen::VectorXd node_slip_prev =
      previous.empty() ? Eigen::VectorXd(Eigen::VectorXd::Zero(n_nodes)) : previous.node_slip;
  add_friction_results(set, rows, {h.slip_s, h.force_t, state, h.node_slip, node_slip_prev},
                       result.nodes);
  if (!result.converged())
    result.friction_history = FrictionHistory{};  // not a state to continue from
}

std::vector<ContactResult> ContactAnalysis::solve_steps(const ContactSettings& settings,
                                                        const std::vector<LoadStep>& steps) {
  validate(settings);
  std::vector<ContactResult> results;
  FrictionHistory history;
  for (const LoadStep& step : steps) {
    if (step.apply)
      step.apply();
    elastic_.update_prescribed_values();
    results.push_back(solve(settings, history));
    if (!results.back().converged())
      break;
    history = results.back().friction_history;
  }
  return results;
}

ContactResult solve_contact(const Model& model, const ContactPair& pair,
                            const ContactSettings& settings) {
  validate(settings);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, pair);
  return contact.solve(settings);
}

}  // namespace cs::solver
