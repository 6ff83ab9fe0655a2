#include "suites/gate.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "grading/grade_change.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

std::string number_text(double v) {
  return std::isfinite(v) ? fmt::format("{:.10g}", v) : std::string("none");
}

std::string optional_bool_text(const std::optional<bool>& v) {
  return v ? (*v ? "yes" : "no") : "n/a";
}

/// Every row a case belongs to (one per quantity).
std::vector<std::string> row_ids(const CaseResult& c) {
  std::vector<std::string> ids;
  for (const auto& q : c.quantities)
    ids.push_back(row_id(c.spec, q.quantity));
  return ids;
}

/// A value that was finite must stay within tolerance; a value that was missing may appear.
void check_case(const Baseline& baseline, const CaseResult& old_case, const CaseResult& new_case,
                GateReport& report) {
  const std::string id = case_id(old_case.spec);
  if (old_case.status == CaseStatus::converged && new_case.status != CaseStatus::converged) {
    report.failures.push_back({id, "status", std::string(to_string(old_case.status)),
                               std::string(to_string(new_case.status)), new_case.reason,
                               row_ids(old_case)});
  }
  for (const auto& q_old : old_case.quantities) {
    if (!std::isfinite(q_old.value))
      continue;
    const QuantityResult* q_new = nullptr;
    for (const auto& q : new_case.quantities) {
      if (q.quantity == q_old.quantity)
        q_new = &q;
    }
    const std::string qid = id + " " + std::string(to_string(q_old.quantity));
    if (q_new == nullptr || !std::isfinite(q_new->value)) {
      report.failures.push_back({qid,
                                 "value drift",
                                 number_text(q_old.value),
                                 "none",
                                 "no value",
                                 {row_id(old_case.spec, q_old.quantity)}});
      continue;
    }
    const double tol = baseline.tolerances.of(q_old.quantity);
    const double drift = grading::relative_drift(q_old.value, q_new->value);
    if (!(drift <= tol)) {
      report.failures.push_back(
          {qid,
           "value drift",
           number_text(q_old.value),
           number_text(q_new->value),
           fmt::format("relative drift {:.3g} > tolerance {:.3g}", drift, tol),
           {row_id(old_case.spec, q_old.quantity)}});
    }
  }
}

void check_row(const Baseline& baseline, const RowVerdict& old_row, const RowVerdict& new_row,
               GateReport& report) {
  if (old_row.grade) {
    const double round_off_tol =
        grading::round_off_tolerance(baseline.tolerances.of(old_row.quantity));
    const bool round_off = grading::grade_change_is_round_off(old_row, new_row, round_off_tol);
    if (!new_row.grade || (is_worse(*new_row.grade, *old_row.grade) && !round_off)) {
      report.failures.push_back({old_row.id,
                                 "grade",
                                 std::string(to_string(*old_row.grade)),
                                 new_row.grade ? std::string(to_string(*new_row.grade)) : "none",
                                 "worse against the exact value (Eq. 46)",
                                 {old_row.id}});
    }
  }
  if (old_row.converging.value_or(false) && !new_row.converging.value_or(false)) {
    report.failures.push_back({old_row.id,
                               "converging",
                               optional_bool_text(old_row.converging),
                               optional_bool_text(new_row.converging),
                               "stopped converging",
                               {old_row.id}});
  }
  if (old_row.diverging.value_or(false) && !new_row.diverging.value_or(false)) {
    report.failures.push_back({old_row.id,
                               "diverging",
                               optional_bool_text(old_row.diverging),
                               optional_bool_text(new_row.diverging),
                               "no longer diverges at the singular edge (Eq. 47)",
                               {old_row.id}});
  }
}

}  // namespace

Baseline make_baseline(const std::vector<CaseResult>& cases,
                       const schema::GateTolerances& tolerances) {
  Baseline b;
  b.tolerances = tolerances;
  for (const auto& c : cases) {
    CaseResult slim;
    slim.spec = c.spec;
    slim.status = c.status;
    slim.reason = c.reason;
    slim.quantities = c.quantities;
    b.cases.push_back(std::move(slim));
  }
  b.rows = make_row_verdicts(cases);
  return b;
}

GateReport run_gate(const Baseline& baseline, const std::vector<CaseResult>& results) {
  std::map<std::string, const CaseResult*> new_cases;
  for (const auto& c : results)
    new_cases[case_id(c.spec)] = &c;
  std::set<std::string> old_ids;
  for (const auto& c : baseline.cases)
    old_ids.insert(case_id(c.spec));
  std::vector<std::string> only_old, only_new;
  for (const auto& id : old_ids) {
    if (!new_cases.count(id))
      only_old.push_back(id);
  }
  for (const auto& [id, c] : new_cases) {
    if (!old_ids.count(id))
      only_new.push_back(id);
  }
  if (!only_old.empty() || !only_new.empty()) {
    auto list = [](const std::vector<std::string>& ids) {
      std::string s;
      for (std::size_t i = 0; i < ids.size() && i < 10; ++i)
        s += (i ? ", " : "") + ids[i];
      if (ids.size() > 10)
        s += fmt::format(", ... ({} in all)", ids.size());
      return s.empty() ? std::string("none") : s;
    };
    throw SuiteInputError(
        fmt::format("the files cover different cases: only in the baseline: {}; "
                    "only in the results: {}",
                    list(only_old), list(only_new)));
  }
  GateReport report;
  for (const auto& old_case : baseline.cases) {
    check_case(baseline, old_case, *new_cases.at(case_id(old_case.spec)), report);
    ++report.cases_checked;
  }
  std::map<std::string, RowVerdict> new_rows;
  for (auto& r : make_row_verdicts(results))
    new_rows[r.id] = r;
  for (const auto& old_row : baseline.rows) {
    const auto it = new_rows.find(old_row.id);
    if (it == new_rows.end())
      continue;  // cannot happen when the cases match
    check_row(baseline, old_row, it->second, report);
    ++report.rows_checked;
  }
  return report;
}

std::string failure_line(const GateFailure& failure) {
  std::string line = fmt::format("{} of {}: now {}, baseline {}", failure.check, failure.id,
                                 failure.after, failure.before);
  if (!failure.detail.empty())
    line += " (" + failure.detail + ")";
  for (char& c : line) {
    if (c == '\n' || c == '\r')
      c = ' ';
  }
  return line;
}

std::string format_gate_failures(const GateReport& report) {
  if (report.passed())
    return "";
  std::string out = "| case or row | check | baseline | now | detail |\n|---|---|---|---|---|\n";
  for (const auto& f : report.failures) {
    out += fmt::format("| {} | {} | {} | {} | {} |\n", f.id, f.check, f.before, f.after, f.detail);
  }
  return out;
}

}  // namespace cs::suites
