#include "suites/gate.hpp"

#include <cmath>
#include <set>

#include <fmt/format.h>

#include "suites/results_json.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

using nlohmann::json;

std::string number_text(double v) {
  return std::isfinite(v) ? fmt::format("{:.10g}", v) : std::string("none");
}

std::string optional_bool_text(const std::optional<bool>& v) {
  return v ? (*v ? "yes" : "no") : "n/a";
}

double tolerance_for(const Baseline& b, const std::string& quantity) {
  const auto it = b.tolerances.find(quantity);
  return it != b.tolerances.end() ? it->second : b.default_tolerance;
}

/// A value that was finite must stay within tolerance; a value that was missing may appear.
void check_case(const Baseline& baseline, const CaseResult& old_case, const CaseResult& new_case,
                GateReport& report) {
  const std::string id = case_id(old_case.spec);
  if (old_case.status == CaseStatus::converged && new_case.status != CaseStatus::converged) {
    report.failures.push_back({id, "status", std::string(to_string(old_case.status)),
                               std::string(to_string(new_case.status)), new_case.reason});
  }
  for (const auto& q_old : old_case.quantities) {
    if (!std::isfinite(q_old.value))
      continue;
    const QuantityResult* q_new = nullptr;
    for (const auto& q : new_case.quantities) {
      if (q.name == q_old.name)
        q_new = &q;
    }
    const std::string qid = id + " " + q_old.name;
    if (q_new == nullptr || !std::isfinite(q_new->value)) {
      report.failures.push_back({qid, "value drift", number_text(q_old.value), "none", "no value"});
      continue;
    }
    const double tol = tolerance_for(baseline, q_old.name);
    const double drift =
        std::abs(q_new->value - q_old.value) / std::max(std::abs(q_old.value), 1e-300);
    if (!(drift <= tol)) {
      report.failures.push_back(
          {qid, "value drift", number_text(q_old.value), number_text(q_new->value),
           fmt::format("relative drift {:.3g} > tolerance {:.3g}", drift, tol)});
    }
  }
}

void check_row(const RowVerdict& old_row, const RowVerdict& new_row, GateReport& report) {
  if (old_row.grade) {
    if (!new_row.grade || is_worse(*new_row.grade, *old_row.grade)) {
      report.failures.push_back({old_row.id, "grade", std::string(to_string(*old_row.grade)),
                                 new_row.grade ? std::string(to_string(*new_row.grade)) : "none",
                                 "worse against the exact value (Eq. 46)"});
    }
  }
  if (old_row.converging.value_or(false) && !new_row.converging.value_or(false)) {
    report.failures.push_back({old_row.id, "converging", optional_bool_text(old_row.converging),
                               optional_bool_text(new_row.converging), "stopped converging"});
  }
  if (old_row.diverging.value_or(false) && !new_row.diverging.value_or(false)) {
    report.failures.push_back({old_row.id, "diverging", optional_bool_text(old_row.diverging),
                               optional_bool_text(new_row.diverging),
                               "no longer diverges at the singular edge (Eq. 47)"});
  }
}

std::optional<Grade> grade_from(const json& j) {
  if (!j.contains("grade") || j.at("grade").is_null())
    return std::nullopt;
  return parse_grade(j.at("grade").get<std::string>());
}

std::optional<bool> bool_from(const json& j, const char* key) {
  if (!j.contains(key) || j.at(key).is_null())
    return std::nullopt;
  return j.at(key).get<bool>();
}

}  // namespace

Baseline make_baseline(const std::vector<CaseResult>& cases, double default_tolerance,
                       const std::map<std::string, double>& tolerances) {
  Baseline b;
  b.default_tolerance = default_tolerance;
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

json to_json(const Baseline& b) {
  json doc{{"schema", kBaselineSchemaName},
           {"schema_version", kBaselineSchemaVersion},
           {"default_tolerance", b.default_tolerance},
           {"tolerances", json(b.tolerances)}};
  json cases = json::array();
  for (const auto& c : b.cases) {
    json j = to_json(c);
    // A baseline keeps what the gate compares: no timings, memory or profiles.
    for (const char* key : {"wall_seconds", "peak_rss_mb", "profile", "exact_profile", "iterations",
                            "n_elements", "n_equations", "element_size_h"}) {
      j.erase(key);
    }
    cases.push_back(j);
  }
  doc["cases"] = cases;
  json rows = json::array();
  for (const auto& r : b.rows)
    rows.push_back(to_json(r));
  doc["rows"] = rows;
  return doc;
}

namespace {

void check_baseline_schema(const json& doc) {
  if (!doc.is_object() || doc.value("schema", "") != kBaselineSchemaName) {
    throw SuiteInputError(
        fmt::format("not a contact-suite baseline (no \"schema\": \"{}\")", kBaselineSchemaName));
  }
}

}  // namespace

std::pair<double, std::map<std::string, double>> baseline_tolerances_from_json(const json& doc) {
  check_baseline_schema(doc);
  try {
    std::map<std::string, double> tolerances;
    if (doc.contains("tolerances"))
      tolerances = doc.at("tolerances").get<std::map<std::string, double>>();
    return {doc.value("default_tolerance", kDefaultGateTolerance), tolerances};
  } catch (const json::exception& e) {
    throw SuiteInputError(fmt::format("malformed baseline tolerances: {}", e.what()));
  }
}

Baseline baseline_from_json(const json& doc) {
  check_baseline_schema(doc);
  if (doc.value("schema_version", -1) != kBaselineSchemaVersion) {
    throw SuiteInputError(fmt::format("baseline schema version {} is not supported (expected {})",
                                      doc.value("schema_version", -1), kBaselineSchemaVersion));
  }
  Baseline b;
  try {
    b.default_tolerance = doc.value("default_tolerance", kDefaultGateTolerance);
    if (doc.contains("tolerances"))
      b.tolerances = doc.at("tolerances").get<std::map<std::string, double>>();
    // The case records share the results schema, less the fields a baseline drops.
    json as_results{{"schema", kResultsSchemaName}, {"schema_version", kResultsSchemaVersion}};
    json cases = doc.at("cases");
    for (auto& c : cases) {
      if (!c.contains("wall_seconds"))
        c["wall_seconds"] = nullptr;
    }
    as_results["cases"] = cases;
    b.cases = cases_from_results_document(as_results);
    for (const auto& r : doc.at("rows")) {
      RowVerdict row;
      row.id = r.at("id").get<std::string>();
      row.problem = parse_problem(r.at("problem").get<std::string>());
      row.quantity = r.at("quantity").get<std::string>();
      row.grade = grade_from(r);
      row.converging = bool_from(r, "converging");
      row.diverging = bool_from(r, "diverging");
      b.rows.push_back(row);
    }
  } catch (const json::exception& e) {
    throw SuiteInputError(fmt::format("malformed baseline: {}", e.what()));
  }
  if (!(b.default_tolerance > 0.0))
    throw SuiteInputError("baseline default_tolerance must be > 0");
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
    check_row(old_row, it->second, report);
    ++report.rows_checked;
  }
  return report;
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
