#include "reports/facts/solvers.hpp"

#include <algorithm>
#include <set>

namespace cs::reports {
namespace {

/// The study's settings apart from the solver and the recovery.
bool study_settings(const schema::CaseSpec& spec) {
  return spec.target == schema::TargetKind::Discretized && spec.overrides.empty();
}

bool matches(const schema::RowVerdict& r, const std::string& solver, schema::ProblemId problem,
             schema::Quantity quantity, schema::Element element, const Option& option) {
  return r.quantity == quantity && r.spec.problem == problem && r.spec.element == element &&
         r.spec.algorithm == option.algorithm && r.spec.contact == option.contact &&
         study_settings(r.spec) && schema::solver_label(r.spec) == solver;
}

}  // namespace

std::string builtin_solver_label() {
  return std::string(schema::to_string(schema::SolverKind::builtin));
}

std::vector<std::string> solvers_in(const ResultsIndex& index) {
  std::set<std::string> others;
  bool builtin = false;
  for (const auto& c : index.results().cases) {
    const std::string s = schema::solver_label(c.spec);
    if (s == builtin_solver_label())
      builtin = true;
    else
      others.insert(s);
  }
  std::vector<std::string> out;
  if (builtin)
    out.push_back(builtin_solver_label());
  out.insert(out.end(), others.begin(), others.end());
  return out;
}

std::string solver_display_name(const std::string& solver) {
  if (solver == builtin_solver_label())
    return "ours";
  return solver;
}

bool is_cross_code(const ResultsIndex& index) {
  return solvers_in(index).size() > 1;
}

const schema::RowVerdict* solver_row(const ResultsIndex& index, const std::string& solver,
                                     schema::ProblemId problem, schema::Quantity quantity,
                                     schema::Element element, const Option& option) {
  if (solver == builtin_solver_label())
    return index.row(problem, quantity, element, option);
  const schema::RowVerdict* found = nullptr;
  for (const auto& r : index.results().rows) {
    if (!matches(r, solver, problem, quantity, element, option))
      continue;
    if (r.spec.recovery == schema::Recovery::spr)
      return &r;
    found = found == nullptr ? &r : found;
  }
  return found;
}

std::vector<Option> cross_code_options(const ResultsIndex& index, schema::ProblemId problem,
                                       schema::Quantity quantity, schema::Element element) {
  const auto solvers = solvers_in(index);
  std::vector<Option> out;
  for (const auto& o : all_options()) {
    const bool any = std::any_of(solvers.begin(), solvers.end(), [&](const std::string& s) {
      return s != builtin_solver_label() &&
             solver_row(index, s, problem, quantity, element, o) != nullptr;
    });
    if (any)
      out.push_back(o);
  }
  return out;
}

std::string same_case_key(const schema::CaseSpec& spec) {
  schema::CaseSpec s = spec;
  s.solver = schema::SolverKind::builtin;
  s.solver_name.clear();
  s.recovery = schema::Recovery::spr;
  return schema::case_id(s);
}

}  // namespace cs::reports
