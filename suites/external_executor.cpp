#include "suites/external_executor.hpp"

#include "suites/interface_checks.hpp"

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include <fmt/format.h>

#include "adapters/protocol/code_environment.hpp"
#include "platform/child_process.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/model.hpp"
#include "solver/stress_recovery.hpp"
#include "suites/case_directory.hpp"
#include "suites/problem_executor.hpp"
#include "suites/run_directory.hpp"
#include "suites/solver_support.hpp"
#include "suites/suite_error.hpp"
#include "suites/surface_sampling.hpp"

namespace cs::suites {
namespace {

namespace fs = std::filesystem;
namespace protocol = adapters::protocol;

/// The last non-empty line a failed code wrote to its standard error (its own statement of why,
/// e.g. an adapter's "not supported: ..."), from the file's last 4 KiB, at most 300 characters,
/// every byte that is not printable ASCII shown as '?' (the stream is bytes in any encoding, and
/// the reason goes into JSON and Markdown); empty if none.
std::string last_error_line(const fs::path& stderr_path) {
  std::ifstream in(stderr_path, std::ios::binary | std::ios::ate);
  if (!in)
    return {};
  const std::streamoff size = in.tellg();
  in.seekg(std::max<std::streamoff>(0, size - 4096));
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      last = line;
  }
  for (char& c : last)
    c = (c >= 0x20 && c < 0x7f) ? c : '?';
  return last.size() > 300 ? last.substr(0, 300) + "..." : last;
}

/// The process's run root for external codes, created on first use (suites/run_directory.hpp).
const fs::path& default_work_root() {
  static const RunDirectory root("contact-suite-ext");
  return root.path();
}

/// Names and modification times of everything under `dir` (not following links).
std::map<std::string, fs::file_time_type> listing(const fs::path& dir) {
  std::map<std::string, fs::file_time_type> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    out[fs::relative(it->path(), dir, ec).string()] = it->last_write_time(ec);
  return out;
}

/// The first entry added or changed between two listings, or "".
std::string first_change(const std::map<std::string, fs::file_time_type>& before,
                         const std::map<std::string, fs::file_time_type>& after) {
  for (const auto& [name, time] : after) {
    const auto it = before.find(name);
    if (it == before.end() || it->second != time)
      return name;
  }
  return {};
}

std::vector<int> deformable_nodes(const ProblemSetup& setup) {
  const solver::Mesh& mesh = setup.model.mesh;
  const bool rigid = std::holds_alternative<solver::RigidProfile>(setup.pair.target);
  std::set<int> nodes;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (rigid && mesh.element_body[e] != 0)
      continue;
    for (int k = 0; k < mesh.n_element_nodes(); ++k)
      nodes.insert(mesh.elements[e][k]);
  }
  return {nodes.begin(), nodes.end()};
}

/// The sorted nodes of edge set `name`.
std::vector<int> sorted_nodes_of(const solver::Mesh& mesh, const std::string& name) {
  std::vector<int> nodes = solver::nodes_of_sides(mesh, solver::resolve_edge_set(mesh, name));
  std::ranges::sort(nodes);
  return nodes;
}

/// What read files lack for grading (one line, "" when nothing): on the `own` basis a stress
/// at every node of the sampled surface; a contact pressure only at the contact surface's
/// nodes (one on the target's side would be taken for the block's).
std::string files_lack(const ProblemSetup& setup, const protocol::ResultFiles& files,
                       Recovery recovery) {
  const solver::Mesh& mesh = setup.model.mesh;
  if (recovery == Recovery::own) {
    for (int n : sorted_nodes_of(mesh, kSampledSurface)) {
      if (!files.has_stress[static_cast<std::size_t>(n)])
        return fmt::format("stresses.csv: node {} of the sampled surface is missing", n + 1);
    }
  }
  const std::vector<int> contact = sorted_nodes_of(mesh, setup.pair.contact_surface);
  for (const auto& p : files.contact_pressure) {
    if (!std::ranges::binary_search(contact, p.node))
      return fmt::format("contact_pressure.csv: node {} is not on the contact surface", p.node + 1);
  }
  return "";
}

}  // namespace

CaseSpec external_case(const CaseSpec& model_case, const protocol::SolverManifest& code,
                       const protocol::SolverOption& option, Recovery recovery) {
  CaseSpec spec = model_case;
  spec.solver = SolverKind::external;
  spec.solver_name = code.name;
  spec.solver_option = option.label;
  spec.algorithm = study_algorithm(option.family);
  spec.contact = schema::parse<ContactKind>(option.discretization);
  spec.recovery = recovery;
  return spec;
}

/// One run of the code: its result files, the child's account and the directory.
struct ExternalExecutor::Run {
  std::string key;      ///< the case id less its recovery
  std::string failure;  ///< why there are no values ("" if there are)
  fs::path kept;        ///< the case directory kept for inspection (empty: removed)
  bool not_converged = false;
  protocol::ResultFiles files;
  platform::ChildResult child;
};

ExternalExecutor::ExternalExecutor(const CaseSpec& representative, ExternalRunOptions options)
    : setup_(std::make_unique<ProblemSetup>(build_problem(representative))),
      options_(std::move(options)) {
  if (options_.time_limit_seconds <= 0.0)
    options_.time_limit_seconds = options_.manifest.time_limit_seconds;
}

ExternalExecutor::~ExternalExecutor() = default;

const ExternalExecutor::Run& ExternalExecutor::run_code(const CaseSpec& spec) {
  CaseSpec key_spec = spec;
  key_spec.recovery = Recovery::spr;
  const std::string key = case_id(key_spec);
  if (last_ && last_->key == key)
    return *last_;
  last_ = std::make_unique<Run>();
  Run& run = *last_;
  run.key = key;
  const protocol::SolverManifest& code = options_.manifest;
  fs::path root;
  try {  // a failure here is this run's, so every basis of the case reports it
    root = options_.work_root.empty() ? default_work_root() : options_.work_root;
    fs::create_directories(root);
  } catch (const std::exception& e) {
    run.failure = std::string("cannot create a run directory: ") + e.what();
    return run;
  }
  std::string pattern = (root / (plain_file_name(key) + ".XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr) {
    run.failure = "cannot create a run directory under " + root.string();
    return run;
  }
  const fs::path run_dir = pattern, case_dir = run_dir / "case";
  platform::ChildOptions child;
  std::map<std::string, fs::file_time_type> adapter_before;
  try {  // as above: a full disk, say, fails this run, not the next basis's reading of it
    fs::create_directory(case_dir);
    write_case_directory(case_dir, spec, *setup_, spec.solver_option);
    child.argv = protocol::expand_command(code.command, code.folder, case_dir, spec.solver_option);
    child.working_directory = case_dir;
    child.stdout_path = case_dir / "solver.out";
    child.stderr_path = case_dir / "solver.err";
    child.time_limit_seconds = options_.time_limit_seconds;
    child.environment = protocol::code_environment();
    adapter_before = listing(code.folder);
    run.child = platform::run_child(child);
  } catch (const std::exception& e) {
    run.failure = std::string("cannot run the case: ") + e.what();
    run.kept = run_dir;
    return run;
  }

  std::set<std::string> beside;
  for (const auto& entry : fs::directory_iterator(run_dir))
    if (entry.path().filename() != "case")
      beside.insert(entry.path().filename().string());
  const std::string adapter_change = first_change(adapter_before, listing(code.folder));
  if (!run.child.succeeded()) {
    const std::string said = last_error_line(child.stderr_path);
    run.failure =
        fmt::format("{} {}{}", code.name, run.child.describe(), said.empty() ? "" : ": " + said);
  } else if (!beside.empty()) {
    run.failure = fmt::format("{} wrote outside the case directory: {}", code.name,
                              (run_dir / *beside.begin()).string());
  } else if (!adapter_change.empty()) {
    run.failure = fmt::format("{} wrote outside the case directory: {}", code.name,
                              (code.folder / adapter_change).string());
  } else {
    run.files = protocol::read_result_files(case_dir, setup_->model.mesh.n_nodes(),
                                            deformable_nodes(*setup_));
    if (!run.files.error.empty())
      run.failure = run.files.error;
    else if (run.files.converged && !*run.files.converged)
      run.not_converged = true;
  }
  if (run.failure.empty() && !run.not_converged) {
    std::error_code ignored;
    fs::remove_all(run_dir, ignored);
  } else {
    run.kept = case_dir;
  }
  return run;
}

CaseResult ExternalExecutor::run(const CaseSpec& spec) {
  CaseResult result;
  result.spec = spec;
  result.n_elements = setup_->mesh_info.n_block_elements;
  result.element_size_h = setup_->mesh_info.h_contact / setup_->length_unit;
  result.status = CaseStatus::failed;
  const protocol::SolverManifest& code = options_.manifest;
  const std::string why = why_not_runnable(spec, *setup_, code);
  if (!why.empty()) {
    result.reason = why;
    mark_missing(*setup_, result);
    return result;
  }
  const Run& run = run_code(spec);
  result.kept_files = run.kept.string();
  result.peak_rss_mb = run.child.peak_rss_mb;
  result.iterations = run.files.iterations;
  result.n_equations = run.files.n_equations;
  if (!run.failure.empty()) {
    result.status = run.child.timed_out ? CaseStatus::timeout : CaseStatus::failed;
    result.reason = run.failure;
    mark_missing(*setup_, result);
    return result;
  }
  if (spec.recovery == Recovery::own && !run.files.stresses_given) {
    result.reason = code.name + " wrote no stresses.csv: it has no `own` basis";
    mark_missing(*setup_, result);
    return result;
  }
  if (const std::string lack = files_lack(*setup_, run.files, spec.recovery); !lack.empty()) {
    result.reason = code.name + "'s " + lack;
    mark_missing(*setup_, result);
    return result;
  }
  result.status = run.not_converged ? CaseStatus::not_converged : CaseStatus::converged;
  result.reason = run.files.reason;
  std::vector<solver::SurfaceStressSample> surface;
  if (spec.recovery == Recovery::own) {
    std::vector<solver::Stress> nodal(run.files.stress.size());
    for (std::size_t n = 0; n < nodal.size(); ++n)
      nodal[n] = solver::Stress::from(run.files.stress[n]);
    surface = surface_of_nodal_stresses(*setup_, nodal);
  } else {
    const auto field =
        solver::recover_stresses(setup_->model, run.files.displacement, recovery_options(spec));
    surface = solver::surface_stresses(setup_->model, field, kSampledSurface);
  }
  std::vector<ContactPressureSample> pressures;
  for (const auto& p : run.files.contact_pressure)
    pressures.push_back({setup_->model.mesh.nodes[p.node].x(), p.pressure});
  const solver::ContactResult interface =
      interface_of_displacements(*setup_, run.files.displacement, pressures);
  sample_quantities(*setup_, surface, pressures, result, nullptr, &interface);
  result.exact_profile = exact_profile(*setup_);
  if (result.status == CaseStatus::converged)
    result.interface = check_interface_of_displacements(*setup_, interface, run.files.displacement);
  return result;
}

}  // namespace cs::suites
