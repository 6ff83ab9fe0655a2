#include "apps/case_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "adapters/protocol/solver_registry.hpp"
#include "adapters/registered_codes.hpp"
#include "apps/case_selection_options.hpp"
#include "apps/usage_error.hpp"
#include "oracles/invalid_input.hpp"
#include "platform/available_cores.hpp"
#include "platform/output_directory.hpp"
#include "platform/output_transaction.hpp"
#include "platform/replaceable_file.hpp"
#include "schema/results_file.hpp"
#include "solver/spare_cores.hpp"
#include "suites/executor_factory.hpp"
#include "suites/external_executor.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/problem_executor.hpp"
#include "suites/problem_setup.hpp"
#include "suites/run_environment.hpp"
#include "suites/solver_support.hpp"
#include "suites/suite_error.hpp"

namespace cs::apps {
namespace {

struct CaseArgs {
  std::string problem;
  std::string mesh{schema::to_string(schema::MeshLevel::C)};
  std::string element{schema::to_string(schema::Element::Q4)};
  std::string algorithm{schema::to_string(schema::Algorithm::AL)};
  std::string contact{schema::to_string(schema::ContactKind::ss)};
  std::string target{schema::to_string(schema::TargetKind::Discretized)};
  std::string recovery{schema::to_string(schema::Recovery::spr)};
  std::string solver{schema::to_string(schema::SolverKind::builtin)};
  std::vector<std::filesystem::path> solver_dirs;  ///< --solver-dir, searched after the others
  std::vector<std::string> sets;
  bool json = false;
  std::string vtu;
  bool vtu_given = false;
};

suites::CaseSpec make_spec(const CaseArgs& args) {
  suites::CaseSpec spec;
  spec.problem = schema::parse<schema::ProblemId>(args.problem);
  spec.mesh = schema::parse<schema::MeshLevel>(args.mesh);
  spec.element = schema::parse<schema::Element>(args.element);
  spec.algorithm = schema::parse<schema::Algorithm>(args.algorithm);
  spec.contact = schema::parse<schema::ContactKind>(args.contact);
  spec.target = schema::parse<schema::TargetKind>(args.target);
  spec.recovery = schema::parse<schema::Recovery>(args.recovery);
  spec.overrides = suites::parse_overrides(args.sets);
  // Validate the parameters now: a bad --set is bad input, not a failed case.
  suites::Parameters(suites::problem_descriptor(spec.problem).parameters, spec.overrides,
                     suites::to_string(spec.problem));
  if (args.solver != schema::to_string(schema::SolverKind::builtin)) {
    const auto colon = args.solver.find(':');
    if (colon == std::string::npos)
      throw UsageError("--solver " + args.solver +
                       ": builtin, or a registered code and its option as NAME:OPTION (e.g. "
                       "calculix:hard-ss; `contact-suite list` shows them)");
    const auto code = adapters::find_code(args.solver.substr(0, colon),
                                          adapters::protocol::solver_directories(args.solver_dirs));
    spec = suites::external_case(spec, code, code.option(args.solver.substr(colon + 1)),
                                 spec.recovery);
    // As `run` leaves such cases out: an option the code does not offer here, for the case or
    // for its model's load path (friction), is bad input.
    std::string why = suites::why_not_offered(spec, code);
    if (why.empty())
      why = suites::why_not_runnable(spec, suites::build_problem(spec), code);
    if (!why.empty())
      throw UsageError("--solver " + args.solver + ": " + why);
  }
  validate_command_case(spec);
  return spec;
}

/// An unwritable --vtu is found before the analysis runs, not after.
void check_vtu_path(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty())
    throw UsageError("--vtu: empty file name");
  platform::require_printable_path(path, "--vtu");
  platform::require_outside_sets(path, "--vtu");
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UsageError(fmt::format("--vtu {}: is a directory, expected a file name", path));
  platform::require_replaceable(path, "--vtu");
  const auto parent = fs::absolute(path).parent_path();
  if (!fs::is_directory(parent, ec))
    throw UsageError(fmt::format("--vtu {}: directory {} does not exist", path, parent.string()));
  if (::access(parent.c_str(), W_OK) != 0)
    throw UsageError(fmt::format("--vtu {}: directory {} is not writable", path, parent.string()));
}

void print_text(const suites::CaseResult& r) {
  fmt::print("{}  {}{}\n", suites::case_id(r.spec), suites::to_string(r.status),
             r.reason.empty() ? "" : "  (" + r.reason + ")");
  if (!r.kept_files.empty())
    fmt::print("  files kept in {}\n", r.kept_files);
  fmt::print("  {} elements, {} equations, {} iterations, {:.3f} s\n", r.n_elements, r.n_equations,
             r.iterations, r.wall_seconds);
  for (const auto& q : r.quantities) {
    const std::string exact =
        std::isfinite(q.exact) ? fmt::format("{:.4f}", q.exact) : std::string("inf");
    std::string line =
        fmt::format("  {:<13} {:>9}  exact {:>8}", schema::to_string(q.quantity),
                    std::isfinite(q.value) ? fmt::format("{:.4f}", q.value) : "-", exact);
    if (std::isfinite(q.exact) && std::isfinite(q.value)) {
      line +=
          fmt::format("  error {:+.3f} %  grade {}", q.error_percent, suites::to_string(q.grade));
    }
    if (q.contact_pressure)
      line += fmt::format("  contact pressure {:.4f}", *q.contact_pressure);
    if (q.study_exact)
      line += fmt::format("  (study's exact {:.4f})", *q.study_exact);
    fmt::print("{}\n", line);
  }
}

int run_case(const CaseArgs& args) {
  const suites::CaseSpec spec = make_spec(args);
  if (args.vtu_given && spec.solver != schema::SolverKind::builtin)
    throw UsageError("--vtu: only the built-in solver's fields can be written");
  if (args.vtu_given)
    check_vtu_path(args.vtu);
  suites::ExecutorOptions options;
  options.solver_dirs = args.solver_dirs;
  suites::require_solvers({spec}, options);  // e.g. ccx missing: exit 2 before anything runs
  // One BLAS thread, as `run` gives every model (apps/model_cost.hpp): the same values as the
  // model's cases in a run. The other cores go to the steps that split without changing a value
  // (a large model's ordering).
  suites::set_blas_threads(1);
  const solver::CoreLoan loan(platform::available_cores() - 1);
  const auto start = std::chrono::steady_clock::now();
  suites::CaseResult result;
  std::unique_ptr<suites::GroupExecutor> executor;
  try {
    executor = suites::make_executor_for(spec, options);
    auto* builtin = dynamic_cast<suites::ProblemExecutor*>(executor.get());
    if (args.vtu_given && builtin)
      builtin->recover_whole_field();  // the .vtu holds the whole field
    result = executor->run(spec);
  } catch (const suites::SuiteInputError&) {
    throw;  // bad input: exit 2
  } catch (const oracles::InvalidInput&) {
    throw;  // parameters the exact solution refuses (a Steuermann load past the rounded edges)
  } catch (const std::exception& e) {
    result.spec = spec;
    result.status = suites::CaseStatus::failed;
    result.reason = e.what();
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.peak_rss_mb = suites::peak_rss_mb();
  if (args.json) {
    fmt::print("{}\n", schema::to_json(result).dump(2, ' ', false,
                                                    nlohmann::json::error_handler_t::replace));
  } else {
    print_text(result);
  }
  // After the values are printed: a file the user put at --vtu during the analysis is refused
  // (exit 2), and the analysis's values are not lost with it.
  auto* builtin = dynamic_cast<suites::ProblemExecutor*>(executor.get());
  if (args.vtu_given && builtin && builtin->last_displacement().size() > 0)
    platform::replace_written_file(args.vtu, builtin->vtu_document(platform::kWrittenMarkText),
                                   "--vtu");
  return result.status == suites::CaseStatus::converged ? kSuccess : kCasesFailed;
}

}  // namespace

void add_case_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CaseArgs>();
  auto* cmd = app.add_subcommand("case", "Run one analysis of the battery and grade it");
  cmd->add_option("problem", args->problem,
                  "Problem: " + schema::accepted_names<schema::ProblemId>())
      ->required();
  cmd->add_option("--mesh", args->mesh, "Mesh level: C, M or F")->capture_default_str();
  cmd->add_option("--element", args->element, "Element: Q4 or Q8")->capture_default_str();
  cmd->add_option("--algorithm", args->algorithm, "Contact algorithm: AL PM LMP PLM MPC (IMC)")
      ->capture_default_str();
  cmd->add_option("--contact", args->contact, "Contact discretization: ns, ss or mortar")
      ->capture_default_str();
  cmd->add_option("--target", args->target, "Indenter: discretized (stiff mesh) or rigid")
      ->capture_default_str();
  cmd->add_option("--recovery", args->recovery,
                  "Nodal stresses: spr (patch recovery) or extrapolated (as commercial codes)")
      ->capture_default_str();
  cmd->add_option("--set", args->sets, "Override a parameter: name=value (see `list`)");
  cmd->add_option("--solver", args->solver,
                  "Who solves it: builtin, or a registered code's NAME:OPTION (e.g. "
                  "calculix:hard-ss; then --algorithm and --contact are the option's)")
      ->capture_default_str();
  cmd->add_option("--solver-dir", args->solver_dirs,
                  "A further folder of external codes (see `run --solver-dir`)")
      ->check(CLI::ExistingDirectory);
  cmd->add_flag("--json", args->json, "Print one JSON object (the fields of results.json)");
  auto* vtu = cmd->add_option("--vtu", args->vtu,
                              "Write the mesh, displacement and stresses to a .vtu file");
  cmd->callback([args, vtu, &exit_code] {
    args->vtu_given = vtu->count() > 0;
    exit_code = run_case(*args);
  });
}

}  // namespace cs::apps
