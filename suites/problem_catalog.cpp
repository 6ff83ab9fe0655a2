#include "suites/problem_catalog.hpp"

#include <array>
#include <deque>
#include <mutex>
#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "schema/registered_problems.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

template <std::size_t... I>
std::array<const ProblemDescriptor*, sizeof...(I)> collect(std::index_sequence<I...>) {
  return {&problem_descriptor<static_cast<ProblemId>(I)>()...};
}

const auto& built_in() {
  static const auto all = collect(std::make_index_sequence<schema::count<ProblemId>()>{});
  return all;
}

/// The registered problems' descriptors, element i for id kFirstRegisteredProblem + i (a deque:
/// references handed out stay valid as it grows).
struct Registered {
  std::mutex mutex;
  std::deque<ProblemDescriptor> descriptors;
};

Registered& registered() {
  static Registered r;
  return r;
}

const ProblemDescriptor* find_registered(ProblemId id) {
  const auto index = static_cast<std::size_t>(id);
  if (index < schema::kFirstRegisteredProblem)
    return nullptr;
  Registered& r = registered();
  const std::lock_guard lock(r.mutex);
  const std::size_t i = index - schema::kFirstRegisteredProblem;
  return i < r.descriptors.size() ? &r.descriptors[i] : nullptr;
}

const ProblemDescriptor* find(ProblemId id) {
  const auto index = static_cast<std::size_t>(id);
  return index < built_in().size() ? built_in()[index] : find_registered(id);
}

}  // namespace

const ProblemDescriptor& problem_descriptor(ProblemId id) {
  if (const ProblemDescriptor* d = find(id))
    return *d;
  throw SuiteInputError(
      fmt::format("problem id {} is neither built in nor registered", static_cast<int>(id)));
}

bool is_known_problem(ProblemId id) {
  return find(id) != nullptr;
}

ProblemId register_problem(std::string_view name, ProblemDescriptor descriptor) {
  Registered& r = registered();
  const std::lock_guard lock(r.mutex);
  const ProblemId id = schema::register_problem_name(name);
  descriptor.record.id = id;
  r.descriptors.push_back(std::move(descriptor));
  return id;
}

std::vector<ProblemId> all_problems() {
  const auto built_in_ids = values<ProblemId>();
  std::vector<ProblemId> out(built_in_ids.begin(), built_in_ids.end());
  for (ProblemId id : schema::registered_values(ProblemId{})) {
    if (is_known_problem(id))
      out.push_back(id);
  }
  return out;
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

void refresh_problem_records(std::vector<schema::ProblemRecord>& records) {
  for (auto& record : records) {
    const ProblemDescriptor* d = find(record.id);
    if (d == nullptr)
      continue;
    if (!record.situation)
      record.situation = d->situation;
    if (!record.length_scale)
      record.length_scale = d->length_scale;
  }
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
