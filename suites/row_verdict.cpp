#include "suites/row_verdict.hpp"

#include <cmath>
#include <map>

#include "grading/accuracy.hpp"
#include "grading/convergence.hpp"
#include "grading/divergence.hpp"
#include "grading/richardson.hpp"
#include "suites/problem_catalog.hpp"

namespace cs::suites {
namespace {

/// The verdicts over M, F, VF, beside the row's C-M-F ones (the row must have VF).
void apply_refinement_verdicts(RowVerdict& row) {
  schema::RefinementVerdict& vf = *row.refinement;
  if (row.errors[2] && vf.error)
    vf.pair_order = grading::pair_order(row.errors[2], vf.error);
  if (!row.values[1] || !row.values[2] || !vf.value)
    return;
  if (is_singular(row.spec.problem)) {
    vf.divergence = grading::divergence_verdict(*row.values[1], *row.values[2], *vf.value);
    vf.diverging = vf.divergence->eq47;
  } else if (row.errors[1] && row.errors[2] && vf.error) {
    vf.converging = grading::study_converging(*row.errors[1], *row.errors[2], *vf.error);
    vf.estimate = grading::error_estimate(*row.values[1], *row.values[2], *vf.value);
  }
}

void apply_verdicts(RowVerdict& row) {
  if (row.refinement)
    apply_refinement_verdicts(row);
  row.pair_orders = {grading::pair_order(row.errors[0], row.errors[1]),
                     grading::pair_order(row.errors[1], row.errors[2])};
  for (int level = 2; level >= 0; --level) {
    if (row.errors[level]) {
      row.grade = grading::grade_of_error(*row.errors[level]);
      row.graded_mesh = static_cast<MeshLevel>(level);
      break;
    }
  }
  const bool complete = row.values[0] && row.values[1] && row.values[2];
  if (!complete)
    return;
  if (is_singular(row.spec.problem)) {
    row.divergence = grading::divergence_verdict(*row.values[0], *row.values[1], *row.values[2]);
    row.diverging = row.divergence->eq47;
    row.grade.reset();  // no finite exact value to grade against
    row.graded_mesh.reset();
  } else {
    row.converging = grading::study_converging(*row.errors[0], *row.errors[1], *row.errors[2]);
    row.estimate = grading::error_estimate(*row.values[0], *row.values[1], *row.values[2]);
  }
}

}  // namespace

std::string row_id(const CaseSpec& spec, Quantity quantity) {
  return schema::case_key(spec) + "/" + std::string(to_string(quantity));
}

std::vector<RowVerdict> make_row_verdicts(const std::vector<CaseResult>& cases) {
  std::map<std::string, RowVerdict> rows;
  std::vector<std::string> order;  // first-seen order keeps the runner's (study) order
  for (const auto& c : cases) {
    for (const auto& q : c.quantities) {
      const std::string key = row_id(c.spec, q.quantity);
      auto [it, inserted] = rows.try_emplace(key);
      RowVerdict& row = it->second;
      if (inserted) {
        order.push_back(key);
        row.id = key;
        row.spec = c.spec;
        row.spec.mesh = MeshLevel::C;
        row.quantity = q.quantity;
      }
      if (c.spec.mesh == MeshLevel::VF && !row.refinement)
        row.refinement.emplace();  // present even when the VF case failed
      if (c.status == CaseStatus::failed || c.status == CaseStatus::timeout ||
          !std::isfinite(q.value))
        continue;
      const bool singular = is_singular(c.spec.problem);
      if (c.spec.mesh == MeshLevel::VF) {
        row.refinement->value = q.value;
        if (!singular)
          row.refinement->error = q.error_percent;
        continue;
      }
      const auto level = static_cast<std::size_t>(c.spec.mesh);
      row.values[level] = q.value;
      if (!singular)
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
