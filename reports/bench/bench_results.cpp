#include "reports/bench/bench_results.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

using nlohmann::json;

/// An error about one file: "bench file 'X': <what>".
[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw ReportError(fmt::format("bench file '{}': {}", source, what));
}

/// The keys of a benchmark entry that Google Benchmark writes itself; the rest are counters.
bool is_counter_key(const std::string& key) {
  static const std::string own =
      " name family_index per_family_instance_index run_name run_type repetitions "
      "repetition_index threads iterations real_time cpu_time time_unit aggregate_name "
      "aggregate_unit error_occurred error_message skipped skip_message label big_o rms "
      "complexity allocs_per_iter max_bytes_used total_allocated_bytes net_heap_growth "
      "memory_iterations ";
  return own.find(" " + key + " ") == std::string::npos;
}

/// The fields of one entry of `benchmarks` that the report uses.
struct Entry {
  std::string name;                ///< as written
  std::vector<std::string> parts;  ///< run_name (name without aggregate suffix) split at '/'
  std::string aggregate;           ///< "mean", "median", ... for aggregates, else empty
  std::optional<double> time_ms;
  std::map<std::string, double> counters;
  std::string label, error;
  /// Throws unless `decoded`: the name has the form a kind of benchmark needs.
  void require(bool decoded, const std::string& form, const std::string& source) const {
    if (!decoded)
      fail(source, fmt::format("benchmark '{}' does not name its case as {}", name, form));
  }
};

/// Why the run did not finish: error_occurred/error_message, or skipped/skip_message.
std::string stop_reason(const json& e) {
  if (e.value("error_occurred", false)) {
    const std::string message = e.value("error_message", "");
    return message.empty() ? "error (no message)" : message;
  }
  if (e.value("skipped", false)) {
    const std::string message = e.value("skip_message", "");
    return message.empty() ? "skipped" : "skipped: " + message;
  }
  return {};
}

Entry read_entry(const json& e, std::size_t i, const std::string& source) {
  if (!e.is_object())
    fail(source, fmt::format("entry {} of 'benchmarks' is not an object", i));
  Entry out;
  out.name = e.value("name", "");
  if (out.name.empty())
    fail(source, fmt::format("entry {} of 'benchmarks' has no 'name'", i));
  std::istringstream run_name(e.value("run_name", out.name));
  for (std::string part; std::getline(run_name, part, '/');)
    out.parts.push_back(part);
  if (e.value("run_type", "") == "aggregate")
    out.aggregate = e.value("aggregate_name", "");
  out.label = e.value("label", "");
  out.error = stop_reason(e);
  if (out.error.empty()) {  // a run stopped by an error has no time worth showing
    if (!e.contains("real_time") || !e["real_time"].is_number() || !e.contains("time_unit"))
      fail(source,
           fmt::format("benchmark '{}' has no numeric 'real_time' with a 'time_unit'", out.name));
    const std::string unit = e["time_unit"].get<std::string>();
    const auto factor = milliseconds_per(unit);
    if (!factor)
      fail(source, fmt::format("benchmark '{}' has time_unit '{}' (expected ns, us, ms or s)",
                               out.name, unit));
    out.time_ms = e["real_time"].get<double>() * *factor;
  }
  for (const auto& [key, value] : e.items()) {
    if (value.is_number() && is_counter_key(key) && std::isfinite(value.get<double>()))
      out.counters[key] = value.get<double>();
  }
  return out;
}

/// The model of parts[1..3]; throws naming the expected form when a part is not a known name.
BenchModel decode_model(const Entry& e, const std::string& form, const std::string& source) {
  const auto problem = schema::try_parse<schema::ProblemId>(e.parts[1]);
  const auto mesh = schema::try_parse<schema::MeshLevel>(e.parts[2]);
  const auto element = schema::try_parse<schema::Element>(e.parts[3]);
  if (!problem || !mesh || !element) {
    fail(source, fmt::format("benchmark '{}' does not name its case as {} (written by an older "
                             "bench_contact_algorithms?)",
                             e.name, form));
  }
  return {*problem, *mesh, *element};
}

/// The family a benchmark name starts with; nullopt for the others.
std::optional<BenchFamily> family_of(const std::string& first_part) {
  static const std::map<std::string, BenchFamily> families{
      {"Contact", BenchFamily::Contact},
      {"ContactAllOptions", BenchFamily::ContactAllOptions},
      {"ModelCases", BenchFamily::ModelCases}};
  const auto it = families.find(first_part);
  return it == families.end() ? std::nullopt : std::optional(it->second);
}

/// The row of an entry of `family`: its model (and for Contact its option) decoded from the name.
BenchRow bench_row(const Entry& e, BenchFamily family, const std::string& source) {
  const bool contact = family == BenchFamily::Contact;
  const std::string form =
      e.parts.front() + (contact ? "/<problem>/<mesh>/<element>/<contact>/<algorithm>"
                                 : "/<problem>/<mesh>/<element>");
  e.require(e.parts.size() >= (contact ? 6u : 4u), form, source);
  BenchRow b;
  b.family = family;
  b.name = e.name;
  b.model = decode_model(e, form, source);
  if (contact) {
    const auto kind = schema::try_parse<schema::ContactKind>(e.parts[4]);
    const auto algorithm = schema::try_parse<BenchMethod>(e.parts[5]);
    e.require(kind && algorithm, form, source);
    b.contact = *kind;
    b.algorithm = *algorithm;
  }
  b.time_ms = e.time_ms;
  b.counters = e.counters;
  b.label = e.label;
  b.error = e.error;
  return b;
}

/// The case a row measures, to find repetitions and the same case in another file.
std::string case_key(const BenchRow& b) {
  const std::string model = fmt::format("{}/{}", static_cast<int>(b.family), model_md(b.model));
  return b.family != BenchFamily::Contact
             ? model
             : fmt::format("{}/{}/{}", model, schema::to_string(b.contact),
                           schema::to_string(b.algorithm));
}

/// Per case, in order of first appearance, the measurement that represents it: the median
/// aggregate, else the mean aggregate, else the repetition of median time (the lower median of
/// an even count; errors last). `runs` pairs each row with its aggregate name.
std::vector<BenchRow> representatives(const std::vector<std::pair<std::string, BenchRow>>& runs) {
  std::vector<BenchRow> out;
  std::vector<std::string> done;
  for (const auto& [unused, first] : runs) {
    const std::string key = case_key(first);
    if (std::find(done.begin(), done.end(), key) != done.end())
      continue;
    done.push_back(key);
    std::map<std::string, std::vector<const BenchRow*>> by_aggregate;
    for (const auto& [aggregate, r] : runs) {
      if (case_key(r) == key)
        by_aggregate[aggregate].push_back(&r);
    }
    std::vector<const BenchRow*> reps = by_aggregate[""];
    std::stable_sort(reps.begin(), reps.end(), [](const BenchRow* a, const BenchRow* b) {
      return a->time_ms.value_or(INFINITY) < b->time_ms.value_or(INFINITY);
    });
    const BenchRow* chosen = !by_aggregate["median"].empty() ? by_aggregate["median"].front()
                             : !by_aggregate["mean"].empty() ? by_aggregate["mean"].front()
                             : !reps.empty()                 ? reps[(reps.size() - 1) / 2]
                                                             : &first;
    out.push_back(*chosen);
  }
  return out;
}

/// The rows of `family`, in order.
std::vector<BenchRow>& rows_of(BenchResults& results, BenchFamily family) {
  switch (family) {
    case BenchFamily::Contact:
      return results.contact;
    case BenchFamily::ContactAllOptions:
      return results.all_options;
    case BenchFamily::ModelCases:
      return results.model_cases;
  }
  return results.contact;
}

BenchContext read_context(const json& doc) {
  BenchContext c;
  const json j = doc.value("context", json::object());
  c.date = j.value("date", "");
  c.host_name = j.value("host_name", "");
  c.executable = j.value("executable", "");
  c.library_build_type = j.value("library_build_type", "");
  if (j.contains("num_cpus"))
    c.num_cpus = j["num_cpus"].get<int>();
  if (j.contains("mhz_per_cpu"))
    c.mhz_per_cpu = j["mhz_per_cpu"].get<double>();
  if (j.contains("cpu_scaling_enabled"))
    c.cpu_scaling_enabled = j["cpu_scaling_enabled"].get<bool>();
  c.load_avg = j.value("load_avg", std::vector<double>{});
  return c;
}

/// Appends `rows` (of source `source`) to `into`, replacing the same case measured earlier.
int merge_into(std::vector<BenchRow>& into, std::vector<BenchRow> rows, std::size_t source) {
  int replaced = 0;
  for (BenchRow& r : rows) {
    r.source = source;
    const auto same = std::find_if(into.begin(), into.end(), [&](const BenchRow& old) {
      return case_key(old) == case_key(r);
    });
    replaced += same != into.end() ? 1 : 0;
    if (same != into.end())
      *same = std::move(r);
    else
      into.push_back(std::move(r));
  }
  return replaced;
}

}  // namespace

std::optional<double> BenchRow::counter(std::string_view key) const {
  const auto it = counters.find(std::string(key));
  return it == counters.end() ? std::nullopt : std::optional(it->second);
}

std::optional<double> BenchRow::counter_ms(std::string_view key) const {
  const auto seconds = counter(key);
  return seconds ? std::optional(*seconds * 1000) : std::nullopt;
}

std::optional<int> BenchRow::count(std::string_view key) const {
  const auto value = counter(key);
  return value ? std::optional(static_cast<int>(std::lround(*value))) : std::nullopt;
}

bool BenchRow::converged() const {
  return failure().empty();
}

std::string BenchRow::failure() const {
  if (!error.empty())
    return "error: " + error;
  return label.starts_with("not converged") ? label : std::string();
}

const std::vector<schema::ContactKind>& bench_contacts() {
  static const std::vector<schema::ContactKind> order{
      schema::ContactKind::ns, schema::ContactKind::ss, schema::ContactKind::mortar};
  return order;
}

BenchOptions options_of(const std::vector<const BenchRow*>& cases) {
  const auto has = [&](auto pred) { return std::any_of(cases.begin(), cases.end(), pred); };
  BenchOptions out;
  for (const auto c : bench_contacts()) {
    if (has([c](const BenchRow* b) { return b->contact == c; }))
      out.contacts.push_back(c);
  }
  for (const auto a : schema::values<BenchMethod>()) {
    if (has([a](const BenchRow* b) { return b->algorithm == a; }))
      out.methods.push_back(a);
  }
  return out;
}

std::tuple<int, int, int> model_order(const BenchModel& model) {
  return {static_cast<int>(model.problem), static_cast<int>(model.mesh),
          static_cast<int>(model.element)};
}

std::string model_md(const BenchModel& m) {
  return fmt::format("{}, mesh {}, {}", schema::label(m.problem), schema::to_string(m.mesh),
                     schema::to_string(m.element));
}

std::optional<double> milliseconds_per(std::string_view time_unit) {
  const std::map<std::string_view, double> per{{"ns", 1e-6}, {"us", 1e-3}, {"ms", 1.0}, {"s", 1e3}};
  const auto it = per.find(time_unit);
  return it == per.end() ? std::nullopt : std::optional(it->second);
}

std::string json_without_nonfinite(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (in_string || text[i] == '"') {  // copy strings as they are, escapes included
      const bool escape = in_string && text[i] == '\\' && i + 1 < text.size();
      out += escape ? text.substr(i++, 2) : text.substr(i, 1);
      in_string = escape || (in_string ? text[i] != '"' : true);
      continue;
    }
    const std::size_t start = i + (text[i] == '-' ? 1 : 0);
    const auto bare = [&](std::string_view word) {
      const std::size_t end = start + word.size();
      return text.substr(start, word.size()) == word &&
             (end == text.size() || std::isalnum(static_cast<unsigned char>(text[end])) == 0);
    };
    const std::size_t length = bare("NaN") ? 3 : bare("Infinity") ? 8 : 0;
    out += length > 0 ? std::string_view("null") : text.substr(i, 1);
    i = length > 0 ? start + length - 1 : i;
  }
  return out;
}

BenchResults parse_bench_document(const json& doc, const std::string& source) {
  if (!doc.is_object())
    fail(source, "is not a JSON object (not Google Benchmark JSON output?)");
  if (!doc.contains("benchmarks") || !doc["benchmarks"].is_array())
    fail(source, "has no 'benchmarks' array (not Google Benchmark JSON output?)");
  BenchResults out;
  std::map<BenchFamily, std::vector<std::pair<std::string, BenchRow>>> runs;
  try {
    out.sources.push_back({source, read_context(doc), 0});
    const json& list = doc["benchmarks"];
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Entry e = read_entry(list[i], i, source);
      if (!e.aggregate.empty() && e.aggregate != "median" && e.aggregate != "mean")
        continue;  // stddev, cv: not a time
      const auto family = family_of(e.parts.front());
      if (family)
        runs[*family].emplace_back(e.aggregate, bench_row(e, *family, source));
      else
        ++out.sources.front().n_other;
    }
    for (auto& [family, family_runs] : runs)
      rows_of(out, family) = representatives(family_runs);
  } catch (const json::exception& e) {  // a field of the wrong type
    fail(source, e.what());
  }
  if (runs.empty()) {
    fail(source, fmt::format("has no Contact, ContactAllOptions or ModelCases benchmark ({} of "
                             "other families; "
                             "written by bench_contact_algorithms?)",
                             out.sources.front().n_other));
  }
  return out;
}

BenchResults load_bench_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw ReportError(fmt::format("bench file '{}' does not exist", name));
  if (!std::filesystem::is_regular_file(file, ec))
    throw ReportError(fmt::format("bench file '{}' is not a regular file", name));
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in)
    throw ReportError(fmt::format("bench file '{}' cannot be read", name));
  if (text.str().empty())
    throw ReportError(fmt::format("bench file '{}' is empty", name));
  const json doc = json::parse(json_without_nonfinite(text.str()), nullptr, false);
  if (doc.is_discarded())
    throw ReportError(fmt::format("bench file '{}' is not valid JSON (truncated?)", name));
  return parse_bench_document(doc, name);
}

BenchResults load_bench_files(const std::vector<std::filesystem::path>& files) {
  BenchResults all;
  for (const auto& file : files) {
    BenchResults one = load_bench_file(file);
    const std::size_t source = all.sources.size();
    all.sources.push_back(std::move(one.sources.front()));
    for (const auto family :
         {BenchFamily::Contact, BenchFamily::ContactAllOptions, BenchFamily::ModelCases})
      all.n_replaced += merge_into(rows_of(all, family), std::move(rows_of(one, family)), source);
  }
  return all;
}

std::vector<std::vector<const BenchRow*>> finest_models(const BenchResults& bench) {
  std::map<std::tuple<int, int>, BenchModel> finest;  // (problem, element) rank -> model
  for (const auto& b : bench.contact) {
    if (!b.time_ms)
      continue;
    const auto [problem, mesh, element] = model_order(b.model);
    const auto [it, added] = finest.try_emplace({problem, element}, b.model);
    if (!added && std::get<1>(model_order(it->second)) < mesh)
      it->second = b.model;
  }
  std::vector<std::vector<const BenchRow*>> out;
  for (const auto& [rank, model] : finest) {
    out.emplace_back();
    for (const auto& b : bench.contact)
      out.back().insert(out.back().end(), b.model == model ? 1 : 0, &b);
  }
  return out;
}

}  // namespace cs::reports
