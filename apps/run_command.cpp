#include "apps/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <fmt/core.h>

#include "apps/invocation.hpp"
#include "apps/usage_error.hpp"
#include "apps/write_run_output.hpp"
#include "platform/interrupts.hpp"
#include "platform/output_transaction.hpp"
#include "schema/results_file.hpp"
#include "suites/case_matrix.hpp"
#include "suites/executor_factory.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/problem_executor.hpp"
#include "suites/problem_setup.hpp"
#include "suites/progress.hpp"
#include "suites/row_verdict.hpp"
#include "suites/run_environment.hpp"
#include "suites/shard.hpp"

namespace cs::apps {
namespace {

struct RunArgs {
  std::vector<std::string> problems, meshes, elements, algorithms, contacts, sets;
  std::string target{schema::to_string(schema::TargetKind::Discretized)};
  std::vector<std::string> recoveries;
  std::string solver{schema::to_string(schema::SolverKind::builtin)};
  double ccx_time_limit = 600.0;
  int jobs = 0;
  std::string out = "out";
  std::string shard;
  bool shard_given = false;
  bool no_report = false;
  std::string command_line;
};

/// The names of a comma-separated list option (repeatable; see suites::split_list_option).
template <class E>
std::vector<E> parse_all(const std::vector<std::string>& raw, const char* option) {
  std::vector<E> out;
  for (const auto& n : suites::split_list_option(raw, option))
    out.push_back(schema::parse<E>(n));
  return out;
}

suites::CaseSelection make_selection(const RunArgs& args) {
  suites::CaseSelection sel;
  sel.problems = parse_all<schema::ProblemId>(args.problems, "--problems");
  sel.meshes = parse_all<schema::MeshLevel>(args.meshes, "--meshes");
  sel.elements = parse_all<schema::Element>(args.elements, "--elements");
  sel.algorithms = parse_all<schema::Algorithm>(args.algorithms, "--algorithms");
  sel.contacts = parse_all<schema::ContactKind>(args.contacts, "--contacts");
  sel.target = schema::parse<schema::TargetKind>(args.target);
  sel.recoveries = parse_all<schema::Recovery>(args.recoveries, "--recovery");
  sel.solver = schema::parse<schema::SolverKind>(args.solver);
  if (sel.solver == schema::SolverKind::imported)
    throw UsageError("--solver imported: imported results are graded by `grade`, not run");
  sel.overrides = suites::parse_overrides(args.sets);
  return sel;
}

/// Every case's --set keys must exist for its problem: checked before anything runs.
void validate_overrides(const std::vector<suites::CaseSpec>& cases) {
  for (const auto& spec : cases) {
    suites::Parameters(suites::problem_descriptor(spec.problem).parameters, spec.overrides,
                       suites::to_string(spec.problem));
    suites::validate_case(spec);  // e.g. MPC with friction: bad input before anything runs
  }
}

/// A rough relative cost of a model, to start the largest first.
double group_cost(const suites::CaseSpec& spec) {
  const double per_level[] = {1.0, 4.0, 16.0};
  double cost = per_level[static_cast<int>(spec.mesh)];
  if (spec.problem == suites::ProblemId::S_1 || spec.problem == suites::ProblemId::S_1_3 ||
      spec.problem == suites::ProblemId::S_1_7) {
    cost *= 30.0;
  }
  return spec.element == schema::Element::Q8 ? 3.0 * cost : cost;
}

int run(const RunArgs& args) {
  const auto all_cases = suites::make_case_matrix(make_selection(args));
  validate_overrides(all_cases);
  suites::ExecutorOptions exec;
  exec.calculix_time_limit_seconds = args.ccx_time_limit;
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

  const int jobs =
      args.jobs > 0 ? args.jobs : static_cast<int>(std::thread::hardware_concurrency());
  // One BLAS thread per worker, whatever --jobs is: a threaded BLAS sums in an order that
  // depends on its thread count, and results must be bit-identical for every --jobs.
  suites::set_blas_threads(1);
  const bool interactive = isatty(fileno(stderr)) != 0;
  suites::ProgressReporter progress(cases.size(), stderr, interactive);
  suites::RunnerOptions options;
  options.jobs = jobs;
  options.on_case_done = [&progress](const suites::CaseResult& r) { progress.case_done(r); };
  options.group_cost = group_cost;
  options.should_stop = [] { return platform::interrupted_signal() != 0; };

  schema::RunInfo info;
  info.started_utc = suites::utc_now_iso8601();
  info.jobs = jobs;
  info.command_line = args.command_line;
  info.environment = suites::run_environment();
  info.shard = shard;
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
                                    .rows = suites::make_row_verdicts(results)};
  const int figures = write_run_output(doc, output, !args.no_report);
  fmt::print("wrote {}{}\n", (std::filesystem::path(args.out) / "results.json").string(),
             args.no_report ? "" : fmt::format(" and its report ({} figures)", figures));
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
  cmd->add_option("--problems", args->problems, "Problems (default: all 11)");
  cmd->add_option("--meshes", args->meshes, "Mesh levels C M F (default: all)");
  cmd->add_option("--elements", args->elements, "Elements Q4 Q8 (default: both)");
  cmd->add_option("--algorithms", args->algorithms, "Algorithms AL PM LMP PLM MPC (default: all)");
  cmd->add_option("--contacts", args->contacts, "Discretizations ss ns mortar (default: ss ns)");
  cmd->add_option("--target", args->target, "Indenter: discretized or rigid")
      ->capture_default_str();
  cmd->add_option("--solver", args->solver,
                  "Who solves the cases: builtin (ours) or calculix (ccx through its adapter; "
                  "see docs/calculix.md for how the options map)")
      ->capture_default_str();
  cmd->add_option("--ccx-time-limit", args->ccx_time_limit,
                  "Seconds one CalculiX case may take before it is `timeout`")
      ->check(CLI::Range(1.0, 86400.0))
      ->capture_default_str();
  cmd->add_option("--recovery", args->recoveries,
                  "Nodal stresses: spr (patch recovery; the default) and/or extrapolated (as "
                  "commercial codes print)");
  cmd->add_option("--set", args->sets, "Override a parameter of every case: name=value");
  cmd->add_option("--jobs", args->jobs, "Parallel workers, 1 to 256 (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--out", args->out, "Output directory")->capture_default_str();
  cmd->add_flag("--no-report", args->no_report, "Write results.json only");
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
