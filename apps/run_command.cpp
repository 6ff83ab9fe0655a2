#include "apps/run_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <thread>

#include <fmt/core.h>

#include "adapters/protocol/solver_registry.hpp"
#include "adapters/registered_codes.hpp"
#include "apps/case_selection_options.hpp"
#include "apps/ci_report_files.hpp"
#include "apps/finite_number.hpp"
#include "apps/invocation.hpp"
#include "apps/memory_plan.hpp"
#include "apps/model_cost.hpp"
#include "apps/usage_error.hpp"
#include "apps/write_run_output.hpp"
#include "platform/available_cores.hpp"
#include "platform/available_memory.hpp"
#include "platform/child_process.hpp"
#include "platform/interrupts.hpp"
#include "platform/output_directory.hpp"
#include "platform/output_transaction.hpp"
#include "schema/results_file.hpp"
#include "suites/case_matrix.hpp"
#include "suites/executor_factory.hpp"
#include "suites/external_executor.hpp"
#include "suites/import_csv.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/problem_executor.hpp"
#include "suites/problem_setup.hpp"
#include "suites/progress.hpp"
#include "suites/row_outcomes.hpp"
#include "suites/row_verdict.hpp"
#include "suites/run_environment.hpp"
#include "suites/shard.hpp"
#include "suites/solver_support.hpp"
#include "suites/study_meshes.hpp"

namespace cs::apps {
namespace {

struct RunArgs {
  SelectionArgs selection;
  std::string solver{schema::to_string(schema::SolverKind::builtin)};
  std::vector<std::string> solver_dirs;
  std::vector<std::string> solver_options;
  double time_limit = 0.0;
  int jobs = 0;
  std::string out = "out";
  std::string shard;
  bool shard_given = false;
  bool no_report = false;
  bool surface_csv = false;
  double max_memory_gib = 0.0;
  CiReportFiles ci;
  std::string command_line;
};

std::vector<std::filesystem::path> solver_dirs(const RunArgs& args) {
  return {args.solver_dirs.begin(), args.solver_dirs.end()};
}

/// The cases of an external code: each model of the selection (its problems, meshes, elements,
/// target and parameters; --algorithms and --contacts do not apply) once per option of the code
/// (or of --solver-options) and per stress basis (--recovery, default spr = common and own),
/// but for those the code does not offer (suites::why_not_offered), which are left out and
/// counted on stderr; none left is a UsageError naming why.
std::vector<suites::CaseSpec> external_cases(const RunArgs& args, suites::CaseSelection sel) {
  if (!args.selection.algorithms.empty() || !args.selection.contacts.empty())
    throw UsageError("--algorithms and --contacts do not apply to " + args.solver +
                     ": its options are chosen by --solver-options");
  const auto code =
      adapters::find_code(args.solver, adapters::protocol::solver_directories(solver_dirs(args)));
  std::vector<const adapters::protocol::SolverOption*> options;
  for (const auto& label : suites::split_list_option(args.solver_options, "--solver-options"))
    options.push_back(&code.option(label));
  if (options.empty())
    for (const auto& o : code.options)
      options.push_back(&o);
  std::vector<schema::Recovery> recoveries = sel.recoveries;
  if (recoveries.empty())
    recoveries = {schema::Recovery::spr, schema::Recovery::own};
  sel.algorithms = {schema::Algorithm::LMP};
  sel.contacts = {schema::ContactKind::ss};
  sel.recoveries.clear();
  std::vector<suites::CaseSpec> out;
  std::map<std::string, int> not_offered;  // reason -> cases left out
  for (const auto& model : suites::make_case_matrix(sel))
    for (const auto* option : options)
      for (const auto recovery : recoveries) {
        auto spec = suites::external_case(model, code, *option, recovery);
        if (std::string why = suites::why_not_offered(spec, code); !why.empty())
          ++not_offered[why];
        else
          out.push_back(std::move(spec));
      }
  if (out.empty() && !not_offered.empty())
    throw UsageError("nothing to run: " + not_offered.begin()->first);
  for (const auto& [why, n] : not_offered)
    std::fprintf(stderr, "contact-suite: %d case%s left out, %s\n", n, n == 1 ? "" : "s",
                 why.c_str());
  return out;
}

std::vector<suites::CaseSpec> selected_cases(const RunArgs& args,
                                             std::vector<schema::SweepAxis>& sweep) {
  suites::CaseSelection sel = make_selection(args.selection);
  sweep = sel.sweeps;
  if (!schema::try_parse<schema::SolverKind>(args.solver)) {
    auto cases = external_cases(args, sel);
    validate_cases(cases);
    return cases;
  }
  sel.solver = schema::parse<schema::SolverKind>(args.solver);
  if (sel.solver == schema::SolverKind::imported || sel.solver == schema::SolverKind::external)
    throw UsageError("--solver " + args.solver +
                     ": name the code (builtin or a registered code, see `contact-suite list`)");
  if (!args.solver_options.empty())
    throw UsageError("--solver-options: only for an external code's options");
  auto cases = suites::make_case_matrix(sel);
  validate_cases(cases);
  return cases;
}

/// DIR/surface.csv: every converged case's sampled-surface values in the import layout
/// (suites/import_csv.hpp), under its case id without the solver suffix (its target and stress
/// basis stay in the id), with its option label, wall time, iterations, equations and memory.
void stage_surface_csv(const std::vector<suites::CaseResult>& results,
                       const platform::OutputTransaction& output) {
  std::vector<suites::ImportedCase> cases;
  for (const auto& r : results) {
    if (r.status != suites::CaseStatus::converged || r.surface_nodes.empty())
      continue;
    suites::CaseSpec spec = r.spec;
    spec.solver = schema::SolverKind::builtin;
    spec.solver_name.clear();
    spec.solver_option.clear();
    suites::ImportedCase c{suites::case_id(spec), 0, {}, {}};
    if (!r.spec.solver_option.empty())
      c.values.option = r.spec.solver_option;
    c.values.wall_seconds = r.wall_seconds;
    c.values.iterations = r.iterations;
    c.values.n_equations = r.n_equations;
    c.values.peak_rss_mb = r.peak_rss_mb;
    for (const auto& n : r.surface_nodes)
      c.rows.push_back({n.x, n.sigma_z, n.sigma_x, n.contact_pressure, 0});
    cases.push_back(std::move(c));
  }
  output.write_text("surface.csv", suites::import_csv_text(cases));
}

/// "S_1_7/VF/Q8": the model of a case, for messages.
std::string model_name(const suites::CaseSpec& spec) {
  return fmt::format("{}/{}/{}", suites::to_string(spec.problem), suites::to_string(spec.mesh),
                     schema::to_string(spec.element));
}

int run(const RunArgs& args) {
  platform::check_output_directory(args.out);  // refused before any input is read
  platform::require_outside_set(args.ci.junit, args.out, "--junit");
  platform::require_outside_set(args.ci.summary, args.out, "--summary");
  require_writable(args.ci);  // before anything runs: a bad path costs nothing
  std::vector<schema::SweepAxis> sweep;
  const auto all_cases = selected_cases(args, sweep);
  suites::ExecutorOptions exec;
  exec.solver_dirs = solver_dirs(args);
  exec.external_time_limit_seconds = args.time_limit;
  suites::require_solvers(all_cases, exec);  // e.g. ccx missing: exit 2 before anything runs
  std::optional<schema::ShardInfo> shard;
  auto cases = all_cases;
  if (args.shard_given) {
    const auto s = suites::parse_shard(args.shard);
    cases = suites::shard_cases(all_cases, s, group_cost);
    shard = schema::ShardInfo{s.index, s.count,
                              suites::run_key(all_cases, suites::contact_suite_version(), s.count),
                              static_cast<long long>(all_cases.size())};
  }
  // Take the output directory before running: an unwritable or busy one fails now, not at the
  // end, and no other process writes into it while this run holds it.
  platform::OutputTransaction output(args.out);

  const int cores = platform::available_cores();
  const int jobs = args.jobs > 0 ? args.jobs : cores;
  if (jobs > cores) {
    std::fprintf(stderr, "contact-suite: --jobs %d on %d core%s found: workers will share cores\n",
                 jobs, cores, cores == 1 ? "" : "s");
  }
  // One BLAS thread for every model (apps/model_cost.hpp): the cores go to models side by side,
  // and a case's results never depend on --jobs, the schedule or the selection.
  suites::set_blas_threads(1);
  const bool interactive = isatty(fileno(stderr)) != 0;
  suites::ProgressReporter progress(cases.size(), stderr, interactive);
  suites::RunnerOptions options;
  options.jobs = jobs;
  options.on_case_done = [&progress](const suites::CaseResult& r) { progress.case_done(r); };
  options.group_cost = group_cost;
  // Memory in proportion to the cost estimate, planned against what the machine has
  // (apps/memory_plan.hpp): refused now, or scheduled to fit.
  const auto largest =
      std::max_element(cases.begin(), cases.end(),
                       [](const auto& a, const auto& b) { return group_cost(a) < group_cost(b); });
  const MemoryPlan memory =
      plan_memory(largest == cases.end() ? 0.0 : kMiBPerCostUnit * group_cost(*largest),
                  largest == cases.end() ? std::string() : model_name(*largest),
                  {platform::available_memory_mb(), 1024.0 * args.max_memory_gib});
  if (!memory.note.empty())
    std::fprintf(stderr, "contact-suite: %s\n", memory.note.c_str());
  options.group_memory = [](const suites::CaseSpec& c) { return kMiBPerCostUnit * group_cost(c); };
  options.memory_budget = memory.budget_mib;
  options.should_stop = [] { return platform::interrupted_signal() != 0; };

  schema::RunInfo info;
  info.started_utc = suites::utc_now_iso8601();
  info.jobs = jobs;
  info.command_line = args.command_line;
  info.environment = suites::run_environment();
  info.shard = shard;
  info.sweep = sweep;
  const auto start = std::chrono::steady_clock::now();
  const auto results = suites::run_cases(cases, suites::executor_factory(exec), options);
  info.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  info.peak_rss_mb = suites::peak_rss_mb();
  progress.finish();
  if (const int sig = platform::interrupted_signal(); sig != 0) {
    std::fprintf(stderr, "contact-suite: interrupted by signal %d; %s left as it was\n", sig,
                 args.out.c_str());
    return 128 + sig;  // the output transaction is not committed: the old set stays
  }

  const schema::ResultsDocument doc{.source = {},
                                    .run = info,
                                    .problems = suites::problem_records(results),
                                    .cases = results,
                                    .rows = suites::make_row_verdicts(results),
                                    .added_runs = {},
                                    .parameter_defaults = suites::parameter_defaults(results)};
  if (args.surface_csv)
    stage_surface_csv(results, output);
  const auto figures = write_run_output(doc, output, !args.no_report);
  if (!figures) {
    report_interrupted_write(args.out);
    return 128 + platform::interrupted_signal();
  }
  if (args.ci.any()) {
    write_ci_reports(args.ci, suites::run_row_outcomes(results, doc.rows), "contact-suite run",
                     fmt::format("contact-suite run ({} cases)", results.size()));
  }
  fmt::print("wrote {}{}\n", (std::filesystem::path(args.out) / "results.json").string(),
             args.no_report ? "" : fmt::format(" and its report ({} figures)", *figures));
  for (const auto& r : results) {
    if (r.status != suites::CaseStatus::converged)
      return kCasesFailed;
  }
  return kSuccess;
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run the study's case matrix (or a subset) and report");
  add_selection_options(*cmd, args->selection);
  cmd->add_option("--solver", args->solver,
                  "Who solves the cases: builtin (ours) or a registered code: calculix (ccx "
                  "through its C++ adapter, docs/calculix.md) or a code registered by its "
                  "manifest (docs/solver-protocol.md; `contact-suite list` shows them all)")
      ->capture_default_str();
  cmd->add_option("--solver-dir", args->solver_dirs,
                  "A folder of external codes (each a folder with manifest.json), or one code's "
                  "folder; searched after adapters/ and CONTACT_SUITE_SOLVER_DIRS")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--solver-options", args->solver_options,
                  "An external code's options to run, by their own labels (default: all)");
  cmd->add_option("--time-limit", args->time_limit,
                  "Seconds one registered code's case may take before it is `timeout` "
                  "(default: its manifest's, 600 s for CalculiX)")
      ->check(finite_number(0.1, false, platform::kMaxTimeLimitSeconds));
  cmd->add_option("--jobs", args->jobs, "Parallel workers, 1 to 256 (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--out", args->out, "Output directory")->capture_default_str();
  cmd->add_option("--max-memory", args->max_memory_gib,
                  "GiB this run may use at most (default: MemAvailable less 10 %); a model "
                  "estimated above it is refused before the run starts")
      ->check(finite_number(0.0, true));
  cmd->add_flag("--no-report", args->no_report, "Write results.json only");
  cmd->add_flag("--surface-csv", args->surface_csv,
                "Also write surface.csv: each converged case's nodal stresses and contact "
                "pressures on the sampled surface, in the layout `grade --import` reads");
  add_ci_report_options(*cmd, args->ci);
  auto* shard = cmd->add_option(
      "--shard", args->shard,
      "Run slice K of N (K/N, 1-based) of the selected cases; slices keep the cases "
      "of one model together and are balanced by cost; combine them with `merge`");
  cmd->callback([args, shard, &exit_code] {
    args->shard_given = shard->count() > 0;
    args->command_line = invocation().empty() ? "contact-suite run" : invocation();
    exit_code = run(*args);
  });
}

}  // namespace cs::apps
