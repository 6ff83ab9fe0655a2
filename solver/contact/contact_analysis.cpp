#include "solver/contact/contact_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "solver/contact/active_set_solver.hpp"
#include "solver/contact/augmented_lagrangian.hpp"
#include "solver/contact/contact_error.hpp"
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

/// A gap this far below zero (relative to the element depth) counts as a penetration of a
/// point outside the pinball.
constexpr double kPinballPenetration = 1e-10;

/// A candidate whose |gap| is below this (relative to the element depth) touches the target.
constexpr double kTouchingGap = 1e-10;

/// The state of every row of a constraint set after a solve.
struct RowState {
  const Eigen::VectorXd& gap;                ///< g = g0 + B u
  const Eigen::VectorXd& lambda;             ///< force (0 outside the candidates)
  const std::vector<char>& active;           ///< the algorithm's last active flags
  const std::vector<int>& candidate_of_row;  ///< -1 outside the pinball
};

/// A row outside the pinball never acts: if it penetrates, the answer cannot be trusted.
void check_pinball(const ConstraintSet& set, const RowState& rows, double pinball,
                   ContactResult& result) {
  for (int j = 0; j < set.n_rows(); ++j) {
    if (rows.candidate_of_row[j] < 0 && rows.gap[j] < -kPinballPenetration * set.rows[j].depth_h) {
      result.status = ContactStatus::NotConverged;
      result.failure = ContactFailure::ContactBeyondPinball;
      result.reason = fmt::format(
          "the contact point at ({:.6g}, {:.6g}) is outside the pinball ({} h) but penetrates "
          "the target by {:.3g}; increase the pinball",
          set.rows[j].position.x(), set.rows[j].position.y(), pinball, -rows.gap[j]);
      return;
    }
  }
}

/// Per-node results, sorted by position. The pressure of a node is its multiplier coefficient
/// lambda / w (weighted rows: mortar, ss with LM/MPC) or its nodal force over its consistent
/// weight (ns; ss Gauss rows, whose forces are shared out with N_a); a node whose consistent
/// weight vanishes reports its neighbour's.
std::vector<ContactNodeResult> node_results(const ConstraintSet& set, const RowState& rows,
                                            const Eigen::VectorXd& node_gap) {
  const int n_nodes = static_cast<int>(set.nodes.size());
  std::vector<ContactNodeResult> nodes(n_nodes);
  std::vector<double> force(n_nodes, 0.0);
  for (int j = 0; j < set.n_rows(); ++j) {
    const ContactConstraint& row = set.rows[j];
    const bool candidate = rows.candidate_of_row[j] >= 0;
    // Closed: active, or a candidate lying on the target (a tie lambda = g = 0 that the active
    // set may resolve either way, e.g. a node that carries no consistent force).
    const bool closed =
        rows.active[j] != 0 || (candidate && std::abs(rows.gap[j]) <= kTouchingGap * row.depth_h);
    for (int s = 0; s < row.n_shares; ++s) {
      const int i = row.share_nodes[s];
      force[i] += row.shares[s] * rows.lambda[j];
      if (row.shares[s] != 0.0) {
        nodes[i].closed = nodes[i].closed || closed;
        nodes[i].candidate = nodes[i].candidate || candidate;
      }
    }
  }
  for (int i = 0; i < n_nodes; ++i) {
    const ContactNode& n = set.nodes[i];
    ContactNodeResult& r = nodes[i];
    r.node = n.node;
    r.position = n.position;
    r.gap = node_gap[i];
    r.penetration = std::max(0.0, -r.gap);
    if (set.weighted) {
      r.pressure = rows.lambda[i] / set.rows[i].weight_w;  // the coefficient p_a
    } else if (!n.degenerate()) {
      r.pressure = force[i] / n.weight_w;
    }
  }
  if (!set.weighted) {
    for (int i = 0; i < n_nodes; ++i) {
      const int nb = set.nodes[i].pressure_neighbour;
      if (set.nodes[i].degenerate() && nb >= 0)
        nodes[i].pressure = nodes[nb].pressure;
    }
  }
  std::sort(nodes.begin(), nodes.end(), [](const ContactNodeResult& a, const ContactNodeResult& b) {
    return a.position.x() != b.position.x() ? a.position.x() < b.position.x()
                                            : a.position.y() < b.position.y();
  });
  return nodes;
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
      set = node_to_surface_constraints(surface_, target_, n_dofs);
      break;
    case ConstraintRows::GaussPoints:
      set = surface_to_surface_constraints(surface_, target_, n_dofs,
                                           SurfaceToSurfaceRows::GaussPoints);
      break;
    case ConstraintRows::NodalWeightedGaps:
      set = surface_to_surface_constraints(surface_, target_, n_dofs,
                                           SurfaceToSurfaceRows::NodalWeightedGaps);
      break;
    case ConstraintRows::Mortar:
      set = mortar_constraints(surface_, target_, n_dofs);
      break;
  }
  return constraints_.emplace(rows, std::move(set)).first->second;
}

std::vector<int> ContactAnalysis::candidates(const ConstraintSet& set, double pinball) const {
  const DofMap& dofs = elastic_.dof_map();
  const Eigen::VectorXd g_start = set.g0 + set.B * dofs.prescribed_values();
  std::vector<int> rows;
  for (int j = 0; j < set.n_rows(); ++j) {
    if (!(std::abs(g_start[j]) <= pinball * set.rows[j].depth_h))
      continue;
    // A row whose every DOF is prescribed cannot move: it is no contact candidate.
    bool movable = false;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(set.B, j); e && !movable;
         ++e) {
      movable = dofs.equation(static_cast<int>(e.col())) >= 0;
    }
    if (movable)
      rows.push_back(j);
  }
  return rows;
}

ContactAnalysis::DofStage& ContactAnalysis::dof_stage(double pinball, CondensationMethod method,
                                                      ContactResult& result) {
  const auto key = std::make_pair(pinball, method);
  auto it = dof_stages_.find(key);
  if (it != dof_stages_.end()) {
    result.timings.condensation_reused = true;
    return *it->second;
  }
  if (!elastic_.is_assembled())
    elastic_.assemble();
  if (load_f_.size() == 0) {
    load_f_ = elastic_.reduced_load(elastic_.model().loads);
    prescribed_ = elastic_.dof_map().prescribed_values();
  }
  const DofMap& dofs = elastic_.dof_map();
  // The contact DOFs: every free DOF a candidate row of any row kind touches.
  std::vector<char> touched(dofs.n_free(), 0);
  for (ConstraintRows rows : {ConstraintRows::NodeToSurface, ConstraintRows::GaussPoints,
                              ConstraintRows::NodalWeightedGaps, ConstraintRows::Mortar}) {
    const ConstraintSet& set = constraints(rows);
    for (int j : candidates(set, pinball)) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(set.B, j); e; ++e) {
        const int eq = dofs.equation(static_cast<int>(e.col()));
        if (eq >= 0)
          touched[eq] = 1;
      }
    }
  }
  std::vector<int> contact_dofs, node_of_equation(dofs.n_free());
  for (int eq = 0; eq < dofs.n_free(); ++eq) {
    if (touched[eq])
      contact_dofs.push_back(eq);
    node_of_equation[eq] = dofs.free_dofs()[eq] / 2;
  }
  auto stage = std::make_unique<DofStage>(method);
  stage->outcome = stage->condensation.compute(
      {elastic_.stiffness().K_ff, load_f_, contact_dofs, node_of_equation});
  const CondensationTimings& t = stage->condensation.timings();
  result.timings.condensation_s += t.total();
  result.timings.analyze_s = t.analyze_s;
  result.timings.factorize_s = t.factorize_s;
  result.timings.condense_s += t.condense_s;
  return *dof_stages_.emplace(key, std::move(stage)).first->second;
}

ContactAnalysis::RowStage& ContactAnalysis::row_stage(ConstraintRows rows, double pinball,
                                                      CondensationMethod method,
                                                      ContactResult& result) {
  const auto key = std::make_tuple(rows, pinball, method);
  auto it = row_stages_.find(key);
  if (it != row_stages_.end()) {
    result.timings.condensation_reused = true;
    return *it->second;
  }
  const ConstraintSet& set = constraints(rows);
  auto stage = std::make_unique<RowStage>();
  RowStage& rs = *stage;
  rs.candidates = candidates(set, pinball);
  if (rs.candidates.empty()) {
    const Eigen::VectorXd g_start = set.g0 + set.B * elastic_.dof_map().prescribed_values();
    double closest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < set.n_rows(); ++j) {
      closest = std::min(closest, std::abs(g_start[j]) / set.rows[j].depth_h);
    }
    throw ContactError(
        fmt::format("contact: the {} never comes within the pinball of contact "
                    "surface '{}' (closest point at {:.3g} h > pinball {} h)",
                    describe(target_), surface_.name(), closest, pinball));
  }
  DofStage& ds = dof_stage(pinball, method, result);
  const DofMap& dofs = elastic_.dof_map();
  const Eigen::VectorXd g_start = set.g0 + set.B * dofs.prescribed_values();
  const int m = static_cast<int>(rs.candidates.size());
  rs.candidate_of_row.assign(set.n_rows(), -1);
  rs.g0.resize(m);
  rs.rho.resize(m);
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
  rs.B_free.resize(m, dofs.n_free());
  rs.B_free.setFromTriplets(triplets.begin(), triplets.end());
  rs.B_free.makeCompressed();
  if (!ds.outcome.ok()) {
    rs.outcome = ds.outcome;
  } else {
    rs.outcome = rs.condensation.compute(ds.condensation, rs.B_free, rs.rho);
    result.timings.condensation_s += rs.condensation.condense_seconds();
    result.timings.condense_s += rs.condensation.condense_seconds();
  }
  return *row_stages_.emplace(key, std::move(stage)).first->second;
}

void ContactAnalysis::refresh_loads() {
  if (dof_stages_.empty())
    return;
  const Eigen::VectorXd f = elastic_.reduced_load(elastic_.model().loads);
  const Eigen::VectorXd& u_prescribed = elastic_.dof_map().prescribed_values();
  if (u_prescribed != prescribed_) {
    // The reference gaps move with prescribed contact DOFs; a changed candidate set needs new
    // stages, an unchanged one only new gaps.
    for (auto& [key, rs] : row_stages_) {
      const ConstraintSet& set = constraints(std::get<0>(key));
      if (candidates(set, std::get<1>(key)) != rs->candidates) {
        row_stages_.clear();
        dof_stages_.clear();
        load_f_.resize(0);
        return;
      }
      const Eigen::VectorXd g_start = set.g0 + set.B * u_prescribed;
      for (int a = 0; a < static_cast<int>(rs->candidates.size()); ++a) {
        rs->g0[a] = g_start[rs->candidates[a]];
      }
    }
    prescribed_ = u_prescribed;
  }
  if (f != load_f_) {
    load_f_ = f;
    for (auto& [key, ds] : dof_stages_) {
      if (ds->outcome.ok())
        ds->condensation.update_load(load_f_);
    }
    for (auto& [key, rs] : row_stages_) {
      const DofStage& ds = *dof_stages_.at(std::make_pair(std::get<1>(key), std::get<2>(key)));
      if (rs->outcome.ok())
        rs->condensation.update_load(ds.condensation);
    }
  }
}

ContactResult ContactAnalysis::solve(const ContactSettings& settings) {
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
  const ConstraintSet& set = constraints(kind);
  RowStage& cd = row_stage(kind, settings.pinball, settings.condensation, result);
  const DofStage& ds = *dof_stages_.at(std::make_pair(settings.pinball, settings.condensation));
  result.n_constraints = set.n_rows();
  result.n_candidates = static_cast<int>(cd.candidates.size());
  result.n_contact_dofs = ds.condensation.n_contact_dofs();
  if (!cd.outcome.ok()) {
    result.status = ContactStatus::NotConverged;
    result.failure = ContactFailure::SingularSystem;
    result.reason = cd.outcome.reason;
    result.timings.total_s = seconds_since(start);
    return result;
  }

  auto t0 = Clock::now();
  const CondensedProblem problem{cd.condensation.W(), cd.condensation.d(), cd.rho, cd.g0,
                                 cd.force_floor};
  const Eigen::VectorXd kp = settings.fkn * cd.rho;
  const AlgorithmInput input{problem, kp, cd.depth, settings,
                             std::vector<char>(cd.candidates.size(), 1)};
  const AlgorithmOutcome out = run_algorithm(input);
  result.timings.iterations_s = seconds_since(t0);
  result.status = out.status;
  result.failure = out.failure;
  result.reason = out.reason;
  result.residual = out.residual;
  result.active_set_iterations = out.iterations;
  result.augmentations = out.augmentations;
  if (!out.has_solution()) {
    result.timings.total_s = seconds_since(start);
    return result;
  }

  t0 = Clock::now();
  const Eigen::VectorXd u_free = cd.condensation.recover(ds.condensation, out.step.mu);
  result.displacement = elastic_.expand(u_free);
  if (!result.displacement.allFinite()) {
    result.displacement.resize(0);
    result.status = ContactStatus::NotConverged;
    result.failure = ContactFailure::NonFinite;
    result.reason = "the recovered displacement is not finite";
    result.timings.total_s = seconds_since(start);
    return result;
  }
  // Row quantities over every row (candidates carry the algorithm's forces and flags).
  const Eigen::VectorXd gap = set.g0 + set.B * result.displacement;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(set.n_rows());
  std::vector<char> active(set.n_rows(), 0);
  for (int a = 0; a < static_cast<int>(cd.candidates.size()); ++a) {
    lambda[cd.candidates[a]] = out.step.lambda[a];
    active[cd.candidates[a]] = out.active.empty() ? 0 : out.active[a];
  }
  const RowState rows{gap, lambda, active, cd.candidate_of_row};
  if (settings.algorithm != ContactAlgorithm::MultipointConstraint && result.converged()) {
    check_pinball(set, rows, settings.pinball, result);
  }
  const Eigen::VectorXd node_gap =
      set.nodal
          ? Eigen::VectorXd(gap.head(static_cast<Eigen::Index>(set.nodes.size())))
          : Eigen::VectorXd(constraints(ConstraintRows::NodeToSurface).g0 +
                            constraints(ConstraintRows::NodeToSurface).B * result.displacement);
  result.nodes = node_results(set, rows, node_gap);
  for (const ContactNodeResult& r : result.nodes) {
    if (r.closed)
      result.contact_extent = std::max(result.contact_extent, r.position.x());
    result.peak_pressure = std::max(result.peak_pressure, r.pressure);
  }
  result.timings.recovery_s = seconds_since(t0);
  result.timings.total_s = seconds_since(start);
  return result;
}

ContactResult solve_contact(const Model& model, const ContactPair& pair,
                            const ContactSettings& settings) {
  validate(settings);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, pair);
  return contact.solve(settings);
}

}  // namespace cs::solver
