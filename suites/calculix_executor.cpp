#include "suites/calculix_executor.hpp"

#include "suites/interface_checks.hpp"

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "adapters/calculix/calculix_error.hpp"
#include "adapters/calculix/calculix_manifest.hpp"
#include "suites/problem_executor.hpp"
#include "suites/run_directory.hpp"
#include "suites/solver_support.hpp"
#include "suites/suite_error.hpp"
#include "suites/surface_sampling.hpp"

namespace cs::suites {
namespace {

namespace ccx = adapters::calculix;

CaseStatus to_case_status(ccx::CalculixStatus status) {
  switch (status) {
    case ccx::CalculixStatus::Converged:
      return CaseStatus::converged;
    case ccx::CalculixStatus::NotConverged:
      return CaseStatus::not_converged;
    case ccx::CalculixStatus::Failed:
      return CaseStatus::failed;
    case ccx::CalculixStatus::Timeout:
      return CaseStatus::timeout;
  }
  return CaseStatus::failed;
}

/// The CalculiX options of `spec` on `setup`; "" or why the case cannot run on CalculiX.
std::string calculix_options(const CaseSpec& spec, const ProblemSetup& setup,
                             const CalculixRunOptions& run, ccx::CalculixOptions& out) {
  if (std::string why = why_not_runnable(spec, setup, ccx::calculix_manifest()); !why.empty())
    return why;
  if (setup.load_control)
    return "not supported by calculix: a load-controlled rigid punch";
  try {
    out = ccx::options_for(spec.solver_option, contact_settings(spec).fkn,
                           ccx::penalty_scale(setup.model, setup.pair, setup.p));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  out.time_limit_seconds = run.time_limit_seconds;
  out.executable = run.executable;
  return {};
}

/// CalculiX's nodal displacements as one vector, 2 DOFs per node of our mesh.
Eigen::VectorXd displacement_of(const ProblemSetup& setup, const ccx::CalculixResult& run) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * setup.model.mesh.n_nodes());
  for (std::size_t n = 0; n < run.displacement.size() && 2 * n + 1 < std::size_t(u.size()); ++n)
    u.segment<2>(2 * static_cast<Eigen::Index>(n)) = run.displacement[n];
  return u;
}

/// The sampled surface's stresses on the case's basis: CalculiX's own extrapolated nodal
/// stresses (recovery own), or our recovery of its nodal displacements (spr: the common basis;
/// extrapolated).
std::vector<solver::SurfaceStressSample> surface_of(const ProblemSetup& setup,
                                                    const ccx::CalculixResult& run,
                                                    const CaseSpec& spec) {
  if (spec.recovery == Recovery::own)
    return surface_of_nodal_stresses(setup, run.nodal_stress);
  const auto field =
      solver::recover_stresses(setup.model, displacement_of(setup, run), recovery_options(spec));
  return solver::surface_stresses(setup.model, field, kSampledSurface);
}

/// Fills the values of a converged run: quantities, profiles, interface checks.
void fill_values(const ProblemSetup& setup, const ccx::CalculixResult& run, CaseResult& result) {
  const auto surface = surface_of(setup, run, result.spec);
  std::vector<ContactPressureSample> pressures;
  pressures.reserve(run.contact.size());
  for (const auto& n : run.contact)
    pressures.push_back({n.position.x(), n.pressure});
  const Eigen::VectorXd u = displacement_of(setup, run);
  const solver::ContactResult interface = interface_of_displacements(setup, u, pressures);
  sample_quantities(setup, surface, pressures, result, nullptr, &interface);
  result.exact_profile = exact_profile(setup);
  result.interface = check_interface_of_displacements(setup, interface, u);
}

/// A run that did not converge or failed: its reason, and the directory it keeps.
void keep_failure(std::string reason, const std::filesystem::path& dir, CaseResult& result) {
  result.reason = reason.empty() ? std::string("CalculiX failed") : std::move(reason);
  result.kept_files = dir.string();
}

}  // namespace

const std::filesystem::path& calculix_run_directory() {
  static const RunDirectory dir("contact-suite-ccx");
  return dir.path();
}

std::string calculix_case_directory_name(const CaseSpec& spec) {
  CaseSpec run = spec;
  run.recovery = Recovery::spr;
  return plain_file_name(case_id(run));
}

CalculixExecutor::CalculixExecutor(const CaseSpec& representative, CalculixRunOptions options)
    : setup_(std::make_unique<ProblemSetup>(build_problem(representative))),
      options_(std::move(options)) {
  if (!(options_.time_limit_seconds > 0.0) || !std::isfinite(options_.time_limit_seconds))
    throw SuiteInputError("the CalculiX time limit must be a positive number of seconds");
}

CalculixExecutor::~CalculixExecutor() = default;

CaseResult CalculixExecutor::run(const CaseSpec& spec) {
  CaseResult result;
  result.spec = spec;
  result.n_elements = setup_->mesh_info.n_block_elements;
  result.element_size_h = setup_->mesh_info.h_contact / setup_->length_unit;
  result.status = CaseStatus::failed;

  ccx::CalculixOptions options;
  if (std::string why = calculix_options(spec, *setup_, options_, options); !why.empty()) {
    last_.reset();
    result.reason = std::move(why);
    mark_missing(*setup_, result);
    return result;
  }
  const std::filesystem::path root =
      options_.work_root.empty() ? calculix_run_directory() : options_.work_root;
  // The cases of one option on other stress bases share its run (and its directory).
  const std::string key = calculix_case_directory_name(spec);
  const std::filesystem::path dir = root / key;
  if (!last_ || last_key_ != key) {
    last_.reset();
    try {
      last_ = ccx::run_calculix(setup_->model, setup_->pair, options, dir);
    } catch (const std::exception& e) {  // ccx missing, a deck it cannot take: this case only
      keep_failure(e.what(), dir, result);
      mark_missing(*setup_, result);
      return result;
    }
    last_key_ = key;
    if (last_->converged()) {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  }
  result.status = to_case_status(last_->status);
  result.iterations = std::max(last_->iterations, 0);
  result.peak_rss_mb = last_->peak_rss_mb;
  if (!last_->converged()) {
    keep_failure(last_->reason, dir, result);
    mark_missing(*setup_, result);
    return result;
  }
  fill_values(*setup_, *last_, result);
  return result;
}

}  // namespace cs::suites
