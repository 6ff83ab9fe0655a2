#include "reports/results_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include <fmt/format.h>

#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

using nlohmann::json;

/// Accepted names of the schema's string fields (docs/results-schema.md).
const std::initializer_list<const char*> kProblems{
    "P_p", "P_a", "Pprime_p", "Pprime_a", "H_p", "H_a", "S_1", "S_1_3", "S_1_7", "F_p", "F_a"};
const std::initializer_list<const char*> kMeshes{"C", "M", "F"};
const std::initializer_list<const char*> kElements{"Q4", "Q8"};
const std::initializer_list<const char*> kAlgorithms{"AL", "PM", "LMP", "PLM", "MPC"};
const std::initializer_list<const char*> kContacts{"ns", "ss", "mortar"};
const std::initializer_list<const char*> kTargets{"discretized", "rigid"};
const std::initializer_list<const char*> kRecoveries{"spr", "extrapolated"};
const std::initializer_list<const char*> kStatuses{"converged", "not_converged", "failed"};
const std::initializer_list<const char*> kGrades{"e", "g", "s", "u"};

std::string joined(std::initializer_list<const char*> names) {
  std::string out;
  for (const char* n : names) {
    if (!out.empty())
      out += ", ";
    out += n;
  }
  return out;
}

/// Reads the fields of one JSON object, naming the file and the record in every error.
class FieldReader {
 public:
  FieldReader(const json& object, std::string where) : object_(object), where_(std::move(where)) {
    if (!object_.is_object())
      fail("is not a JSON object");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw ReportError(fmt::format("{}: {}", where_, what));
  }

  bool has(const char* key) const { return object_.contains(key); }
  const json& at(const char* key) const { return object_.at(key); }

  std::string string(const char* key) const {
    if (!has(key))
      fail(fmt::format("missing '{}'", key));
    if (!at(key).is_string())
      fail(fmt::format("'{}' is not a string", key));
    return at(key).get<std::string>();
  }

  std::string name(const char* key, std::initializer_list<const char*> accepted) const {
    std::string v = string(key);
    if (std::none_of(accepted.begin(), accepted.end(), [&](const char* a) { return v == a; }))
      fail(fmt::format("'{}' is \"{}\", expected one of {}", key, v, joined(accepted)));
    return v;
  }

  std::string optional_string(const char* key) const {
    if (!has(key) || at(key).is_null())
      return {};
    if (!at(key).is_string())
      fail(fmt::format("'{}' is not a string", key));
    return at(key).get<std::string>();
  }

  /// A number or null (nullopt); absent keys are nullopt unless `required`.
  std::optional<double> number(const char* key, bool required = false) const {
    if (!has(key)) {
      if (required)
        fail(fmt::format("missing '{}'", key));
      return std::nullopt;
    }
    return number_value(at(key), key);
  }

  std::optional<double> number_value(const json& v, const std::string& key) const {
    if (v.is_null())
      return std::nullopt;
    if (!v.is_number())
      fail(fmt::format("'{}' is not a number or null", key));
    const double d = v.get<double>();
    return std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
  }

  template <class Int>
  Int integer(const char* key, Int fallback) const {
    if (!has(key) || at(key).is_null())
      return fallback;
    if (!at(key).is_number_integer() && !at(key).is_number_unsigned())
      fail(fmt::format("'{}' is not an integer", key));
    return at(key).get<Int>();
  }

  const std::string& where() const { return where_; }

 private:
  const json& object_;
  std::string where_;
};

std::vector<double> numbers_or_nan(const FieldReader& r, const json& array, const char* key) {
  std::vector<double> out;
  if (!array.is_array())
    r.fail(fmt::format("'{}' is not an array", key));
  out.reserve(array.size());
  for (const auto& v : array) {
    const auto d = r.number_value(v, key);
    out.push_back(d ? *d : std::nan(""));
  }
  return out;
}

ProfileCurve read_curve(const FieldReader& parent, const char* key) {
  ProfileCurve curve;
  if (!parent.has(key) || parent.at(key).is_null())
    return curve;
  const FieldReader r(parent.at(key), parent.where() + " " + key);
  if (r.has("x_over_a"))
    curve.x_over_a = numbers_or_nan(r, r.at("x_over_a"), "x_over_a");
  if (r.has("sigma_z_over_p"))
    curve.sigma_z_over_p = numbers_or_nan(r, r.at("sigma_z_over_p"), "sigma_z_over_p");
  if (r.has("pressure_over_p"))
    curve.pressure_over_p = numbers_or_nan(r, r.at("pressure_over_p"), "pressure_over_p");
  if (!curve.sigma_z_over_p.empty() && curve.sigma_z_over_p.size() != curve.x_over_a.size())
    r.fail("'x_over_a' and 'sigma_z_over_p' differ in length");
  if (!curve.pressure_over_p.empty() && curve.pressure_over_p.size() != curve.x_over_a.size())
    r.fail("'x_over_a' and 'pressure_over_p' differ in length");
  return curve;
}

QuantityRecord read_quantity(const std::string& name, const json& j, const std::string& where) {
  const FieldReader r(j, fmt::format("{} quantity '{}'", where, name));
  QuantityRecord q;
  q.name = name;
  q.value = r.number("value", true);
  if (!r.has("exact"))
    r.fail("missing 'exact'");
  if (r.at("exact").is_string()) {
    if (r.at("exact").get<std::string>() != "inf")
      r.fail("'exact' is a string other than \"inf\"");
    q.singular = true;
  } else {
    q.exact = r.number("exact", true);
  }
  q.error_percent = r.number("error_percent");
  q.grade = r.name("grade", kGrades);
  q.contact_pressure = r.number("contact_pressure");
  q.study_exact = r.number("study_exact");
  return q;
}

CaseRecord read_case(const json& j, std::size_t index, const std::string& source) {
  std::string where = fmt::format("{}: case #{}", source, index);
  if (j.is_object() && j.contains("id") && j.at("id").is_string())
    where += fmt::format(" ({})", j.at("id").get<std::string>());
  const FieldReader r(j, where);
  CaseRecord c;
  c.id = r.string("id");
  c.problem = r.name("problem", kProblems);
  c.mesh = r.name("mesh", kMeshes);
  c.element = r.name("element", kElements);
  c.algorithm = r.name("algorithm", kAlgorithms);
  c.contact = r.name("contact", kContacts);
  c.target = r.name("target", kTargets);
  c.recovery = r.name("recovery", kRecoveries);
  if (r.has("overrides") && !r.at("overrides").is_null()) {
    if (!r.at("overrides").is_object())
      r.fail("'overrides' is not an object");
    for (const auto& [k, v] : r.at("overrides").items()) {
      if (!v.is_number())
        r.fail(fmt::format("override '{}' is not a number", k));
      c.overrides[k] = v.get<double>();
    }
  }
  c.status = r.name("status", kStatuses);
  c.reason = r.optional_string("reason");
  c.iterations = r.integer<int>("iterations", 0);
  c.wall_seconds = r.number("wall_seconds");
  c.peak_rss_mb = r.number("peak_rss_mb");
  c.n_elements = r.integer<long>("n_elements", 0);
  c.n_equations = r.integer<long>("n_equations", 0);
  c.element_size_h = r.number("element_size_h");
  if (!r.has("quantities") || !r.at("quantities").is_object())
    r.fail("missing or non-object 'quantities'");
  for (const auto& [name, q] : r.at("quantities").items())
    c.quantities.push_back(read_quantity(name, q, where));
  c.profile = read_curve(r, "profile");
  c.exact_profile = read_curve(r, "exact_profile");
  return c;
}

RowRecord read_row(const json& j, std::size_t index, const std::string& source) {
  std::string where = fmt::format("{}: row #{}", source, index);
  if (j.is_object() && j.contains("id") && j.at("id").is_string())
    where += fmt::format(" ({})", j.at("id").get<std::string>());
  const FieldReader r(j, where);
  RowRecord row;
  row.id = r.string("id");
  row.problem = r.name("problem", kProblems);
  row.element = r.name("element", kElements);
  row.algorithm = r.name("algorithm", kAlgorithms);
  row.contact = r.name("contact", kContacts);
  row.target = r.name("target", kTargets);
  row.recovery = r.name("recovery", kRecoveries);
  row.quantity = r.string("quantity");
  for (const char* key : {"values", "error_percent"}) {
    if (!r.has(key) || !r.at(key).is_object())
      r.fail(fmt::format("missing or non-object '{}'", key));
    const FieldReader per_mesh(r.at(key), where + " " + key);
    auto& target = std::string(key) == "values" ? row.values : row.errors;
    for (std::size_t m = 0; m < kMeshLevels.size(); ++m)
      target[m] = per_mesh.number(kMeshLevels[m]);
  }
  if (r.has("grade") && !r.at("grade").is_null())
    row.grade = r.name("grade", kGrades);
  if (r.has("graded_mesh") && !r.at("graded_mesh").is_null())
    row.graded_mesh = r.name("graded_mesh", kMeshes);
  for (const char* key : {"converging", "diverging"}) {
    if (!r.has(key) || r.at(key).is_null())
      continue;
    if (!r.at(key).is_boolean())
      r.fail(fmt::format("'{}' is not true, false or null", key));
    (std::string(key) == "converging" ? row.converging : row.diverging) = r.at(key).get<bool>();
  }
  return row;
}

RunRecord read_run(const json& doc, const std::string& source) {
  if (!doc.contains("run"))
    throw ReportError(source + ": missing 'run'");
  const FieldReader r(doc.at("run"), source + ": run");
  RunRecord run;
  run.started_utc = r.optional_string("started_utc");
  run.wall_seconds = r.number("wall_seconds");
  run.jobs = r.integer<int>("jobs", 1);
  run.peak_rss_mb = r.number("peak_rss_mb");
  run.command_line = r.optional_string("command_line");
  if (r.has("environment") && !r.at("environment").is_null())
    run.environment = r.at("environment");
  return run;
}

}  // namespace

const QuantityRecord* CaseRecord::quantity(const std::string& name) const {
  for (const auto& q : quantities) {
    if (q.name == name)
      return &q;
  }
  return nullptr;
}

std::string RowRecord::case_key() const {
  const auto slash = id.rfind('/');
  return slash == std::string::npos ? id : id.substr(0, slash);
}

std::string RowRecord::variant() const {
  // id: problem/element/algorithm/contact[/variant...]/quantity
  const std::string key = case_key();
  std::size_t pos = 0;
  for (int field = 0; field < 4; ++field) {
    pos = key.find('/', pos);
    if (pos == std::string::npos)
      return {};
    ++pos;
  }
  return key.substr(pos);
}

std::string case_key_of(const std::string& case_id) {
  const auto first = case_id.find('/');
  if (first == std::string::npos)
    return case_id;
  const auto second = case_id.find('/', first + 1);
  if (second == std::string::npos)
    return case_id.substr(0, first);
  return case_id.substr(0, first) + case_id.substr(second);
}

ResultsFile parse_results_document(const json& doc, const std::string& source) {
  if (!doc.is_object())
    throw ReportError(
        fmt::format("{}: not a contact-suite results file (not a JSON object)", source));
  const std::string schema = doc.contains("schema") && doc.at("schema").is_string()
                                 ? doc.at("schema").get<std::string>()
                                 : std::string("none");
  if (schema != kResultsSchemaName) {
    throw ReportError(
        fmt::format("{}: not a contact-suite results file (schema \"{}\", expected \"{}\")", source,
                    schema, kResultsSchemaName));
  }
  if (!doc.contains("schema_version") || !doc.at("schema_version").is_number_integer()) {
    throw ReportError(fmt::format("{}: missing or non-integer 'schema_version'", source));
  }
  const int version = doc.at("schema_version").get<int>();
  if (version != kResultsSchemaVersion) {
    throw ReportError(
        fmt::format("{}: results schema version {} is not supported (this report reads "
                    "version {})",
                    source, version, kResultsSchemaVersion));
  }
  ResultsFile out;
  out.source = source;
  out.run = read_run(doc, source);
  for (const char* key : {"cases", "rows"}) {
    if (!doc.contains(key) || !doc.at(key).is_array())
      throw ReportError(fmt::format("{}: missing or non-array '{}'", source, key));
  }
  const json& cases = doc.at("cases");
  for (std::size_t i = 0; i < cases.size(); ++i)
    out.cases.push_back(read_case(cases[i], i, source));
  const json& rows = doc.at("rows");
  for (std::size_t i = 0; i < rows.size(); ++i)
    out.rows.push_back(read_row(rows[i], i, source));
  return out;
}

ResultsFile load_results_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw ReportError(fmt::format("results file '{}' does not exist", name));
  if (!std::filesystem::is_regular_file(path, ec))
    throw ReportError(fmt::format("results file '{}' is not a regular file", name));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw ReportError(fmt::format("results file '{}' cannot be read", name));
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().empty())
    throw ReportError(fmt::format("results file '{}' is empty", name));
  json doc;
  try {
    doc = json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw ReportError(
        fmt::format("results file '{}' is not valid JSON (truncated?): {}", name, e.what()));
  }
  return parse_results_document(doc, name);
}

}  // namespace cs::reports
