#include "suites/results_json.hpp"

#include <cmath>

#include <fmt/format.h>

#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

using nlohmann::json;

/// A finite number, or null: JSON has no NaN or infinity, and a result never prints one.
json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

template <class T>
json optional_number(const std::optional<T>& v) {
  return v && std::isfinite(static_cast<double>(*v)) ? json(*v) : json(nullptr);
}

json quantity_to_json(const QuantityResult& q) {
  json j{{"value", number_or_null(q.value)},
         {"exact", std::isfinite(q.exact) ? json(q.exact) : json("inf")},
         {"error_percent", number_or_null(q.error_percent)},
         {"grade", std::string(to_string(q.grade))}};
  j["contact_pressure"] = optional_number(q.contact_pressure);
  if (q.study_exact)
    j["study_exact"] = *q.study_exact;
  return j;
}

double number_from(const json& j, const char* key, const std::string& where) {
  if (!j.contains(key))
    throw SuiteInputError(fmt::format("{}: missing '{}'", where, key));
  const json& v = j.at(key);
  if (v.is_null())
    return std::nan("");
  if (v.is_string() && v.get<std::string>() == "inf")
    return INFINITY;
  if (!v.is_number())
    throw SuiteInputError(fmt::format("{}: '{}' is not a number", where, key));
  return v.get<double>();
}

std::string string_from(const json& j, const char* key, const std::string& where) {
  if (!j.contains(key) || !j.at(key).is_string()) {
    throw SuiteInputError(fmt::format("{}: missing or non-string '{}'", where, key));
  }
  return j.at(key).get<std::string>();
}

/// An array of numbers in which null stands for a value that was not finite.
std::vector<double> numbers_from(const json& j, const char* key) {
  std::vector<double> out;
  if (!j.contains(key) || !j.at(key).is_array())
    return out;
  for (const auto& v : j.at(key))
    out.push_back(v.is_number() ? v.get<double>() : std::nan(""));
  return out;
}

CaseResult case_from_json(const json& j, std::size_t index) {
  const std::string where = fmt::format("results case #{}", index);
  if (!j.is_object())
    throw SuiteInputError(where + ": not an object");
  CaseResult r;
  r.spec.problem = parse_problem(string_from(j, "problem", where));
  r.spec.mesh = parse_mesh_level(string_from(j, "mesh", where));
  r.spec.element = parse_element(string_from(j, "element", where));
  r.spec.algorithm = parse_algorithm(string_from(j, "algorithm", where));
  r.spec.contact = parse_contact(string_from(j, "contact", where));
  r.spec.target = parse_target(string_from(j, "target", where));
  r.spec.recovery = parse_recovery(string_from(j, "recovery", where));
  if (j.contains("overrides") && j.at("overrides").is_object()) {
    for (const auto& [k, v] : j.at("overrides").items())
      r.spec.overrides[k] = v.get<double>();
  }
  r.status = parse_case_status(string_from(j, "status", where));
  r.reason = j.value("reason", "");
  r.iterations = j.value("iterations", 0);
  r.wall_seconds = number_from(j, "wall_seconds", where);
  r.peak_rss_mb = j.value("peak_rss_mb", 0.0);
  r.n_elements = j.value("n_elements", 0);
  r.n_equations = j.value("n_equations", 0);
  r.element_size_h = j.value("element_size_h", 0.0);
  if (!j.contains("quantities") || !j.at("quantities").is_object()) {
    throw SuiteInputError(where + ": missing 'quantities'");
  }
  for (const auto& [name, q] : j.at("quantities").items()) {
    const std::string qwhere = where + " quantity " + name;
    QuantityResult qr;
    qr.name = name;
    qr.value = number_from(q, "value", qwhere);
    qr.exact = number_from(q, "exact", qwhere);
    qr.error_percent = number_from(q, "error_percent", qwhere);
    qr.grade = parse_grade(string_from(q, "grade", qwhere));
    if (q.contains("contact_pressure") && q.at("contact_pressure").is_number()) {
      qr.contact_pressure = q.at("contact_pressure").get<double>();
    }
    if (q.contains("study_exact"))
      qr.study_exact = q.at("study_exact").get<double>();
    r.quantities.push_back(qr);
  }
  if (j.contains("profile") && j.at("profile").is_object()) {
    const json& p = j.at("profile");
    r.profile.x_over_a = numbers_from(p, "x_over_a");
    r.profile.sigma_z_over_p = numbers_from(p, "sigma_z_over_p");
    r.profile.pressure_over_p = numbers_from(p, "pressure_over_p");
  }
  if (j.contains("exact_profile") && j.at("exact_profile").is_object()) {
    r.exact_profile.x_over_a = numbers_from(j.at("exact_profile"), "x_over_a");
    r.exact_profile.sigma_z_over_p = numbers_from(j.at("exact_profile"), "sigma_z_over_p");
  }
  return r;
}

}  // namespace

std::string_view to_string(CaseStatus status) {
  switch (status) {
    case CaseStatus::converged:
      return "converged";
    case CaseStatus::not_converged:
      return "not_converged";
    case CaseStatus::failed:
      return "failed";
  }
  return "?";
}

CaseStatus parse_case_status(std::string_view text) {
  if (text == "converged")
    return CaseStatus::converged;
  if (text == "not_converged")
    return CaseStatus::not_converged;
  if (text == "failed")
    return CaseStatus::failed;
  throw SuiteInputError(fmt::format("unknown case status '{}'", text));
}

json to_json(const CaseResult& r) {
  json j{{"id", case_id(r.spec)},
         {"problem", std::string(to_string(r.spec.problem))},
         {"mesh", std::string(to_string(r.spec.mesh))},
         {"element", std::string(to_string(r.spec.element))},
         {"algorithm", std::string(to_string(r.spec.algorithm))},
         {"contact", std::string(to_string(r.spec.contact))},
         {"target", std::string(to_string(r.spec.target))},
         {"recovery", std::string(to_string(r.spec.recovery))},
         {"overrides", json(r.spec.overrides)},
         {"status", std::string(to_string(r.status))},
         {"reason", r.reason},
         {"iterations", r.iterations},
         {"wall_seconds", number_or_null(r.wall_seconds)},
         {"peak_rss_mb", number_or_null(r.peak_rss_mb)},
         {"n_elements", r.n_elements},
         {"n_equations", r.n_equations},
         {"element_size_h", number_or_null(r.element_size_h)}};
  json quantities = json::object();
  for (const auto& q : r.quantities)
    quantities[q.name] = quantity_to_json(q);
  j["quantities"] = quantities;
  auto finite_or_null = [](const std::vector<double>& v) {
    json a = json::array();
    for (double x : v)
      a.push_back(number_or_null(x));
    return a;
  };
  j["profile"] = {{"x_over_a", finite_or_null(r.profile.x_over_a)},
                  {"sigma_z_over_p", finite_or_null(r.profile.sigma_z_over_p)},
                  {"pressure_over_p", finite_or_null(r.profile.pressure_over_p)}};
  if (!r.exact_profile.x_over_a.empty()) {
    j["exact_profile"] = {{"x_over_a", finite_or_null(r.exact_profile.x_over_a)},
                          {"sigma_z_over_p", finite_or_null(r.exact_profile.sigma_z_over_p)}};
  }
  return j;
}

json to_json(const RowVerdict& row) {
  json j{{"id", row.id},
         {"problem", std::string(to_string(row.problem))},
         {"element", std::string(to_string(row.element))},
         {"algorithm", std::string(to_string(row.algorithm))},
         {"contact", std::string(to_string(row.contact))},
         {"target", std::string(to_string(row.target))},
         {"recovery", std::string(to_string(row.recovery))},
         {"quantity", row.quantity}};
  json values = json::object(), errors = json::object();
  for (MeshLevel level : all_mesh_levels()) {
    const auto i = static_cast<std::size_t>(level);
    const std::string name(to_string(level));
    values[name] = optional_number(row.values[i]);
    errors[name] = optional_number(row.errors[i]);
  }
  j["values"] = values;
  j["error_percent"] = errors;
  j["grade"] = row.grade ? json(std::string(to_string(*row.grade))) : json(nullptr);
  j["graded_mesh"] =
      row.graded_mesh ? json(std::string(to_string(*row.graded_mesh))) : json(nullptr);
  j["converging"] = row.converging ? json(*row.converging) : json(nullptr);
  j["diverging"] = row.diverging ? json(*row.diverging) : json(nullptr);
  return j;
}

json make_results_document(const RunInfo& run, const std::vector<CaseResult>& cases) {
  json doc{{"schema", kResultsSchemaName}, {"schema_version", kResultsSchemaVersion}};
  doc["run"] = {{"started_utc", run.started_utc},
                {"wall_seconds", number_or_null(run.wall_seconds)},
                {"jobs", run.jobs},
                {"peak_rss_mb", number_or_null(run.peak_rss_mb)},
                {"command_line", run.command_line},
                {"environment", run.environment}};
  json case_array = json::array();
  for (const auto& c : cases)
    case_array.push_back(to_json(c));
  doc["cases"] = case_array;
  json rows = json::array();
  for (const auto& row : make_row_verdicts(cases))
    rows.push_back(to_json(row));
  doc["rows"] = rows;
  return doc;
}

std::vector<CaseResult> cases_from_results_document(const json& doc) {
  if (!doc.is_object() || doc.value("schema", "") != kResultsSchemaName) {
    throw SuiteInputError(fmt::format("not a contact-suite results file (no \"schema\": \"{}\")",
                                      kResultsSchemaName));
  }
  const int version = doc.value("schema_version", -1);
  if (version != kResultsSchemaVersion) {
    throw SuiteInputError(fmt::format("results schema version {} is not supported (expected {})",
                                      version, kResultsSchemaVersion));
  }
  if (!doc.contains("cases") || !doc.at("cases").is_array()) {
    throw SuiteInputError("results file has no 'cases' array");
  }
  std::vector<CaseResult> out;
  const json& cases = doc.at("cases");
  for (std::size_t i = 0; i < cases.size(); ++i)
    out.push_back(case_from_json(cases[i], i));
  return out;
}

}  // namespace cs::suites
