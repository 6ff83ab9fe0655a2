#include "suites/problem_executor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/contact/repeated_solve.hpp"
#include "solver/io/vtu_writer.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "suites/friction_cases.hpp"
#include "suites/friction_sampling.hpp"
#include "suites/interface_checks.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/suite_error.hpp"
#include "suites/surface_sampling.hpp"

namespace cs::suites {
namespace {

using solver::ContactAlgorithm;
using solver::ContactDiscretization;

ContactAlgorithm to_solver(Algorithm a) {
  switch (a) {
    case Algorithm::AL:
      return ContactAlgorithm::AugmentedLagrangian;
    case Algorithm::PM:
      return ContactAlgorithm::Penalty;
    case Algorithm::LMP:
    case Algorithm::PLM:
      return ContactAlgorithm::LagrangeMultiplier;
    case Algorithm::MPC:
      return ContactAlgorithm::MultipointConstraint;
  }
  throw SuiteInputError("unknown algorithm");
}

ContactDiscretization to_solver(ContactKind c) {
  switch (c) {
    case ContactKind::ns:
      return ContactDiscretization::NodeToSurface;
    case ContactKind::ss:
      return ContactDiscretization::SurfaceToSurface;
    case ContactKind::mortar:
      return ContactDiscretization::Mortar;
  }
  throw SuiteInputError("unknown contact discretization");
}

}  // namespace

solver::ContactSettings contact_settings(const CaseSpec& spec) {
  const auto& specs = problem_descriptor(spec.problem).parameters;
  const Parameters params(specs, spec.overrides, to_string(spec.problem));
  solver::ContactSettings s;
  s.algorithm = to_solver(spec.algorithm);
  s.discretization = to_solver(spec.contact);
  s.fkn = params.get("fkn");
  s.ftoln = params.get("ftoln");
  s.pinball = params.get("pinball");
  apply_friction(spec, specs, params, s);
  return s;
}

solver::StressRecoveryOptions recovery_options(const CaseSpec& spec) {
  solver::StressRecoveryOptions options;
  options.method = spec.recovery == Recovery::spr
                       ? solver::StressRecoveryMethod::PatchRecovered
                       : solver::StressRecoveryMethod::ExtrapolatedAveraged;
  return options;
}

ProblemExecutor::ProblemExecutor(const CaseSpec& representative)
    : ProblemExecutor(build_problem(representative)) {}

ProblemExecutor::ProblemExecutor(ProblemSetup setup)
    : setup_(std::make_unique<ProblemSetup>(std::move(setup))),
      elastic_(std::make_unique<solver::LinearStaticAnalysis>(setup_->model)) {}

ProblemExecutor::~ProblemExecutor() = default;

double ProblemExecutor::support_reaction(const Eigen::VectorXd& u) const {
  const Eigen::VectorXd r = elastic_->reactions(u, elastic_->external_load(setup_->model.loads));
  double total = 0.0;
  for (int node : solver::node_set(setup_->model.mesh, setup_->load_control->reaction_set)) {
    total -= r[2 * node + 1];  // the support pushes back against the contact force
  }
  return total;
}

solver::ContactResult ProblemExecutor::solve_with_load_control(
    const solver::ContactSettings& settings) {
  // Secant iterations on the support's advance delta until it carries the target load.
  const RigidLoadControl& control = *setup_->load_control;
  constexpr int kMaxSteps = 30;
  constexpr double kLoadTolerance = 1e-10;  // relative; the answer is linear in delta per set
  int iterations = 0, augmentations = 0;
  // One ContactAnalysis for every step (and every case of the group): a changed advance is a
  // changed prescribed value, which it picks up with one forward solve, not a new condensation.
  solver::ContactAnalysis& contact = contact_analysis();
  auto attempt = [&](double delta, double& load) {
    *control.delta = delta;
    elastic_->update_prescribed_values();
    solver::ContactResult r = contact.solve(settings);
    iterations += r.active_set_iterations;
    augmentations += r.augmentations;
    load = r.displacement.size() > 0 ? support_reaction(r.displacement) : std::nan("");
    return r;
  };
  double d0 = control.delta_guess, f0 = 0.0;
  solver::ContactResult r = attempt(d0, f0);
  if (!(f0 > 0.0))
    f0 = 0.0;
  double d1 = f0 > 0.0 ? d0 * control.target_load / f0 : 2.0 * d0, f1 = 0.0;
  for (int step = 0; step < kMaxSteps; ++step) {
    r = attempt(d1, f1);
    if (r.status != solver::ContactStatus::Converged || !std::isfinite(f1))
      break;
    if (std::abs(f1 - control.target_load) <= kLoadTolerance * control.target_load) {
      r.active_set_iterations = iterations;
      r.augmentations = augmentations;
      return r;
    }
    const double slope = (f1 - f0) / (d1 - d0);
    if (!(slope > 0.0) || !std::isfinite(slope))
      break;
    d0 = d1, f0 = f1;
    d1 = d1 + (control.target_load - f1) / slope;
  }
  r.active_set_iterations = iterations;
  r.augmentations = augmentations;
  if (r.status == solver::ContactStatus::Converged) {
    r.status = solver::ContactStatus::NotConverged;
    r.reason = fmt::format("rigid punch load control: load {:.6g} vs target {:.6g}", f1,
                           control.target_load);
  }
  return r;
}

void ProblemExecutor::recover_whole_field() {
  whole_field_ = true;
  last_contact_.reset();
  recent_.clear();  // partial fields
  if (contact_)
    contact_->recover_only_at({});
}

solver::ContactAnalysis& ProblemExecutor::contact_analysis() {
  if (!contact_) {
    contact_ = std::make_unique<solver::ContactAnalysis>(*elastic_, setup_->pair);
    if (!whole_field_)
      contact_->recover_only_at(read_nodes());
  }
  return *contact_;
}

const solver::SurfaceStressRecovery& ProblemExecutor::surface_recovery() {
  if (!surface_recovery_)
    surface_recovery_.emplace(setup_->model, kSampledSurface);
  return *surface_recovery_;
}

std::vector<int> ProblemExecutor::read_nodes() {
  std::vector<int> nodes = surface_recovery().nodes_read();
  if (setup_->load_control) {
    const solver::Mesh& mesh = setup_->model.mesh;
    std::vector<char> support(mesh.n_nodes(), 0);
    for (int node : solver::node_set(mesh, setup_->load_control->reaction_set))
      support[node] = 1;
    const int nen = mesh.n_element_nodes();
    for (const auto& element : mesh.elements) {
      if (std::any_of(element.begin(), element.begin() + nen, [&](int n) { return support[n]; }))
        nodes.insert(nodes.end(), element.begin(), element.begin() + nen);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

const solver::ContactResult& ProblemExecutor::contact_solution(const CaseSpec& spec) {
  CaseSpec key_spec = spec;
  key_spec.recovery = Recovery::spr;  // post-processing: the same contact solution
  const std::string key = case_id(key_spec);
  if (last_contact_ && last_contact_->first == key)
    return *last_contact_->second;
  const solver::ContactSettings settings = contact_settings(spec);
  key_spec.algorithm = Algorithm::AL;  // the model and its parameters: what the solves share
  const std::string model_key = case_id(key_spec);
  auto earlier = std::find_if(recent_.begin(), recent_.end(), [&](const RecentSolution& r) {
    return r.model_key == model_key && solver::repeats_solve(settings, r.result);
  });
  if (earlier == recent_.end()) {
    ++contact_solves_;
    recent_.push_back({model_key, solve(settings)});
    if (recent_.size() > kRecentSolutions)
      recent_.pop_front();
    earlier = std::prev(recent_.end());
  }
  last_contact_.emplace(key, &earlier->result);
  return earlier->result;
}

solver::ContactResult ProblemExecutor::solve(const solver::ContactSettings& settings) {
  if (setup_->load_control)
    return solve_with_load_control(settings);
  return setup_->load_steps.empty()
             ? contact_analysis().solve(settings)
             : solve_load_steps(contact_analysis(), settings, setup_->load_steps);
}

CaseResult ProblemExecutor::run(const CaseSpec& spec) {
  CaseResult result;
  result.spec = spec;
  result.n_elements = setup_->mesh_info.n_block_elements;
  result.element_size_h = setup_->mesh_info.h_contact / setup_->length_unit;
  last_u_.resize(0);
  last_stresses_.reset();
  last_recovery_ = recovery_options(spec);

  const solver::ContactResult& contact = contact_solution(spec);
  result.n_equations = elastic_->dof_map().n_free();
  result.iterations = contact.active_set_iterations;
  result.reason = contact.reason;
  // A partial field is NaN where no case reads it; the analysis checked the entries it gave.
  const bool has_values = contact.displacement.size() > 0 &&
                          (!contact.displacement_complete || contact.displacement.allFinite());
  if (!has_values) {
    result.status = CaseStatus::failed;
    if (result.reason.empty())
      result.reason = "the contact solve produced no displacement";
    mark_missing(*setup_, result);
    return result;
  }
  result.status = contact.status == solver::ContactStatus::Converged ? CaseStatus::converged
                                                                     : CaseStatus::not_converged;
  last_u_ = contact.displacement;
  // Only the sampled surface is graded: recovered there alone (the whole field on demand).
  const auto surface = surface_recovery().recover(last_u_, last_recovery_);
  std::vector<ContactPressureSample> pressures;
  pressures.reserve(contact.nodes.size());
  for (const auto& n : contact.nodes)
    pressures.push_back({n.position.x(), n.pressure});
  sample_quantities(*setup_, surface, pressures, result, &contact);
  result.exact_profile = exact_profile(*setup_);
  result.interface = check_interface(*setup_, contact, applied_load());
  return result;
}

double ProblemExecutor::applied_load() {
  if (!applied_load_)
    applied_load_ = interface_load(*setup_, elastic_->external_load(setup_->model.loads));
  return *applied_load_;
}

const std::optional<solver::StressField>& ProblemExecutor::last_stresses() {
  if (!whole_field_ && last_u_.size() > 0)
    throw std::logic_error("the whole field was not recovered: call recover_whole_field() first");
  if (!last_stresses_ && last_u_.size() > 0)
    last_stresses_ = solver::recover_stresses(setup_->model, last_u_, last_recovery_);
  return last_stresses_;
}

std::string ProblemExecutor::vtu_document(std::string_view comment) {
  if (last_u_.size() == 0 || !last_stresses()) {
    throw std::runtime_error("no displacement to write: the case produced no values");
  }
  const solver::Mesh& mesh = setup_->model.mesh;
  const auto n = static_cast<std::size_t>(mesh.n_nodes());
  solver::VtuField displacement{"displacement", 3, std::vector<double>(3 * n, 0.0), true};
  std::vector<solver::VtuField> stresses{{"sigma_x", 1, {}, true},
                                         {"sigma_z", 1, {}, true},
                                         {"tau_xz", 1, {}, true},
                                         {"sigma_out_of_plane", 1, {}, true}};
  for (std::size_t i = 0; i < n; ++i) {
    displacement.values[3 * i] = last_u_[2 * i];
    displacement.values[3 * i + 1] = last_u_[2 * i + 1];
    const Eigen::Vector4d s = last_stresses_->at_node(static_cast<int>(i)).vector();
    for (int k = 0; k < 4; ++k)
      stresses[k].values.push_back(s[k]);
  }
  stresses.insert(stresses.begin(), displacement);
  return solver::vtu_document(mesh, stresses, comment);
}

std::unique_ptr<GroupExecutor> make_problem_executor(const CaseSpec& representative) {
  return std::make_unique<ProblemExecutor>(representative);
}

}  // namespace cs::suites
