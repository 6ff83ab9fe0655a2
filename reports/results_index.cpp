#include "reports/results_index.hpp"

#include <algorithm>
#include <array>

namespace cs::reports {
namespace {

constexpr std::array<const char*, 5> kAlgorithmOrder{"AL", "PM", "LMP", "PLM", "MPC"};
constexpr std::array<const char*, 3> kContactOrder{"ss", "ns", "mortar"};

std::vector<Option> make_all_options() {
  std::vector<Option> out;
  for (const char* a : kAlgorithmOrder) {
    for (const char* c : kContactOrder)
      out.push_back({a, c});
  }
  return out;
}

}  // namespace

const std::vector<Option>& all_options() {
  static const std::vector<Option> options = make_all_options();
  return options;
}

int algorithm_order(const std::string& algorithm) {
  for (std::size_t i = 0; i < kAlgorithmOrder.size(); ++i) {
    if (algorithm == kAlgorithmOrder[i])
      return static_cast<int>(i);
  }
  return 99;
}

int contact_order(const std::string& contact) {
  for (std::size_t i = 0; i < kContactOrder.size(); ++i) {
    if (contact == kContactOrder[i])
      return static_cast<int>(i);
  }
  return 99;
}

ResultsIndex::ResultsIndex(const ResultsFile& results) : results_(results) {
  for (const auto& c : results_.cases) {
    case_by_id_key_.emplace(case_key_of(c.id) + "#" + c.mesh, &c);
  }
  for (const auto& r : results_.rows) {
    const RowKey key{r.problem, r.quantity, r.element, r.algorithm, r.contact};
    if (r.target == "discretized" && r.variant().empty()) {
      baseline_.push_back(&r);
      baseline_by_key_.emplace(key, &r);
    } else if (r.target == "discretized" && r.variant() == "extrapolated") {
      extrapolated_by_key_.emplace(key, &r);
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

const RowRecord* ResultsIndex::extrapolated_twin(const RowRecord& b) const {
  const auto it =
      extrapolated_by_key_.find(RowKey{b.problem, b.quantity, b.element, b.algorithm, b.contact});
  return it == extrapolated_by_key_.end() ? nullptr : it->second;
}

const RowRecord* ResultsIndex::row(const std::string& problem, const std::string& quantity,
                                   const std::string& element, const Option& option) const {
  const auto it =
      baseline_by_key_.find(RowKey{problem, quantity, element, option.algorithm, option.contact});
  return it == baseline_by_key_.end() ? nullptr : it->second;
}

const CaseRecord* ResultsIndex::case_of(const RowRecord& row, std::size_t mesh) const {
  const auto it = case_by_id_key_.find(row.case_key() + "#" + kMeshLevels.at(mesh));
  return it == case_by_id_key_.end() ? nullptr : it->second;
}

const QuantityRecord* ResultsIndex::quantity_of(const RowRecord& row, std::size_t mesh) const {
  const CaseRecord* c = case_of(row, mesh);
  return c == nullptr ? nullptr : c->quantity(row.quantity);
}

MeshState ResultsIndex::state(const RowRecord& row, std::size_t mesh) const {
  const CaseRecord* c = case_of(row, mesh);
  if (c == nullptr)
    return MeshState::missing;
  if (c->status == "failed")
    return MeshState::failed;
  if (c->status == "not_converged")
    return MeshState::not_converged;
  return MeshState::converged;
}

bool ResultsIndex::any_not_converged(const RowRecord& row) const {
  for (std::size_t m = 0; m < kMeshLevels.size(); ++m) {
    if (state(row, m) == MeshState::not_converged)
      return true;
  }
  return false;
}

bool ResultsIndex::complete(const RowRecord& row) {
  return std::all_of(row.values.begin(), row.values.end(),
                     [](const auto& v) { return v.has_value(); });
}

std::vector<Option> ResultsIndex::options_present(const std::string& problem,
                                                  const std::string& quantity,
                                                  const std::string& element) const {
  std::vector<Option> out;
  for (const auto& o : all_options()) {
    if (row(problem, quantity, element, o) != nullptr)
      out.push_back(o);
  }
  return out;
}

bool ResultsIndex::has(const std::string& problem, const std::string& quantity,
                       const std::string& element) const {
  return !options_present(problem, quantity, element).empty();
}

std::optional<double> ResultsIndex::exact_of(const RowRecord& row) const {
  for (std::size_t m = 0; m < kMeshLevels.size(); ++m) {
    if (const QuantityRecord* q = quantity_of(row, m); q != nullptr && q->exact)
      return q->exact;
  }
  return std::nullopt;
}

std::optional<double> ResultsIndex::study_exact_of(const RowRecord& row) const {
  for (std::size_t m = 0; m < kMeshLevels.size(); ++m) {
    if (const QuantityRecord* q = quantity_of(row, m); q != nullptr && q->study_exact)
      return q->study_exact;
  }
  return std::nullopt;
}

}  // namespace cs::reports
