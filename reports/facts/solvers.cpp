#include "reports/facts/solvers.hpp"

#include <set>

#include "reports/tables/markdown_table.hpp"

namespace cs::reports {

std::string builtin_solver_label() {
  return std::string(schema::to_string(schema::SolverKind::builtin));
}

std::string code_of(const schema::CaseSpec& spec) {
  const std::string label = schema::solver_label(spec);
  return label.substr(0, label.find(':'));
}

std::string option_label_of(const schema::CaseSpec& spec) {
  const std::string label = schema::solver_label(spec);
  const std::size_t colon = label.find(':');
  return colon == std::string::npos ? Option{spec.algorithm, spec.contact}.label()
                                    : label.substr(colon + 1);
}

std::vector<std::string> solvers_in(const ResultsIndex& index) {
  std::set<std::string> others;
  bool builtin = false;
  for (const auto& c : index.results().cases) {
    const std::string code = code_of(c.spec);
    if (code == builtin_solver_label())
      builtin = true;
    else
      others.insert(code);
  }
  std::vector<std::string> out;
  if (builtin)
    out.push_back(builtin_solver_label());
  out.insert(out.end(), others.begin(), others.end());
  return out;
}

std::string solver_display_name(const std::string& code) {
  return code == builtin_solver_label() ? "ours" : code;
}

std::string solver_names(const ResultsIndex& index, const char* last) {
  std::vector<std::string> names;
  for (const auto& s : solvers_in(index))
    names.push_back(solver_display_name(s));
  return join_words(names, last);
}

bool is_cross_code(const ResultsIndex& index) {
  return solvers_in(index).size() > 1;
}

}  // namespace cs::reports
