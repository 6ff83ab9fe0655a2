#include "reports/results/results_index.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>

#include <fmt/format.h>

#include "grading/convergence.hpp"

namespace cs::reports {
namespace {

using schema::CaseResult;
using schema::RowVerdict;

std::vector<Option> make_all_options() {
  std::vector<Option> out;
  for (const auto a : schema::values<schema::Algorithm>()) {
    for (const auto c : schema::values<schema::ContactKind>())
      out.push_back({a, c});
  }
  return out;
}

/// The first table number of "7, 8" (7); INT_MAX when the problem records no study table.
int first_study_table(const schema::ProblemRecord& p) {
  const std::string& tables = p.study_tables;
  int n = 0;
  const std::from_chars_result read =
      std::from_chars(tables.data(), tables.data() + tables.size(), n);
  return read.ec == std::errc() ? n : INT_MAX;
}

/// The solver whose rows are the baseline: ours when the document has a row of ours, else the
/// first other solver by name (the results of one imported code are reported like ours).
std::string reference_solver(const std::vector<schema::RowVerdict>& rows) {
  std::string out;
  for (const auto& r : rows) {
    const std::string s = schema::solver_label(r.spec);
    if (r.spec.solver == schema::SolverKind::builtin)
      return s;
    out = out.empty() || s < out ? s : out;
  }
  return out;
}

/// True for a row of `solver` with the study's options, with recovery `recovery`.
bool study_options(const schema::CaseSpec& spec, const std::string& solver,
                   schema::Recovery recovery) {
  schema::CaseSpec as_ours = spec;
  as_ours.solver = schema::SolverKind::builtin;
  as_ours.solver_name.clear();
  as_ours.recovery = schema::Recovery::spr;
  return spec.recovery == recovery && schema::solver_label(spec) == solver &&
         schema::is_baseline(as_ours);
}

/// The first value `value_of` finds in a row's quantity on C, M, then F.
template <class ValueOf>
std::optional<double> first_on_meshes(const ResultsIndex& index, const RowVerdict& row,
                                      ValueOf&& value_of) {
  for (const auto m : kMeshes) {
    const schema::QuantityResult* q = index.quantity_of(row, m);
    const std::optional<double> v = q != nullptr ? value_of(*q) : std::nullopt;
    if (v)
      return v;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> finite(double v) {
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

std::string Option::label() const {
  return fmt::format("{} {}", schema::to_string(algorithm), schema::to_string(contact));
}

const std::vector<Option>& all_options() {
  static const std::vector<Option> options = make_all_options();
  return options;
}

std::string variant_of(const schema::CaseSpec& spec) {
  schema::CaseSpec study_options = spec;
  study_options.target = schema::TargetKind::Discretized;
  study_options.recovery = schema::Recovery::spr;
  study_options.solver = schema::SolverKind::builtin;
  study_options.solver_name.clear();
  study_options.overrides.clear();
  const std::string key = schema::case_key(spec);
  const std::string base = schema::case_key(study_options);
  return key.size() > base.size() ? key.substr(base.size() + 1) : std::string();
}

ResultsIndex::RowKey ResultsIndex::key_of(const RowVerdict& r) {
  return {r.spec.problem, r.quantity, r.spec.element, r.spec.algorithm, r.spec.contact};
}

ResultsIndex::ResultsIndex(const schema::ResultsDocument& results) : results_(results) {
  for (const auto& p : results_.problems)
    problems_.push_back(&p);
  std::stable_sort(problems_.begin(), problems_.end(), [](const auto* a, const auto* b) {
    return std::pair(first_study_table(*a), a->id) < std::pair(first_study_table(*b), b->id);
  });
  for (const auto& c : results_.cases)
    case_by_key_.emplace(std::pair(schema::case_key(c.spec), c.spec.mesh), &c);
  const std::string solver = reference_solver(results_.rows);
  for (const auto& r : results_.rows) {
    if (study_options(r.spec, solver, schema::Recovery::spr)) {
      baseline_.push_back(&r);
      baseline_by_key_.emplace(key_of(r), &r);
    } else if (study_options(r.spec, solver, schema::Recovery::extrapolated)) {
      extrapolated_by_key_.emplace(key_of(r), &r);
    } else {
      variants_.push_back(&r);
    }
  }
  // An extrapolated row without its baseline (a run of extrapolated stresses only) is a variant.
  for (auto it = extrapolated_by_key_.begin(); it != extrapolated_by_key_.end();) {
    if (baseline_by_key_.count(it->first) == 0) {
      variants_.push_back(it->second);
      it = extrapolated_by_key_.erase(it);
    } else {
      ++it;
    }
  }
}

const schema::ProblemRecord* ResultsIndex::problem(schema::ProblemId id) const {
  return results_.problem(id);
}

const schema::QuantityDefinition* ResultsIndex::definition(schema::ProblemId id,
                                                           schema::Quantity q) const {
  const schema::ProblemRecord* p = problem(id);
  return p == nullptr ? nullptr : p->definition(q);
}

bool ResultsIndex::singular(schema::ProblemId id) const {
  const schema::ProblemRecord* p = problem(id);
  return p != nullptr && p->singular;
}

const RowVerdict* ResultsIndex::extrapolated_twin(const RowVerdict& b) const {
  const auto it = extrapolated_by_key_.find(key_of(b));
  return it == extrapolated_by_key_.end() ? nullptr : it->second;
}

const RowVerdict* ResultsIndex::row(schema::ProblemId problem, schema::Quantity quantity,
                                    schema::Element element, const Option& option) const {
  const auto it =
      baseline_by_key_.find(RowKey{problem, quantity, element, option.algorithm, option.contact});
  return it == baseline_by_key_.end() ? nullptr : it->second;
}

const CaseResult* ResultsIndex::case_of(const RowVerdict& row, schema::MeshLevel mesh) const {
  const auto it = case_by_key_.find(std::pair(schema::case_key(row.spec), mesh));
  return it == case_by_key_.end() ? nullptr : it->second;
}

const schema::QuantityResult* ResultsIndex::quantity_of(const RowVerdict& row,
                                                        schema::MeshLevel mesh) const {
  const CaseResult* c = case_of(row, mesh);
  return c == nullptr ? nullptr : c->quantity(row.quantity);
}

MeshState ResultsIndex::state(const RowVerdict& row, schema::MeshLevel mesh) const {
  const CaseResult* c = case_of(row, mesh);
  if (c == nullptr)
    return MeshState::missing;
  switch (c->status) {
    case schema::CaseStatus::converged:
      return MeshState::converged;
    case schema::CaseStatus::not_converged:
      return MeshState::not_converged;
    case schema::CaseStatus::failed:
    case schema::CaseStatus::timeout:
      return MeshState::failed;
  }
  return MeshState::failed;
}

bool ResultsIndex::any_not_converged(const RowVerdict& row) const {
  return std::any_of(kMeshes.begin(), kMeshes.end(), [&](schema::MeshLevel m) {
    return state(row, m) == MeshState::not_converged;
  });
}

bool ResultsIndex::complete(const RowVerdict& row) {
  return std::all_of(row.values.begin(), row.values.end(),
                     [](const auto& v) { return v.has_value(); });
}

std::vector<Option> ResultsIndex::options_present(schema::ProblemId problem,
                                                  schema::Quantity quantity,
                                                  schema::Element element) const {
  std::vector<Option> out;
  for (const auto& o : all_options()) {
    if (row(problem, quantity, element, o) != nullptr)
      out.push_back(o);
  }
  return out;
}

bool ResultsIndex::has(schema::ProblemId problem, schema::Quantity quantity,
                       schema::Element element) const {
  return !options_present(problem, quantity, element).empty();
}

std::optional<double> ResultsIndex::exact_of(const RowVerdict& row) const {
  return first_on_meshes(*this, row,
                         [](const schema::QuantityResult& q) { return finite(q.exact); });
}

double ResultsIndex::read_resolution_percent(const RowVerdict& row, schema::MeshLevel mesh) const {
  const CaseResult* c = case_of(row, mesh);
  const schema::QuantityResult* q = quantity_of(row, mesh);
  if (!schema::read_between_nodes(row.quantity) || c == nullptr || q == nullptr)
    return 0.0;
  const double nodes_per_side = row.spec.element == schema::Element::Q8 ? 2.0 : 1.0;
  return grading::node_read_resolution_percent(c->element_size_h / nodes_per_side, q->exact);
}

std::optional<double> ResultsIndex::study_exact_of(const RowVerdict& row) const {
  return first_on_meshes(*this, row, [](const schema::QuantityResult& q) { return q.study_exact; });
}

}  // namespace cs::reports
