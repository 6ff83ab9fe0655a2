#include "suites/calculix_executor.hpp"

#include <stdlib.h>

#include <cmath>
#include <exception>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "adapters/calculix/calculix_error.hpp"
#include "adapters/calculix/calculix_options.hpp"
#include "suites/problem_executor.hpp"
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

/// "not supported by CalculiX: <the adapter's message less its "CalculiX: " prefix>".
std::string unsupported_reason(const std::string& message) {
  constexpr std::string_view kPrefix = "CalculiX: ";
  std::string_view m = message;
  if (m.starts_with(kPrefix))
    m.remove_prefix(kPrefix.size());
  return "not supported by CalculiX: " + std::string(m);
}

/// The CalculiX options of `spec` on `setup` (throws UnsupportedByCalculix for its gaps).
ccx::CalculixOptions calculix_options(const CaseSpec& spec, const ProblemSetup& setup,
                                      const ExecutorOptions& options) {
  if (spec.target == TargetKind::Rigid || setup.load_control)
    throw ccx::UnsupportedByCalculix(
        "a rigid target (the adapter writes meshed surfaces only: use --target discretized)");
  ccx::CalculixOptions out = ccx::map_contact_settings(
      contact_settings(spec), ccx::penalty_scale(setup.model, setup.pair, setup.p));
  out.time_limit_seconds = options.calculix_time_limit_seconds;
  out.executable = options.ccx_executable;
  return out;
}

/// The sampled surface's stresses on the case's basis: CalculiX's own extrapolated nodal
/// stresses (recovery own), or our recovery of its nodal displacements (spr: the common basis;
/// extrapolated).
std::vector<solver::SurfaceStressSample> surface_of(const ProblemSetup& setup,
                                                    const ccx::CalculixResult& run,
                                                    const CaseSpec& spec) {
  if (spec.recovery == Recovery::own)
    return surface_of_nodal_stresses(setup, run.nodal_stress);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * setup.model.mesh.n_nodes());
  for (std::size_t n = 0; n < run.displacement.size() && 2 * n + 1 < std::size_t(u.size()); ++n)
    u.segment<2>(2 * static_cast<Eigen::Index>(n)) = run.displacement[n];
  const auto field = solver::recover_stresses(setup.model, u, recovery_options(spec));
  return solver::surface_stresses(setup.model, field, kSampledSurface);
}

/// Fills the values of a converged run: quantities, profiles.
void fill_values(const ProblemSetup& setup, const ccx::CalculixResult& run, CaseResult& result) {
  const auto surface = surface_of(setup, run, result.spec);
  std::vector<ContactPressureSample> pressures;
  pressures.reserve(run.contact.size());
  for (const auto& n : run.contact)
    pressures.push_back({n.position.x(), n.pressure});
  sample_quantities(setup, surface, pressures, result);
  result.exact_profile = exact_profile(setup);
}

std::string with_kept_directory(std::string reason, const std::filesystem::path& dir) {
  return (reason.empty() ? std::string("CalculiX failed") : std::move(reason)) +
         " (CalculiX files kept in " + dir.string() + ")";
}

/// The process's run directory, removed at exit when it is empty (every case converged).
struct RunDirectory {
  std::filesystem::path path;
  RunDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "contact-suite-ccx.XXXXXX");
    if (mkdtemp(pattern.data()) == nullptr)
      throw std::system_error(errno, std::generic_category(),
                              "cannot create a CalculiX run directory from " + pattern);
    path = pattern;
  }
  ~RunDirectory() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);  // fails, harmlessly, while failed cases are kept
  }
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;
};

}  // namespace

const std::filesystem::path& calculix_run_directory() {
  static const RunDirectory dir;
  return dir.path;
}

std::string calculix_case_directory_name(const CaseSpec& spec) {
  return plain_file_name(case_id(spec));
}

CalculixExecutor::CalculixExecutor(const CaseSpec& representative, const ExecutorOptions& options)
    : setup_(std::make_unique<ProblemSetup>(build_problem(representative))), options_(options) {
  if (!(options_.calculix_time_limit_seconds > 0.0) ||
      !std::isfinite(options_.calculix_time_limit_seconds))
    throw SuiteInputError("the CalculiX time limit must be a positive number of seconds");
}

CalculixExecutor::~CalculixExecutor() = default;

CaseResult CalculixExecutor::run(const CaseSpec& spec) {
  CaseResult result;
  result.spec = spec;
  result.spec.solver = SolverKind::calculix;
  result.n_elements = setup_->mesh_info.n_block_elements;
  result.element_size_h = setup_->mesh_info.h_contact / setup_->length_unit;
  result.status = CaseStatus::failed;
  last_.reset();

  ccx::CalculixOptions options;
  try {
    options = calculix_options(spec, *setup_, options_);
  } catch (const ccx::UnsupportedByCalculix& e) {
    result.reason = unsupported_reason(e.what());
    mark_missing(*setup_, result);
    return result;
  }
  const std::filesystem::path root =
      options_.calculix_work_root.empty() ? calculix_run_directory() : options_.calculix_work_root;
  const std::filesystem::path dir = root / calculix_case_directory_name(spec);
  try {
    last_ = ccx::run_calculix(setup_->model, setup_->pair, options, dir);
  } catch (const std::exception& e) {  // ccx missing, a deck it cannot take: this case only
    result.reason = with_kept_directory(e.what(), dir);
    mark_missing(*setup_, result);
    return result;
  }
  result.status = to_case_status(last_->status);
  result.iterations = std::max(last_->iterations, 0);
  result.peak_rss_mb = last_->peak_rss_mb;
  if (!last_->converged()) {
    result.reason = with_kept_directory(last_->reason, dir);
    mark_missing(*setup_, result);
    return result;
  }
  fill_values(*setup_, *last_, result);
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  return result;
}

}  // namespace cs::suites
