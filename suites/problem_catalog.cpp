#include "suites/problem_catalog.hpp"

#include <array>
#include <set>
#include <utility>

namespace cs::suites {
namespace {

template <std::size_t... I>
std::array<const ProblemDescriptor*, sizeof...(I)> collect(std::index_sequence<I...>) {
  return {&problem_descriptor<static_cast<ProblemId>(I)>()...};
}

const auto& catalogue() {
  static const auto all = collect(std::make_index_sequence<schema::count<ProblemId>()>{});
  return all;
}

}  // namespace

const ProblemDescriptor& problem_descriptor(ProblemId id) {
  return *catalogue().at(static_cast<std::size_t>(id));
}

bool is_axisymmetric(ProblemId id) {
  return problem_descriptor(id).record.axisymmetric;
}

std::vector<ProblemId> study_problems() {
  std::vector<ProblemId> out;
  for (ProblemId id : values<ProblemId>()) {
    if (!problem_descriptor(id).record.study_tables.empty())
      out.push_back(id);
  }
  return out;
}

bool is_frictional(ProblemId id) {
  for (const auto& s : problem_descriptor(id).parameters) {
    if (s.name == "mu")
      return true;
  }
  return false;
}

bool is_singular(ProblemId id) {
  return problem_descriptor(id).record.singular;
}

std::vector<schema::ProblemRecord> problem_records(const std::vector<CaseResult>& cases) {
  std::set<ProblemId> present;
  for (const auto& c : cases)
    present.insert(c.spec.problem);
  std::vector<schema::ProblemRecord> out;
  for (ProblemId id : present)
    out.push_back(problem_descriptor(id).record);
  return out;
}

std::map<ProblemId, std::map<std::string, double>> parameter_defaults(
    const std::vector<CaseResult>& cases) {
  std::map<ProblemId, std::map<std::string, double>> out;
  for (const auto& c : cases) {
    for (const auto& parameter : problem_descriptor(c.spec.problem).parameters)
      out[c.spec.problem][parameter.name] = parameter.default_value;
  }
  return out;
}

}  // namespace cs::suites
