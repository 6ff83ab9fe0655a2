#include "suites/row_verdict.hpp"

#include <cmath>
#include <map>

namespace cs::suites {
namespace {

/// The case id with the mesh level left out: cases sharing it form one row per quantity.
std::string row_key(const CaseSpec& spec, const std::string& quantity) {
  CaseSpec s = spec;
  s.mesh = MeshLevel::C;
  std::string id = case_id(s);
  // case_id is "problem/mesh/..."; drop the mesh field.
  const auto first = id.find('/');
  const auto second = id.find('/', first + 1);
  id.erase(first, second - first);
  return id + "/" + quantity;
}

void apply_verdicts(RowVerdict& row) {
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
  if (is_singular(row.problem)) {
    row.diverging = is_diverging(*row.values[0], *row.values[1], *row.values[2]);
    row.grade.reset();  // no finite exact value to grade against
    row.graded_mesh.reset();
  } else {
    row.converging = is_converging(*row.errors[0], *row.errors[1], *row.errors[2]);
  }
}

}  // namespace

std::vector<RowVerdict> make_row_verdicts(const std::vector<CaseResult>& cases) {
  std::map<std::string, RowVerdict> rows;
  std::vector<std::string> order;  // first-seen order keeps the runner's (study) order
  for (const auto& c : cases) {
    for (const auto& q : c.quantities) {
      const std::string key = row_key(c.spec, q.name);
      auto [it, inserted] = rows.try_emplace(key);
      RowVerdict& row = it->second;
      if (inserted) {
        order.push_back(key);
        row.id = key;
        row.problem = c.spec.problem;
        row.element = c.spec.element;
        row.algorithm = c.spec.algorithm;
        row.contact = c.spec.contact;
        row.target = c.spec.target;
        row.recovery = c.spec.recovery;
        row.quantity = q.name;
      }
      if (c.status == CaseStatus::failed || !std::isfinite(q.value))
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
