#include "suites/problem_executor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "solver/io/vtu_writer.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "suites/friction_cases.hpp"
#include "suites/friction_sampling.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/suite_error.hpp"

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

/// -sigma/p of one stress component.
double normalized(const solver::Stress& s, StressComponent c, double p) {
  switch (c) {
    case StressComponent::SigmaZ:
      return -s.sigma_z / p;
    case StressComponent::SigmaX:
      return -s.sigma_x / p;
    case StressComponent::TauXZ:
      return -s.tau_xz / p;
  }
  return std::nan("");
}

/// The index of the sample of `positions` that a rule reads, or -1 when there is none.
int sample_index(const std::vector<double>& x, const std::vector<double>& values, SamplePoint where,
                 double a) {
  if (x.empty())
    return -1;
  int best = 0;
  for (int i = 1; i < static_cast<int>(x.size()); ++i) {
    switch (where) {
      case SamplePoint::MaxOnSurface:
        if (values[i] > values[best])
          best = i;
        break;
      case SamplePoint::AtAxis:
        if (std::abs(x[i]) < std::abs(x[best]))
          best = i;
        break;
      case SamplePoint::AtEdge:
        if (std::abs(x[i] - a) < std::abs(x[best] - a))
          best = i;
        break;
      case SamplePoint::StickZoneEdge:  // read off the contact (friction_sampling.hpp)
      case SamplePoint::ContactPeakShear:
        return -1;
    }
  }
  return best;
}

/// Fills value, error and grade of each quantity, the contact-pressure version, and the profile.
void grade_case(const ProblemSetup& setup, const std::vector<solver::SurfaceStressSample>& surface,
                const solver::ContactResult& contact, CaseResult& result) {
  const double p = setup.p, a = setup.contact_half_width_a;
  std::vector<double> x_nodal, x_contact, pressure;
  for (const auto& s : surface)
    x_nodal.push_back(s.position.x());
  for (const auto& n : contact.nodes) {
    x_contact.push_back(n.position.x());
    pressure.push_back(n.pressure / p);
  }
  for (const QuantityRule& rule : setup.quantities) {
    if (sampled_from_contact(rule.where)) {
      result.quantities.push_back(contact_quantity(rule, contact, a, p));
      continue;
    }
    std::vector<double> values;
    for (const auto& s : surface)
      values.push_back(normalized(s.stress, rule.component, p));
    QuantityResult q;
    q.quantity = rule.quantity;
    q.exact = rule.exact;
    q.study_exact = rule.study_exact;
    const int i = sample_index(x_nodal, values, rule.where, a);
    q.value = i >= 0 ? values[i] : std::nan("");
    if (std::isfinite(rule.exact)) {
      q.error_percent = error_percent(q.value, rule.exact);
      q.grade = grade_from_error(q.error_percent);
    }
    if (rule.component == StressComponent::TauXZ)  // the contact's own peak shear
      q.contact_pressure = contact.peak_shear / p;
    if (rule.component == StressComponent::SigmaZ) {
      const int j = sample_index(x_contact, pressure, rule.where, a);
      if (j >= 0 && std::isfinite(pressure[j]))
        q.contact_pressure = pressure[j];
    }
    result.quantities.push_back(q);
  }
  // The profile of the study's Figure 4: nodal -sigma_z/p and the contact pressure, by x / a.
  for (const auto& s : surface) {
    result.profile.x_over_a.push_back(s.position.x() / a);
    result.profile.sigma_z_over_p.push_back(-s.stress.sigma_z / p);
    double nearest = std::nan("");
    double distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < x_contact.size(); ++k) {
      const double d = std::abs(x_contact[k] - s.position.x());
      if (d < distance)
        distance = d, nearest = pressure[k];
    }
    result.profile.pressure_over_p.push_back(distance < 1e-9 * a ? nearest : std::nan(""));
  }
}

/// The exact -sigma_z/p on z = 0 at 301 points of 0 <= x <= 1.5 a (within the block).
ExactProfile exact_profile(const ProblemSetup& setup) {
  ExactProfile out;
  if (!setup.exact_pressure_over_p)
    return out;
  const double a = setup.contact_half_width_a;
  const double x_max = std::min(1.5 * a, setup.mesh_info.block_width);
  constexpr int kPoints = 301;
  for (int i = 0; i < kPoints; ++i) {
    const double x = x_max * i / (kPoints - 1);
    double value = std::nan("");
    try {
      value = setup.exact_pressure_over_p(x);
    } catch (const std::invalid_argument&) {
      continue;  // the singular edge of a flat punch
    }
    if (!std::isfinite(value))
      continue;
    out.x_over_a.push_back(x / a);
    out.sigma_z_over_p.push_back(value);
  }
  return out;
}

/// Every quantity of the problem with no value: a failed case still names what it lacks.
void mark_missing(const ProblemSetup& setup, CaseResult& result) {
  for (const QuantityRule& rule : setup.quantities) {
    QuantityResult q;
    q.quantity = rule.quantity;
    q.exact = rule.exact;
    q.study_exact = rule.study_exact;
    q.value = std::nan("");
    q.error_percent = std::nan("");
    result.quantities.push_back(q);
  }
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
    : setup_(std::make_unique<ProblemSetup>(build_problem(representative))),
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
  int iterations = 0;
  // One ContactAnalysis for every step (and every case of the group): a changed advance is a
  // changed prescribed value, which it picks up with one forward solve, not a new condensation.
  if (!contact_)
    contact_ = std::make_unique<solver::ContactAnalysis>(*elastic_, setup_->pair);
  auto attempt = [&](double delta, double& load) {
    *control.delta = delta;
    elastic_->update_prescribed_values();
    solver::ContactResult r = contact_->solve(settings);
    iterations += r.active_set_iterations;
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
      return r;
    }
    const double slope = (f1 - f0) / (d1 - d0);
    if (!(slope > 0.0) || !std::isfinite(slope))
      break;
    d0 = d1, f0 = f1;
    d1 = d1 + (control.target_load - f1) / slope;
  }
  r.active_set_iterations = iterations;
  if (r.status == solver::ContactStatus::Converged) {
    r.status = solver::ContactStatus::NotConverged;
    r.reason = fmt::format("rigid punch load control: load {:.6g} vs target {:.6g}", f1,
                           control.target_load);
  }
  return r;
}

const solver::ContactResult& ProblemExecutor::contact_solution(const CaseSpec& spec) {
  CaseSpec key_spec = spec;
  key_spec.recovery = Recovery::spr;  // post-processing: the same contact solution
  const std::string key = case_id(key_spec);
  if (last_contact_ && last_contact_->first == key)
    return last_contact_->second;
  last_contact_.reset();
  const solver::ContactSettings settings = contact_settings(spec);
  solver::ContactResult contact;
  if (setup_->load_control) {
    contact = solve_with_load_control(settings);
  } else {
    if (!contact_)
      contact_ = std::make_unique<solver::ContactAnalysis>(*elastic_, setup_->pair);
    contact = setup_->load_steps.empty()
                  ? contact_->solve(settings)
                  : solve_load_steps(*contact_, settings, setup_->load_steps);
  }
  last_contact_.emplace(key, std::move(contact));
  return last_contact_->second;
}

CaseResult ProblemExecutor::run(const CaseSpec& spec) {
  CaseResult result;
  result.spec = spec;
  result.n_elements = setup_->mesh_info.n_block_elements;
  result.element_size_h = setup_->mesh_info.h_contact / setup_->length_unit;
  last_u_.resize(0);
  last_stresses_.reset();

  const solver::ContactResult& contact = contact_solution(spec);
  result.n_equations = elastic_->dof_map().n_free();
  result.iterations = contact.active_set_iterations;
  result.reason = contact.reason;
  const bool has_values = contact.displacement.size() > 0 && contact.displacement.allFinite();
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
  last_stresses_ = solver::recover_stresses(setup_->model, last_u_, recovery_options(spec));
  const auto surface = solver::surface_stresses(setup_->model, *last_stresses_, kSampledSurface);
  grade_case(*setup_, surface, contact, result);
  result.exact_profile = exact_profile(*setup_);
  return result;
}

void ProblemExecutor::write_vtu(const std::string& path) const {
  if (last_u_.size() == 0 || !last_stresses_) {
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
  solver::write_vtu(path, mesh, stresses);
}

std::unique_ptr<GroupExecutor> make_problem_executor(const CaseSpec& representative) {
  return std::make_unique<ProblemExecutor>(representative);
}

}  // namespace cs::suites
