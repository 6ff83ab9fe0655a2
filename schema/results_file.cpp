#include "schema/results_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <fmt/format.h>

#include "schema/json_fields.hpp"
#include "schema/json_file.hpp"
#include "schema/results_migration.hpp"
#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

using nlohmann::json;

constexpr long long kIntMax = std::numeric_limits<int>::max();
/// The older version read through results_migration.hpp.
constexpr int kMigratedSchemaVersion = 3;
/// Version 3's solver of every CalculiX case; version 4 names the option ("calculix:<label>").
constexpr std::string_view kCalculixWithoutOption = "calculix";

/// Files written before `kept_files` ended a kept run's reason with where its files were kept,
/// "... (files kept in DIR)" or "... (CalculiX files kept in DIR)": split into the two fields,
/// so that the reason is the same in every run.
void split_kept_files(CaseResult& c) {
  if (!c.kept_files.empty() || !c.reason.ends_with(")"))
    return;
  for (const std::string_view marker : {" (CalculiX files kept in ", " (files kept in "}) {
    const auto at = c.reason.rfind(marker);
    if (at == std::string::npos)
      continue;
    const auto dir = at + marker.size();
    c.kept_files = c.reason.substr(dir, c.reason.size() - 1 - dir);
    c.reason.erase(at);
    return;
  }
}

json numbers_or_null(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v)
    a.push_back(number_or_null(x));
  return a;
}

/// An array of numbers in which null stands for a value that was not finite.
std::vector<double> numbers_from(const JsonFields& r, const char* key) {
  std::vector<double> out;
  if (!r.has(key))
    return out;
  const json& a = r.at(key);
  if (!a.is_array())
    r.fail_field(key, "is not an array");
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].is_null()) {
      out.push_back(std::nan(""));
    } else if (a[i].is_number() && std::isfinite(a[i].get<double>())) {
      out.push_back(a[i].get<double>());
    } else {
      r.fail_field(key, fmt::format("item {} is not a finite number or null", i));
    }
  }
  return out;
}

json quantity_to_json(const QuantityResult& q) {
  json j{{"value", number_or_null(q.value)},
         {"exact", std::isinf(q.exact) ? json("inf") : number_or_null(q.exact)},
         {"error_percent", number_or_null(q.error_percent)},
         {"grade", std::string(to_string(q.grade))},
         {"contact_pressure", number_or_null(q.contact_pressure)}};
  if (q.study_exact)
    j["study_exact"] = *q.study_exact;
  return j;
}

QuantityResult quantity_from_json(const JsonFields& r, Quantity quantity) {
  QuantityResult q;
  q.quantity = quantity;
  q.value = r.number("value", true);
  if (r.has("exact") && r.at("exact").is_string()) {
    if (r.string("exact") != "inf")
      r.fail_field("exact", "is a string other than \"inf\"");
    q.exact = std::numeric_limits<double>::infinity();
  } else {
    q.exact = r.number("exact", false);
  }
  q.error_percent = r.number("error_percent", true);
  q.grade = r.name<Grade>("grade");
  q.contact_pressure = r.optional_number("contact_pressure");
  q.study_exact = r.optional_number("study_exact");
  return q;
}

/// The option axes a case and a row share.
void spec_to_json(const CaseSpec& s, json& j) {
  j["problem"] = to_string(s.problem);
  j["element"] = to_string(s.element);
  j["algorithm"] = to_string(s.algorithm);
  j["contact"] = to_string(s.contact);
  j["target"] = to_string(s.target);
  j["recovery"] = to_string(s.recovery);
  j["solver"] = solver_label(s);
  j["overrides"] = json(s.overrides);
}

CaseSpec spec_from_json(const JsonFields& r) {
  CaseSpec s;
  s.problem = r.name<ProblemId>("problem");
  s.element = r.name<Element>("element");
  s.algorithm = r.name<Algorithm>("algorithm");
  s.contact = r.name<ContactKind>("contact");
  s.target = r.name<TargetKind>("target");
  s.recovery = r.name<Recovery>("recovery");
  const std::string solver = r.string("solver");
  const auto colon = solver.find(':');
  if (const auto kind = try_parse<SolverKind>(solver);
      kind && *kind != SolverKind::imported && *kind != SolverKind::external) {
    s.solver = *kind;
  } else if (solver.empty() || solver == "imported" || solver == "external") {
    r.fail_field("solver",
                 "is empty, \"imported\" or \"external\": name the code the results "
                 "came from");
  } else if (solver == kCalculixWithoutOption) {
    r.fail_field("solver", "is \"calculix\" without its option (calculix:<option>)");
  } else if (colon != std::string::npos) {
    if (colon == 0 || colon + 1 == solver.size())
      r.fail_field("solver", "is not <code>:<option>");
    s.solver = SolverKind::external;
    s.solver_name = solver.substr(0, colon);
    s.solver_option = solver.substr(colon + 1);
  } else {
    s.solver = SolverKind::imported;
    s.solver_name = solver;
  }
  const JsonFields overrides = r.object("overrides");
  for (const auto& [key, value] : r.at("overrides").items()) {
    s.overrides[key] = overrides.number(key.c_str(), false);
  }
  return s;
}

void check_id(const JsonFields& r, const std::string& expected) {
  const std::string id = r.string("id");
  if (id != expected)
    r.fail_field("id", fmt::format("\"{}\" does not match its fields (\"{}\")", id, expected));
}

json problem_quantity_to_json(const QuantityDefinition& d) {
  return {{"quantity", to_string(d.quantity)},
          {"definition_md", d.definition_md},
          {"definition_plain", d.definition_plain},
          {"study_table", d.study_table},
          {"study_row", d.study_row}};
}

ProblemRecord problem_from_json(const json& j, const std::string& path) {
  const JsonFields r(j, path);
  ProblemRecord p;
  p.id = r.name<ProblemId>("id");
  p.title = r.string("title");
  p.description = r.string("description");
  p.axisymmetric = r.boolean("axisymmetric");
  p.singular = r.boolean("singular");
  p.study_tables = r.string("study_tables");
  p.exact_source = r.string("exact_source");
  const json& qs = r.at("quantities");
  if (!qs.is_array())
    r.fail_field("quantities", "is not an array");
  for (std::size_t i = 0; i < qs.size(); ++i) {
    const JsonFields q(qs[i], fmt::format("{}[{}]", r.path_of("quantities"), i));
    p.quantities.push_back({q.name<Quantity>("quantity"), q.string("definition_md"),
                            q.string("definition_plain"), q.string("study_table"),
                            q.string("study_row")});
  }
  // Optional: files written before these were recorded lack them.
  if (r.has("situation"))
    p.situation = r.name<Situation>("situation");
  if (r.has("length_scale"))
    p.length_scale = r.name<LengthScale>("length_scale");
  return p;
}

/// The run's sweep axes: an array of {key, values}, keys non-empty and unique, each with at
/// least one finite value and no value twice (the cases are their cross product).
std::vector<SweepAxis> sweep_from_json(const JsonFields& r) {
  const json& a = r.at("sweep");
  if (!a.is_array())
    r.fail_field("sweep", "is not an array");
  std::vector<SweepAxis> axes;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const JsonFields f(a[i], fmt::format("{}[{}]", r.path_of("sweep"), i));
    SweepAxis axis{f.string("key"), numbers_from(f, "values")};
    if (axis.key.empty())
      f.fail_field("key", "is empty");
    if (!f.has("values") || axis.values.empty())
      f.fail_field("values", "is missing or empty");
    for (std::size_t k = 0; k < axis.values.size(); ++k) {
      if (!std::isfinite(axis.values[k]))
        f.fail_field("values", fmt::format("item {} is not a finite number", k));
      for (std::size_t m = 0; m < k; ++m) {
        if (axis.values[m] == axis.values[k])
          f.fail_field("values", fmt::format("item {} repeats item {}", k, m));
      }
    }
    for (const auto& earlier : axes) {
      if (earlier.key == axis.key)
        f.fail_field("key", fmt::format("\"{}\" is swept twice", axis.key));
    }
    axes.push_back(std::move(axis));
  }
  return axes;
}

/// The longest time (s) and the largest count a file may state: far beyond any run, so that
/// sums over merged files cannot overflow.
constexpr double kMaxSeconds = 1e9;

/// A measure (time, memory, length) at `key`: null reads NaN; otherwise in [0, most].
double measure(const JsonFields& r, const char* key, double most = 1e300) {
  const double v = r.number(key, true);
  if (std::isfinite(v) && (v < 0.0 || v > most))
    r.fail_field(key, v < 0.0 ? "is negative" : fmt::format("is above {:g}", most));
  return v;
}

RunInfo run_from_json(const JsonFields& r) {
  RunInfo run;
  run.started_utc = r.string("started_utc");
  run.wall_seconds = measure(r, "wall_seconds", kMaxSeconds);
  run.jobs = static_cast<int>(r.integer("jobs", 1, kIntMax));
  run.peak_rss_mb = measure(r, "peak_rss_mb");
  run.command_line = r.string("command_line");
  run.environment = r.has("environment") ? r.at("environment") : json::object();
  if (!run.environment.is_object())
    r.fail_field("environment", "is not an object");
  if (r.has("shard") && !r.at("shard").is_null()) {
    const JsonFields s = r.object("shard");
    ShardInfo info;
    info.count = static_cast<int>(s.integer("count", 1, kIntMax));
    info.index = static_cast<int>(s.integer("index", 1, info.count));
    info.run_key = s.string("run_key");
    info.total_cases = s.integer("total_cases", 0, kIntMax);
    run.shard = info;
  }
  if (r.has("sweep"))
    run.sweep = sweep_from_json(r);
  if (r.has("merged_files"))
    run.merged_files = static_cast<int>(r.integer("merged_files", 0, kMaxMergedFiles));
  return run;
}

template <class Record, class Read>
std::vector<Record> records_from(const JsonFields& r, const char* key, Read read) {
  const json& a = r.at(key);
  if (!a.is_array())
    r.fail_field(key, "is not an array");
  std::vector<Record> out;
  out.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    out.push_back(read(a[i], fmt::format("{}[{}]", r.path_of(key), i)));
  return out;
}

void check_unique_ids(const ResultsDocument& doc, const std::string& source) {
  std::set<std::string> seen;
  for (const auto& c : doc.cases) {
    if (!seen.insert(case_id(c.spec)).second)
      throw SchemaError(fmt::format("{}: duplicate case id \"{}\"", source, case_id(c.spec)));
  }
  seen.clear();
  for (const auto& row : doc.rows) {
    if (!seen.insert(row.id).second)
      throw SchemaError(fmt::format("{}: duplicate row id \"{}\"", source, row.id));
  }
  for (const auto& c : doc.cases) {
    if (doc.problem(c.spec.problem) == nullptr) {
      throw SchemaError(
          fmt::format("{}: case \"{}\" has no entry in 'problems'", source, case_id(c.spec)));
    }
  }
}

}  // namespace

const ProblemRecord* ResultsDocument::problem(ProblemId id) const {
  for (const auto& p : problems) {
    if (p.id == id)
      return &p;
  }
  return nullptr;
}

json to_json(const CaseResult& r) {
  json j{{"id", case_id(r.spec)}, {"mesh", to_string(r.spec.mesh)}};
  spec_to_json(r.spec, j);
  j["status"] = to_string(r.status);
  j["reason"] = r.reason;
  if (!r.kept_files.empty())
    j["kept_files"] = r.kept_files;
  j["iterations"] = r.iterations;
  j["wall_seconds"] = number_or_null(r.wall_seconds);
  j["peak_rss_mb"] = number_or_null(r.peak_rss_mb);
  j["n_elements"] = r.n_elements;
  j["n_equations"] = r.n_equations;
  j["element_size_h"] = number_or_null(r.element_size_h);
  json quantities = json::object();
  for (const auto& q : r.quantities)
    quantities[std::string(to_string(q.quantity))] = quantity_to_json(q);
  j["quantities"] = quantities;
  j["profile"] = {{"x_over_a", numbers_or_null(r.profile.x_over_a)},
                  {"sigma_z_over_p", numbers_or_null(r.profile.sigma_z_over_p)},
                  {"pressure_over_p", numbers_or_null(r.profile.pressure_over_p)}};
  if (!r.exact_profile.empty()) {
    j["exact_profile"] = {{"x_over_a", numbers_or_null(r.exact_profile.x_over_a)},
                          {"sigma_z_over_p", numbers_or_null(r.exact_profile.sigma_z_over_p)}};
  }
  if (r.interface) {
    j["interface"] = {
        {"force_balance", number_or_null(r.interface->force_balance)},
        {"max_tensile_over_p", number_or_null(r.interface->max_tensile_over_p)},
        {"max_outside_over_p", number_or_null(r.interface->max_outside_over_p)},
        {"max_penetration_over_h", number_or_null(r.interface->max_penetration_over_h)}};
  }
  return j;
}

CaseResult case_from_json(const json& j, const std::string& path) {
  const JsonFields r(j, path);
  CaseResult c;
  c.spec = spec_from_json(r);
  c.spec.mesh = r.name<MeshLevel>("mesh");
  check_id(r, case_id(c.spec));
  c.status = r.name<CaseStatus>("status");
  c.reason = r.optional_string("reason");
  c.kept_files = r.optional_string("kept_files");
  split_kept_files(c);
  c.iterations = static_cast<int>(r.optional_integer("iterations", 0, 0, kIntMax));
  c.wall_seconds = measure(r, "wall_seconds", kMaxSeconds);
  c.peak_rss_mb = measure(r, "peak_rss_mb");
  c.n_elements = static_cast<int>(r.optional_integer("n_elements", 0, 0, kIntMax));
  c.n_equations = static_cast<int>(r.optional_integer("n_equations", 0, 0, kIntMax));
  c.element_size_h = measure(r, "element_size_h");
  const JsonFields qs = r.object("quantities");
  for (const auto& [name, value] : r.at("quantities").items()) {
    const auto quantity = try_parse<Quantity>(name);
    if (!quantity) {
      qs.fail_field(
          name, fmt::format("unknown quantity (expected one of: {})", accepted_names<Quantity>()));
    }
    c.quantities.push_back(quantity_from_json(qs.object(name.c_str()), *quantity));
  }
  if (r.has("profile")) {
    const JsonFields p = r.object("profile");
    c.profile = {numbers_from(p, "x_over_a"), numbers_from(p, "sigma_z_over_p"),
                 numbers_from(p, "pressure_over_p")};
    if (c.profile.sigma_z_over_p.size() != c.profile.x_over_a.size() ||
        c.profile.pressure_over_p.size() != c.profile.x_over_a.size())
      p.fail("its arrays differ in length");
  }
  if (r.has("exact_profile")) {
    const JsonFields p = r.object("exact_profile");
    c.exact_profile = {numbers_from(p, "x_over_a"), numbers_from(p, "sigma_z_over_p")};
    if (c.exact_profile.sigma_z_over_p.size() != c.exact_profile.x_over_a.size())
      p.fail("its arrays differ in length");
  }
  if (r.has("interface")) {
    const JsonFields f = r.object("interface");
    c.interface = InterfaceChecks{
        f.optional_number("force_balance"), f.optional_number("max_tensile_over_p"),
        f.optional_number("max_outside_over_p"), f.optional_number("max_penetration_over_h")};
    for (const char* key : {"max_tensile_over_p", "max_outside_over_p", "max_penetration_over_h"}) {
      if (const auto v = f.optional_number(key); v && *v < 0)
        f.fail_field(key, "is negative");
    }
  }
  return c;
}

namespace {

json to_json(const ErrorEstimate& e) {
  return {{"asymptotic", e.asymptotic},
          {"observed_order", number_or_null(e.observed_order)},
          {"richardson", number_or_null(e.richardson)},
          {"gci_percent", number_or_null(e.gci_percent)},
          {"note", e.note}};
}

json to_json(const DivergenceVerdict& d) {
  return {{"eq47", d.eq47},
          {"monotone", d.monotone},
          {"exponent", number_or_null(d.exponent)},
          {"diverges", d.diverges}};
}

json to_json(const RefinementVerdict& v) {
  json j{{"mesh", to_string(MeshLevel::VF)},
         {"value", number_or_null(v.value)},
         {"error_percent", number_or_null(v.error)},
         {"observed_order_F_VF", number_or_null(v.pair_order)},
         {"converging_M_F_VF", v.converging ? json(*v.converging) : json(nullptr)},
         {"diverging_M_F_VF", v.diverging ? json(*v.diverging) : json(nullptr)}};
  if (v.estimate)
    j["estimate_M_F_VF"] = to_json(*v.estimate);
  if (v.divergence)
    j["divergence_M_F_VF"] = to_json(*v.divergence);
  return j;
}

ErrorEstimate estimate_from_json(const JsonFields& e) {
  return ErrorEstimate{e.boolean("asymptotic"), e.optional_number("observed_order"),
                       e.optional_number("richardson"), e.optional_number("gci_percent"),
                       e.optional_string("note")};
}

DivergenceVerdict divergence_from_json(const JsonFields& d) {
  return DivergenceVerdict{d.boolean("eq47"), d.boolean("monotone"), d.optional_number("exponent"),
                           d.boolean("diverges")};
}

RefinementVerdict refinement_from_json(const JsonFields& r) {
  RefinementVerdict v;
  v.value = r.optional_number("value");
  v.error = r.optional_number("error_percent");
  v.pair_order = r.optional_number("observed_order_F_VF");
  v.converging = r.optional_boolean("converging_M_F_VF");
  v.diverging = r.optional_boolean("diverging_M_F_VF");
  if (r.has("estimate_M_F_VF") && !r.at("estimate_M_F_VF").is_null())
    v.estimate = estimate_from_json(r.object("estimate_M_F_VF"));
  if (r.has("divergence_M_F_VF") && !r.at("divergence_M_F_VF").is_null())
    v.divergence = divergence_from_json(r.object("divergence_M_F_VF"));
  return v;
}

}  // namespace

json to_json(const RowVerdict& row) {
  json j{{"id", row.id}};
  spec_to_json(row.spec, j);
  j["quantity"] = to_string(row.quantity);
  json by_mesh = json::object(), errors = json::object();
  for (MeshLevel level : kStudyMeshes) {
    const auto i = static_cast<std::size_t>(level);
    by_mesh[std::string(to_string(level))] = number_or_null(row.values[i]);
    errors[std::string(to_string(level))] = number_or_null(row.errors[i]);
  }
  j["values"] = by_mesh;
  j["error_percent"] = errors;
  j["grade"] = row.grade ? json(to_string(*row.grade)) : json(nullptr);
  j["graded_mesh"] = row.graded_mesh ? json(to_string(*row.graded_mesh)) : json(nullptr);
  j["converging"] = row.converging ? json(*row.converging) : json(nullptr);
  j["diverging"] = row.diverging ? json(*row.diverging) : json(nullptr);
  j["observed_order"] = {{"C_M", number_or_null(row.pair_orders[0])},
                         {"M_F", number_or_null(row.pair_orders[1])}};
  if (row.estimate)
    j["estimate"] = to_json(*row.estimate);
  if (row.divergence)
    j["divergence"] = to_json(*row.divergence);
  if (row.refinement)
    j["refinement"] = to_json(*row.refinement);
  return j;
}

RowVerdict row_from_json(const json& j, const std::string& path) {
  const JsonFields r(j, path);
  RowVerdict row;
  row.spec = spec_from_json(r);
  row.quantity = r.name<Quantity>("quantity");
  row.id = case_key(row.spec) + "/" + std::string(to_string(row.quantity));
  check_id(r, row.id);
  const JsonFields by_mesh = r.object("values");
  const JsonFields errors = r.object("error_percent");
  for (MeshLevel level : kStudyMeshes) {
    const auto i = static_cast<std::size_t>(level);
    const std::string name(to_string(level));
    const double v = by_mesh.number(name.c_str(), true);
    const double e = errors.number(name.c_str(), true);
    if (std::isfinite(v))
      row.values[i] = v;
    if (std::isfinite(e))
      row.errors[i] = e;
  }
  row.grade = r.optional_name<Grade>("grade");
  row.graded_mesh = r.optional_name<MeshLevel>("graded_mesh");
  if (row.graded_mesh && std::ranges::find(kStudyMeshes, *row.graded_mesh) == kStudyMeshes.end())
    r.fail_field("graded_mesh", "is not one of the study's meshes C, M, F");
  row.converging = r.optional_boolean("converging");
  row.diverging = r.optional_boolean("diverging");
  if (r.has("observed_order")) {
    const JsonFields o = r.object("observed_order");
    row.pair_orders = {o.optional_number("C_M"), o.optional_number("M_F")};
  }
  if (r.has("estimate") && !r.at("estimate").is_null())
    row.estimate = estimate_from_json(r.object("estimate"));
  if (r.has("divergence") && !r.at("divergence").is_null())
    row.divergence = divergence_from_json(r.object("divergence"));
  if (r.has("refinement") && !r.at("refinement").is_null())
    row.refinement = refinement_from_json(r.object("refinement"));
  return row;
}

json to_json(const ProblemRecord& p) {
  json quantities = json::array();
  for (const auto& d : p.quantities)
    quantities.push_back(problem_quantity_to_json(d));
  json out{{"id", to_string(p.id)},          {"title", p.title},
           {"description", p.description},   {"axisymmetric", p.axisymmetric},
           {"singular", p.singular},         {"study_tables", p.study_tables},
           {"exact_source", p.exact_source}, {"quantities", quantities}};
  if (p.situation)
    out["situation"] = to_string(*p.situation);
  if (p.length_scale)
    out["length_scale"] = to_string(*p.length_scale);
  return out;
}

json to_json(const ResultsDocument& doc) {
  json out{{"schema", kResultsSchemaName}, {"schema_version", kResultsSchemaVersion}};
  out["run"] = {{"started_utc", doc.run.started_utc},
                {"wall_seconds", number_or_null(doc.run.wall_seconds)},
                {"jobs", doc.run.jobs},
                {"peak_rss_mb", number_or_null(doc.run.peak_rss_mb)},
                {"command_line", doc.run.command_line},
                {"environment", doc.run.environment}};
  if (doc.run.shard) {
    out["run"]["shard"] = {{"index", doc.run.shard->index},
                           {"count", doc.run.shard->count},
                           {"run_key", doc.run.shard->run_key},
                           {"total_cases", doc.run.shard->total_cases}};
  }
  if (doc.run.merged_files > 0)
    out["run"]["merged_files"] = doc.run.merged_files;
  if (!doc.run.sweep.empty()) {
    json sweep = json::array();
    for (const auto& axis : doc.run.sweep)
      sweep.push_back({{"key", axis.key}, {"values", numbers_or_null(axis.values)}});
    out["run"]["sweep"] = sweep;
  }
  json problems = json::array(), cases = json::array(), rows = json::array();
  for (const auto& p : doc.problems)
    problems.push_back(to_json(p));
  for (const auto& c : doc.cases)
    cases.push_back(to_json(c));
  for (const auto& r : doc.rows)
    rows.push_back(to_json(r));
  out["problems"] = problems;
  out["cases"] = cases;
  out["rows"] = rows;
  json defaults = json::object();
  for (const auto& [problem, values] : doc.parameter_defaults)
    defaults[std::string(to_string(problem))] = values;
  out["parameter_defaults"] = defaults;
  return out;
}

std::optional<std::string> RunInfo::build() const {
  const auto it = environment.find("contact_suite_version");
  return it != environment.end() && it->is_string() ? std::optional(it->get<std::string>())
                                                    : std::nullopt;
}

ResultsDocument results_from_json(const json& j, const std::string& source) {
  const JsonFields r(j, source);
  if (r.string("schema") != kResultsSchemaName) {
    r.fail_field("schema", fmt::format("is not \"{}\": not a contact-suite results file",
                                       kResultsSchemaName));
  }
  const auto version = r.integer("schema_version", 0, kIntMax);
  if (version == kMigratedSchemaVersion) {
    json migrated = j;
    migrate_results_v3_to_v4(migrated);
    migrated["schema_version"] = kResultsSchemaVersion;
    return results_from_json(migrated, source);
  }
  if (version != kResultsSchemaVersion) {
    r.fail_field("schema_version",
                 fmt::format("{} is not supported (this build reads {} and {})", version,
                             kMigratedSchemaVersion, kResultsSchemaVersion));
  }
  ResultsDocument doc;
  doc.source = source;
  doc.run = run_from_json(r.object("run"));
  doc.problems = records_from<ProblemRecord>(r, "problems", problem_from_json);
  doc.cases = records_from<CaseResult>(r, "cases", case_from_json);
  doc.rows = records_from<RowVerdict>(r, "rows", row_from_json);
  if (r.has("parameter_defaults")) {
    const JsonFields all = r.object("parameter_defaults");
    for (const auto& [problem, values] : r.at("parameter_defaults").items()) {
      const JsonFields d = all.object(problem.c_str());
      const auto id = try_parse<ProblemId>(problem);
      if (!id)
        all.fail_field(problem, "is not a problem");
      auto& out = doc.parameter_defaults[*id];
      for (const auto& [key, value] : values.items())
        out[key] = d.number(key.c_str(), false);
    }
  }
  check_unique_ids(doc, source);
  return doc;
}

ResultsDocument parse_results_text(std::string_view text, const std::string& source) {
  return results_from_json(parse_json_text(text, "results", source), source);
}

ResultsDocument read_results_file(const std::filesystem::path& path) {
  return results_from_json(read_json_file(path, "results"), path.string());
}

void write_results_file(const std::filesystem::path& path, const ResultsDocument& doc) {
  write_json_file_atomically(path, to_json(doc));
}

}  // namespace cs::schema
