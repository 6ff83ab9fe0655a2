#include "suites/row_outcomes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <fmt/format.h>

#include "grading/grade_change.hpp"

namespace cs::suites {
namespace {

/// The cases of each row, by row id (a case belongs to one row per quantity).
using CasesByRow = std::map<std::string, std::vector<const CaseResult*>>;

CasesByRow cases_by_row(const std::vector<CaseResult>& cases) {
  CasesByRow out;
  for (const auto& c : cases) {
    for (const auto& q : c.quantities)
      out[row_id(c.spec, q.quantity)].push_back(&c);
  }
  return out;
}

double wall_seconds(const std::vector<const CaseResult*>& cases) {
  double sum = 0.0;
  for (const CaseResult* c : cases)
    sum += c->wall_seconds;
  return sum;
}

/// "grade e on F (error -0.12 %), converging" / "diverging (Eq. 47)" / "no grade".
std::string row_summary(const RowVerdict& row) {
  std::string out;
  if (row.grade && row.graded_mesh) {
    const auto level = static_cast<std::size_t>(*row.graded_mesh);
    out = fmt::format("grade {} on {}", to_string(*row.grade), to_string(*row.graded_mesh));
    if (level < row.errors.size() && row.errors[level])
      out += fmt::format(" (error {:.4g} %)", *row.errors[level]);
  } else {
    out = "no grade";
  }
  if (row.converging)
    out += *row.converging ? ", converging" : ", not converging";
  if (row.diverging)
    out += *row.diverging ? ", diverging (Eq. 47)" : ", not diverging (Eq. 47)";
  return out;
}

bool has_verdict(const RowVerdict& row) {
  return row.grade || row.converging || row.diverging;
}

std::string case_status_line(const CaseResult& c) {
  std::string line = fmt::format("{} {}", case_id(c.spec), to_string(c.status));
  if (!c.reason.empty())
    line += ": " + c.reason;
  return line;
}

/// The baseline's value of `quantity` in a case, or NaN.
double value_of(const CaseResult& c, Quantity quantity) {
  const QuantityResult* q = c.quantity(quantity);
  return q ? q->value : NAN;
}

/// Whether the gate compares anything of the row: a grade or verdict of the baseline row, a
/// finite baseline value, or a baseline case that converged.
bool gate_compares(const RowVerdict* old_row, const std::vector<const CaseResult*>& old_cases,
                   Quantity quantity) {
  if (old_row &&
      (old_row->grade || old_row->converging.value_or(false) || old_row->diverging.value_or(false)))
    return true;
  return std::any_of(old_cases.begin(), old_cases.end(), [quantity](const CaseResult* c) {
    return c->status == CaseStatus::converged || std::isfinite(value_of(*c, quantity));
  });
}

/// "grade g -> e; values moved by up to 3.2e-05 (relative)"; empty when nothing moved.
std::string movement(const RowVerdict* old_row, const RowVerdict& row,
                     const std::vector<const CaseResult*>& old_cases,
                     const std::map<std::string, const CaseResult*>& new_cases) {
  std::string out;
  if (old_row && old_row->grade != row.grade) {
    out = fmt::format("grade {} -> {}",
                      old_row->grade ? std::string(to_string(*old_row->grade)) : "none",
                      row.grade ? std::string(to_string(*row.grade)) : "none");
  }
  double largest = 0.0;
  bool moved = false;
  for (const CaseResult* old_case : old_cases) {
    const auto it = new_cases.find(case_id(old_case->spec));
    if (it == new_cases.end())
      continue;
    const double before = value_of(*old_case, row.quantity);
    const double now = value_of(*it->second, row.quantity);
    if (std::isnan(before) && std::isnan(now))
      continue;
    if (!(before == now)) {
      moved = true;
      largest = std::max(largest, grading::relative_drift(before, now));
    }
  }
  if (moved) {
    out += out.empty() ? "" : "; ";
    out += std::isfinite(largest) ? fmt::format("values moved by up to {:.3g} (relative)", largest)
                                  : std::string("a value appeared or vanished");
  }
  return out;
}

}  // namespace

std::vector<RowOutcome> run_row_outcomes(const std::vector<CaseResult>& cases,
                                         const std::vector<RowVerdict>& rows) {
  const CasesByRow by_row = cases_by_row(cases);
  std::vector<RowOutcome> out;
  for (const auto& row : rows) {
    RowOutcome o{row.id, row.spec.problem, 0.0, RowOutcomeKind::passed, {}, row_summary(row), {}};
    if (const auto it = by_row.find(row.id); it != by_row.end()) {
      o.wall_seconds = wall_seconds(it->second);
      for (const CaseResult* c : it->second) {
        if (c->status != CaseStatus::converged)
          o.reasons.push_back(case_status_line(*c));
      }
    }
    if (!o.reasons.empty()) {
      o.kind = RowOutcomeKind::error;
    } else if (!has_verdict(row)) {
      o.kind = RowOutcomeKind::skipped;
      o.reasons.push_back("not graded: no value to grade and no convergence or divergence verdict");
    }
    out.push_back(std::move(o));
  }
  return out;
}

std::vector<RowOutcome> gate_row_outcomes(const schema::Baseline& baseline,
                                          const GateReport& report,
                                          const std::vector<CaseResult>& results) {
  std::map<std::string, std::vector<const GateFailure*>> failures;
  for (const auto& f : report.failures) {
    for (const auto& id : f.row_ids)
      failures[id].push_back(&f);
  }
  std::map<std::string, const RowVerdict*> old_rows;
  for (const auto& r : baseline.rows)
    old_rows[r.id] = &r;
  std::map<std::string, const CaseResult*> new_cases;
  for (const auto& c : results)
    new_cases[case_id(c.spec)] = &c;
  const CasesByRow old_by_row = cases_by_row(baseline.cases);
  const CasesByRow new_by_row = cases_by_row(results);
  static const std::vector<const CaseResult*> kNone;

  std::vector<RowOutcome> out;
  for (const auto& row : make_row_verdicts(results)) {
    const auto old_it = old_rows.find(row.id);
    const RowVerdict* old_row = old_it == old_rows.end() ? nullptr : old_it->second;
    const auto old_cases_it = old_by_row.find(row.id);
    const auto& old_cases = old_cases_it == old_by_row.end() ? kNone : old_cases_it->second;
    const auto new_cases_it = new_by_row.find(row.id);
    RowOutcome o{row.id,
                 row.spec.problem,
                 new_cases_it == new_by_row.end() ? 0.0 : wall_seconds(new_cases_it->second),
                 RowOutcomeKind::passed,
                 {},
                 row_summary(row),
                 movement(old_row, row, old_cases, new_cases)};
    bool stopped_converging = false;
    if (const auto it = failures.find(row.id); it != failures.end()) {
      for (const GateFailure* f : it->second) {
        o.reasons.push_back(failure_line(*f));
        stopped_converging = stopped_converging || f->check == "status";
      }
      o.kind = stopped_converging ? RowOutcomeKind::error : RowOutcomeKind::failed;
    } else if (!gate_compares(old_row, old_cases, row.quantity)) {
      o.kind = RowOutcomeKind::skipped;
      o.reasons.push_back(
          "not compared: the baseline holds no value, grade or verdict of this row");
    }
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace cs::suites
