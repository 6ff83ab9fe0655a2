#include "schema/baseline_file.hpp"

#include <limits>
#include <set>

#include <fmt/format.h>

#include "schema/json_fields.hpp"
#include "schema/json_file.hpp"
#include "schema/results_file.hpp"
#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

using nlohmann::json;

JsonFields checked_baseline(const json& doc, const std::string& source) {
  const JsonFields r(doc, source);
  if (r.string("schema") != kBaselineSchemaName) {
    r.fail_field("schema",
                 fmt::format("is not \"{}\": not a contact-suite baseline", kBaselineSchemaName));
  }
  return r;
}

double positive_tolerance(const JsonFields& r, const char* key) {
  const double t = r.number(key, false);
  if (!(t > 0.0))
    r.fail_field(key, fmt::format("{} is not a positive tolerance", t));
  return t;
}

}  // namespace

double GateTolerances::of(Quantity q) const {
  const auto it = per_quantity.find(q);
  return it != per_quantity.end() ? it->second : default_tolerance;
}

json to_json(const Baseline& b) {
  json tolerances = json::object();
  for (const auto& [q, t] : b.tolerances.per_quantity)
    tolerances[std::string(to_string(q))] = t;
  json doc{{"schema", kBaselineSchemaName},
           {"schema_version", kBaselineSchemaVersion},
           {"default_tolerance", b.tolerances.default_tolerance},
           {"tolerances", tolerances}};
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

GateTolerances tolerances_from_json(const json& doc, const std::string& source) {
  const JsonFields r = checked_baseline(doc, source);
  GateTolerances t;
  if (r.has("default_tolerance"))
    t.default_tolerance = positive_tolerance(r, "default_tolerance");
  if (r.has("tolerances")) {
    const JsonFields per = r.object("tolerances");
    for (const auto& [name, value] : r.at("tolerances").items()) {
      const auto q = try_parse<Quantity>(name);
      if (!q)
        per.fail_field(name, "unknown quantity");
      t.per_quantity[*q] = positive_tolerance(per, name.c_str());
    }
  }
  return t;
}

Baseline baseline_from_json(const json& doc, const std::string& source) {
  const JsonFields r = checked_baseline(doc, source);
  const auto version = r.integer("schema_version", 0, std::numeric_limits<int>::max());
  if (version != kBaselineSchemaVersion) {
    r.fail_field("schema_version", fmt::format("{} is not supported (this build reads {})", version,
                                               kBaselineSchemaVersion));
  }
  Baseline b;
  b.tolerances = tolerances_from_json(doc, source);
  const auto read_array = [&](const char* key, auto read) {
    const json& a = r.at(key);
    if (!a.is_array())
      r.fail_field(key, "is not an array");
    for (std::size_t i = 0; i < a.size(); ++i)
      read(a[i], fmt::format("{}[{}]", r.path_of(key), i));
  };
  std::set<std::string> ids;
  read_array("cases", [&](const json& j, const std::string& path) {
    b.cases.push_back(case_from_json(j, path));
    if (!ids.insert(case_id(b.cases.back().spec)).second)
      throw SchemaError(
          fmt::format("{}: duplicate case id \"{}\"", path, case_id(b.cases.back().spec)));
  });
  ids.clear();
  read_array("rows", [&](const json& j, const std::string& path) {
    b.rows.push_back(row_from_json(j, path));
    if (!ids.insert(b.rows.back().id).second)
      throw SchemaError(fmt::format("{}: duplicate row id \"{}\"", path, b.rows.back().id));
  });
  return b;
}

Baseline parse_baseline_text(std::string_view text, const std::string& source) {
  return baseline_from_json(parse_json_text(text, "baseline", source), source);
}

Baseline read_baseline_file(const std::filesystem::path& path) {
  return baseline_from_json(read_json_file(path, "baseline"), path.string());
}

void write_baseline_file(const std::filesystem::path& path, const Baseline& baseline) {
  write_json_file_atomically(path, to_json(baseline));
}

}  // namespace cs::schema
