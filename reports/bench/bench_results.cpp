#include "reports/bench/bench_results.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "reports/report_error.hpp"
#include "schema/json_file.hpp"
#include "schema/schema_error.hpp"

namespace cs::reports {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw ReportError(fmt::format("bench file '{}': {}", file, what));
}

/// `text` with Google Benchmark's bare NaN, -NaN, Infinity and -Infinity values replaced by
/// null, so that it parses as JSON; strings are copied as they are.
std::string json_without_nonfinite(std::string_view text) {
  // One pass, no recursion: a string of any length (a long label) is copied as it is.
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '"') {
      std::size_t end = i + 1;
      while (end < text.size() && text[end] != '"')
        end += text[end] == '\\' ? 2 : 1;
      end = std::min(end + 1, text.size());
      out.append(text.substr(i, end - i));
      i = end;
      continue;
    }
    const std::size_t word = i + (text[i] == '-' ? 1 : 0);
    const auto bare = [&](std::string_view name) {
      const std::size_t after = word + name.size();
      return text.substr(word, name.size()) == name &&
             (after == text.size() || std::isalnum(static_cast<unsigned char>(text[after])) == 0);
    };
    const std::size_t length = bare("NaN") ? 3 : bare("Infinity") ? 8 : 0;
    if (length > 0) {
      out += "null";
      i = word + length;
    } else {
      out += text[i++];
    }
  }
  return out;
}

BenchContext read_context(const json& doc) {
  const json c = doc.value("context", json::object());
  const auto number = [&](const char* key) {
    return c.contains(key) ? std::optional(c[key].get<double>()) : std::nullopt;
  };
  return {c.value("host_name", ""),
          c.value("library_build_type", ""),
          c.value("executable", ""),
          c.value("date", ""),
          number("num_cpus"),
          number("mhz_per_cpu"),
          c.value("load_avg", std::vector<double>{}),
          c.value("cpu_scaling_enabled", false)};
}

/// Why the run did not finish: error_occurred/error_message, or skipped/skip_message.
std::string stop_reason(const json& e) {
  const std::string error = e.value("error_message", ""), skip = e.value("skip_message", "");
  if (e.value("error_occurred", false))
    return error.empty() ? "error (no message)" : error;
  if (e.value("skipped", false))
    return skip.empty() ? "skipped" : "skipped: " + skip;
  return {};
}

/// Sets the model (and for Contact the option) of `b` from the parts of its run name; throws
/// naming the form expected when a part is missing or not a known name.
void decode_name(BenchRow& b, const std::vector<std::string>& parts, const std::string& name,
                 const std::string& file) {
  const auto part = [&](std::size_t k) { return k < parts.size() ? parts[k] : std::string(); };
  const auto problem = schema::try_parse<schema::ProblemId>(part(1));
  const auto mesh = schema::try_parse<schema::MeshLevel>(part(2));
  const auto element = schema::try_parse<schema::Element>(part(3));
  const auto contact = schema::try_parse<schema::ContactKind>(part(4));
  const auto method = schema::try_parse<BenchMethod>(part(5));
  const bool options = b.family == BenchFamily::Contact;
  if (!problem || !mesh || !element || (options && (!contact || !method))) {
    fail(file,
         fmt::format("benchmark '{}' does not name its case as {}/<problem>/<mesh>/<element>{} "
                     "(written by an older bench_contact_algorithms?)",
                     name, parts[0], options ? "/<contact>/<algorithm>" : ""));
  }
  b.model = {*problem, *mesh, *element};
  b.contact = options ? *contact : b.contact;
  b.algorithm = options ? *method : b.algorithm;
}

/// The row of entry `i` of `benchmarks`; nullopt for other families.
std::optional<BenchRow> read_row(const json& e, std::size_t i, const std::string& file) {
  if (!e.is_object())
    fail(file, fmt::format("entry {} of 'benchmarks' is not an object", i));
  const std::string name = e.value("name", "");
  if (name.empty())
    fail(file, fmt::format("entry {} of 'benchmarks' has no 'name'", i));
  std::vector<std::string> parts;  // of run_name: the name without an aggregate's suffix
  std::istringstream run_name(e.value("run_name", name));
  for (std::string part; std::getline(run_name, part, '/');)
    parts.push_back(part);
  static const std::map<std::string, BenchFamily> families{
      {"Contact", BenchFamily::Contact},
      {"ContactAllOptions", BenchFamily::ContactAllOptions},
      {"ModelCases", BenchFamily::ModelCases}};
  const auto family = families.find(parts.empty() ? "" : parts[0]);
  if (family == families.end())
    return std::nullopt;
  BenchRow b;
  b.family = family->second;
  decode_name(b, parts, name, file);
  b.label = e.value("label", "");
  b.error = stop_reason(e);
  if (b.error.empty()) {  // a run stopped by an error has no time worth showing
    if (!e.contains("real_time") || !e["real_time"].is_number() || !e.contains("time_unit"))
      fail(file, fmt::format("benchmark '{}' has no numeric 'real_time' with a 'time_unit'", name));
    static const std::map<std::string, double> ms_per{
        {"ns", 1e-6}, {"us", 1e-3}, {"ms", 1.0}, {"s", 1e3}};
    const std::string unit = e["time_unit"].get<std::string>();
    if (!ms_per.contains(unit))
      fail(file,
           fmt::format("benchmark '{}' has time_unit '{}' (expected ns, us, ms or s)", name, unit));
    b.time_ms = e["real_time"].get<double>() * ms_per.at(unit);
  }
  for (const auto& [key, value] : e.items()) {
    if (value.is_number() && std::isfinite(value.get<double>()))
      b.counters[key] = value.get<double>();
  }
  return b;
}

/// The case a row measures: the same in repetitions, and in another file.
auto case_of(const BenchRow& b) {
  return std::tuple(b.family, b.model, b.contact, b.algorithm);
}

/// Puts `row` into `rows` in place of an earlier measurement of its case.
void merge_into(std::vector<BenchRow>& rows, BenchRow row) {
  if (const auto same = std::ranges::find(rows, case_of(row), case_of); same != rows.end())
    *same = std::move(row);
  else
    rows.push_back(std::move(row));
}

/// The standard deviations of a stddev aggregate, onto the row of its case (read before
/// it: Google Benchmark writes the median first).
void attach_stddev(std::vector<BenchRow>& rows, const json& e, std::size_t i,
                   const std::string& file) {
  const auto aggregate = read_row(e, i, file);
  if (!aggregate)
    return;
  const auto row = std::ranges::find(rows, case_of(*aggregate), case_of);
  if (row != rows.end()) {
    row->ratio_stddev = aggregate->ratio();
    row->time_stddev_ms = aggregate->time_ms;
    row->counter_stddev = aggregate->counters;
  }
}

/// Reads one parsed benchmark document: its source and its rows, one per case.
std::pair<BenchSource, std::vector<BenchRow>> read_document(const json& doc,
                                                            const std::string& file) {
  if (!doc.is_object())
    fail(file, "is not a JSON object (not Google Benchmark JSON output?)");
  if (!doc.contains("benchmarks") || !doc["benchmarks"].is_array())
    fail(file, "has no 'benchmarks' array (not Google Benchmark JSON output?)");
  BenchSource source{file, {}, 0};
  std::vector<BenchRow> rows;
  try {
    source.context = read_context(doc);
    const json& list = doc["benchmarks"];
    for (std::size_t i = 0; i < list.size(); ++i) {
      // Repetitions are followed by their aggregates: the median replaces them; mean, stddev and
      // cv are left out.
      const json& e = list[i];
      const std::string aggregate = e.is_object() && e.value("run_type", "") == "aggregate"
                                        ? e.value("aggregate_name", "")
                                        : "";
      if (aggregate == "stddev") {
        attach_stddev(rows, e, i, file);
        continue;
      }
      if (!aggregate.empty() && aggregate != "median")
        continue;
      auto row = read_row(e, i, file);
      source.n_other += row ? 0 : 1;
      if (row)
        merge_into(rows, std::move(*row));
    }
  } catch (const json::exception& e) {  // a field of the wrong type
    fail(file, e.what());
  }
  if (rows.empty()) {
    fail(file, fmt::format("has no Contact, ContactAllOptions or ModelCases benchmark ({} of "
                           "other families; written by bench_contact_algorithms?)",
                           source.n_other));
  }
  return {source, rows};
}

std::pair<BenchSource, std::vector<BenchRow>> load_bench_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    fail(name, std::filesystem::exists(file, ec) ? "is not a regular file" : "does not exist");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in)
    fail(name, "cannot be read");
  if (text.str().empty())
    fail(name, "is empty");
  json doc;
  try {  // the readers' one parser: depth and duplicate keys bounded, as for results files
    doc = schema::parse_json_text(json_without_nonfinite(text.str()), "benchmark file", name);
  } catch (const schema::SchemaError&) {
    fail(name, "is not valid JSON (truncated, nested beyond 64 levels, or a key given twice)");
  }
  return read_document(doc, name);
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

std::string BenchRow::failure() const {
  if (!error.empty())
    return "error: " + error;
  return label.starts_with("not converged") ? label : std::string();
}

std::vector<const BenchRow*> BenchResults::of(BenchFamily family) const {
  std::vector<const BenchRow*> out;
  for (const auto& b : rows) {
    if (b.family == family)
      out.push_back(&b);
  }
  const auto rank = [](const BenchRow* b) {
    return std::tuple(b->model, std::ranges::find(kBenchContacts, b->contact), b->algorithm);
  };
  std::ranges::stable_sort(out, {}, rank);
  return out;
}

const BenchRow* BenchGrid::at(schema::ContactKind contact, BenchMethod method) const {
  const auto it = std::ranges::find_if(
      cases, [&](const BenchRow* b) { return b->contact == contact && b->algorithm == method; });
  return it == cases.end() ? nullptr : *it;
}

std::optional<double> BenchGrid::reference_ms() const {
  const auto it =
      std::ranges::find_if(cases, [](const BenchRow* b) { return b->reference_ms().has_value(); });
  return it == cases.end() ? std::nullopt : (*it)->reference_ms();
}

std::vector<BenchGrid> contact_grids(const BenchResults& bench) {
  std::vector<BenchGrid> out;
  for (const BenchRow* b : bench.of(BenchFamily::Contact)) {
    if (out.empty() || out.back().model != b->model)
      out.emplace_back().model = b->model;
    BenchGrid& grid = out.back();
    grid.cases.push_back(b);
    if (std::ranges::find(grid.contacts, b->contact) == grid.contacts.end())
      grid.contacts.push_back(b->contact);  // the cases come in kBenchContacts' order
    if (std::ranges::find(grid.methods, b->algorithm) == grid.methods.end())
      grid.methods.push_back(b->algorithm);
  }
  for (BenchGrid& grid : out)
    std::ranges::sort(grid.methods);
  return out;
}

std::string model_md(const BenchModel& m) {
  return fmt::format("{}, mesh {}, {}", schema::label(m.problem), schema::to_string(m.mesh),
                     schema::to_string(m.element));
}

std::vector<BenchRow::Measurement> BenchRow::measurements() const {
  std::vector<Measurement> out = earlier;
  if (ratio())
    out.push_back({*ratio(), ratio_stddev, reference_ms()});
  return out;
}

BenchResults load_bench_files(const std::vector<std::filesystem::path>& files) {
  BenchResults all;
  std::set<std::size_t> remeasured;  // indices into all.rows
  for (const auto& file : files) {
    auto [source, rows] = load_bench_file(file);
    all.sources.push_back(std::move(source));
    for (BenchRow& r : rows) {
      const auto same = std::ranges::find(all.rows, case_of(r), case_of);
      if (same == all.rows.end()) {
        all.rows.push_back(std::move(r));
        continue;
      }
      remeasured.insert(static_cast<std::size_t>(same - all.rows.begin()));
      r.earlier = same->measurements();
      *same = std::move(r);
    }
  }
  all.n_replaced = static_cast<int>(remeasured.size());
  return all;
}

}  // namespace cs::reports
