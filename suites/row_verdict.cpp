#include "suites/row_verdict.hpp"

#include <cmath>
#include <map>

#include "suites/problem_catalog.hpp"
#include "suites/row_estimates.hpp"

namespace cs::suites {
namespace {

std::string row_key(const CaseSpec& spec, Quantity quantity) {
  return schema::case_key(spec) + "/" + std::string(to_string(quantity));
}

void apply_verdicts(RowVerdict& row) {
  row.pair_orders = pair_orders(row.errors);
  for (int level = 2; level >= 0; --level) {
    if (row.errors[level]) {
      row.grade = grade_from_error(*row.errors[level]);
      row.graded_mesh = static_cast<MeshLevel>(level);
      break;
    }
  }
  const bool complete = row.values[0] && row.values[1] && row.values[2];
  if (!complete)
    return;
  if (is_singular(row.spec.problem)) {
    row.diverging = is_diverging(*row.values[0], *row.values[1], *row.values[2]);
    row.divergence = divergence_verdict(*row.values[0], *row.values[1], *row.values[2]);
    row.grade.reset();  // no finite exact value to grade against
    row.graded_mesh.reset();
  } else {
    row.converging = is_converging(*row.errors[0], *row.errors[1], *row.errors[2]);
    row.estimate = error_estimate(*row.values[0], *row.values[1], *row.values[2]);
  }
}

}  // namespace

std::vector<RowVerdict> make_row_verdicts(const std::vector<CaseResult>& cases) {
  std::map<std::string, RowVerdict> rows;
  std::vector<std::string> order;  // first-seen order keeps the runner's (study) order
  for (const auto& c : cases) {
    for (const auto& q : c.quantities) {
      const std::string key = row_key(c.spec, q.quantity);
      auto [it, inserted] = rows.try_emplace(key);
      RowVerdict& row = it->second;
      if (inserted) {
        order.push_back(key);
        row.id = key;
        row.spec = c.spec;
        row.spec.mesh = MeshLevel::C;
        row.quantity = q.quantity;
      }
      if (c.status == CaseStatus::failed || c.status == CaseStatus::timeout ||
          !std::isfinite(q.value))
        continue;
      const auto level = static_cast<std::size_t>(c.spec.mesh);
      row.values[level] = q.value;
      if (!is_singular(c.spec.problem))
        row.errors[level] = q.error_percent;
    }
  }
  std::vector<RowVerdict> out;
  out.reserve(order.size());
  for (const auto& key : order) {
    RowVerdict row = rows.at(key);
    apply_verdicts(row);
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace cs::suites
