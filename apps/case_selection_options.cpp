#include "apps/case_selection_options.hpp"

#include <fmt/format.h>

#include "suites/problem_catalog.hpp"
#include "suites/problem_setup.hpp"
#include "suites/suite_error.hpp"

namespace cs::apps {
namespace {

/// The names of a comma-separated list option (repeatable), split here rather than by CLI11,
/// which drops empty items: "H_p,,S_1" is refused, not read as "H_p,S_1".
template <class E>
std::vector<E> parse_all(const std::vector<std::string>& raw, const char* option) {
  std::vector<E> out;
  for (const auto& n : suites::split_list_option(raw, option))
    out.push_back(schema::parse<E>(n));
  return out;
}

}  // namespace

void add_selection_options(CLI::App& cmd, SelectionArgs& args) {
  cmd.add_option(
      "--problems", args.problems,
      fmt::format("Problems (default: the study's {})", suites::study_problems().size()));
  cmd.add_option("--meshes", args.meshes, "Mesh levels C M F (default: all)");
  cmd.add_option("--elements", args.elements, "Elements Q4 Q8 (default: both)");
  cmd.add_option("--algorithms", args.algorithms, "Algorithms AL PM LMP PLM MPC (default: all)");
  cmd.add_option("--contacts", args.contacts, "Discretizations ss ns mortar (default: ss ns)");
  cmd.add_option("--target", args.target, "Indenter: discretized or rigid")->capture_default_str();
  cmd.add_option("--recovery", args.recoveries,
                 "Nodal stresses: spr (patch recovery), extrapolated (as commercial codes "
                 "print) and/or own (another code's own nodal stresses); default: spr, and for "
                 "a registered code (run --solver <code>) spr and own");
  cmd.add_option("--set", args.sets, "Override a parameter of every case: name=value");
  cmd.add_option("--sweep", args.sweeps,
                 "Sweep a --set parameter: key=v1,v2,... (repeatable: the cross product of the "
                 "values); each case runs once per point, its swept values as its overrides");
}

suites::CaseSelection make_selection(const SelectionArgs& args) {
  suites::CaseSelection sel;
  sel.problems = parse_all<schema::ProblemId>(args.problems, "--problems");
  sel.meshes = parse_all<schema::MeshLevel>(args.meshes, "--meshes");
  sel.elements = parse_all<schema::Element>(args.elements, "--elements");
  sel.algorithms = parse_all<schema::Algorithm>(args.algorithms, "--algorithms");
  sel.contacts = parse_all<schema::ContactKind>(args.contacts, "--contacts");
  sel.target = schema::parse<schema::TargetKind>(args.target);
  sel.recoveries = parse_all<schema::Recovery>(args.recoveries, "--recovery");
  sel.overrides = suites::parse_overrides(args.sets);
  sel.sweeps = suites::parse_sweeps(args.sweeps);
  return sel;
}

void validate_command_case(const suites::CaseSpec& spec) {
  if (spec.recovery == schema::Recovery::own && spec.solver == schema::SolverKind::builtin)
    throw suites::SuiteInputError(
        "--recovery own: our solver's own nodal stresses are the patch-recovered ones (spr); own "
        "is another code's stresses (run --solver <code>)");
  suites::validate_case(spec);  // --set keys, values; e.g. MPC with friction is refused
}

void validate_cases(const std::vector<suites::CaseSpec>& cases) {
  for (const auto& spec : cases)
    validate_command_case(spec);
}

}  // namespace cs::apps
