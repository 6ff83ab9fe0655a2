#pragma once
// The case-selection options that `run` and `export` share: --problems, --meshes, --elements,
// --algorithms, --contacts, --target, --recovery, --set and --sweep, registered, parsed and
// validated in one place so that both commands select and refuse cases the same way.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "suites/case_matrix.hpp"

namespace cs::apps {

/// The raw values of the selection options (lists as typed; split and parsed by make_selection).
struct SelectionArgs {
  std::vector<std::string> problems, meshes, elements, algorithms, contacts, sets;
  std::string target{schema::to_string(schema::TargetKind::Discretized)};
  std::vector<std::string> recoveries;
  std::vector<std::string> sweeps;  ///< `--sweep KEY=V1,V2,...`, one axis each
};

/// Adds the selection options to `cmd`, writing into `args` (which must outlive the parse).
void add_selection_options(CLI::App& cmd, SelectionArgs& args);

/// The selection `args` name, solved by the built-in solver. Throws SchemaError for an unknown
/// name, SuiteInputError for an empty list item, a malformed --set or --sweep.
suites::CaseSelection make_selection(const SelectionArgs& args);

/// Checks a case a command is asked to run before anything runs: its --set keys and values exist
/// for its problem, its options combine (e.g. MPC with friction is refused), and our solver is
/// not asked for `own` stresses (another code's). Throws SuiteInputError.
void validate_command_case(const suites::CaseSpec& spec);
/// validate_command_case for every case.
void validate_cases(const std::vector<suites::CaseSpec>& cases);

}  // namespace cs::apps
