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

  std::optional<double> counter(const char* key) const {
    const auto it = counters.find(key);
    return it == counters.end() ? std::nullopt : std::optional(it->second);
  }
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

std::optional<double> seconds_to_ms(const std::optional<double>& seconds) {
  return seconds ? std::optional(*seconds * 1000) : std::nullopt;
}

std::optional<int> count(const std::optional<double>& value) {
  return value ? std::optional(static_cast<int>(std::lround(*value))) : std::nullopt;
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

ContactBenchmark contact_benchmark(const Entry& e, const std::string& source) {
  const std::string form = "Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>";
  e.require(e.parts.size() >= 6, form, source);
  ContactBenchmark b;
  b.name = e.name;
  b.model = decode_model(e, form, source);
  const auto contact = schema::try_parse<schema::ContactKind>(e.parts[4]);
  const auto algorithm = schema::try_parse<BenchMethod>(e.parts[5]);
  e.require(contact && algorithm, form, source);
  b.contact = *contact;
  b.algorithm = *algorithm;
  b.time_ms = e.time_ms;
  b.ratio = e.counter("ratio");
  b.reference_ms = seconds_to_ms(e.counter("reference_s"));
  b.active_set_iterations = e.counter("active_set_iterations");
  b.augmentations = e.counter("augmentations");
  b.counters = e.counters;
  b.label = e.label;
  b.error = e.error;
  return b;
}

AllOptionsBenchmark all_options_benchmark(const Entry& e, const std::string& source) {
  const std::string form = "ContactAllOptions/<problem>/<mesh>/<element>";
  e.require(e.parts.size() >= 4, form, source);
  AllOptionsBenchmark b;
  b.name = e.name;
  b.model = decode_model(e, form, source);
  b.time_ms = e.time_ms;
  b.ratio_per_case = e.counter("ratio_per_case");
  b.reference_ms = seconds_to_ms(e.counter("reference_s"));
  b.cases = count(e.counter("cases"));
  b.converged = count(e.counter("converged"));
  b.label = e.label;
  b.error = e.error;
  return b;
}

/// The case a record measures, to find repetitions and the same case in another file.
std::string case_key(const ContactBenchmark& b) {
  return fmt::format("{}/{}/{}", model_md(b.model), schema::to_string(b.contact),
                     schema::to_string(b.algorithm));
}
std::string case_key(const AllOptionsBenchmark& b) {
  return model_md(b.model);
}

/// Per case, in order of first appearance, the measurement that represents it: the median
/// aggregate, else the mean aggregate, else the repetition of median time (the lower median of
/// an even count; errors last). `runs` pairs each record with its aggregate name.
template <class Record>
std::vector<Record> representatives(const std::vector<std::pair<std::string, Record>>& runs) {
  std::vector<Record> out;
  std::vector<std::string> done;
  for (const auto& [unused, first] : runs) {
    const std::string key = case_key(first);
    if (std::find(done.begin(), done.end(), key) != done.end())
      continue;
    done.push_back(key);
    std::map<std::string, std::vector<const Record*>> by_aggregate;
    for (const auto& [aggregate, r] : runs) {
      if (case_key(r) == key)
        by_aggregate[aggregate].push_back(&r);
    }
    std::vector<const Record*> reps = by_aggregate[""];
    std::stable_sort(reps.begin(), reps.end(), [](const Record* a, const Record* b) {
      return a->time_ms.value_or(INFINITY) < b->time_ms.value_or(INFINITY);
    });
    const Record* chosen = !by_aggregate["median"].empty() ? by_aggregate["median"].front()
                           : !by_aggregate["mean"].empty() ? by_aggregate["mean"].front()
                           : !reps.empty()                 ? reps[(reps.size() - 1) / 2]
                                                           : &first;
    out.push_back(*chosen);
  }
  return out;
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

/// Appends `records` (of source `source`) to `into`, replacing the same case measured earlier.
template <class Record>
int merge_into(std::vector<Record>& into, std::vector<Record> records, std::size_t source) {
  int replaced = 0;
  for (Record& r : records) {
    r.source = source;
    const auto same = std::find_if(into.begin(), into.end(),
                                   [&](const Record& old) { return case_key(old) == case_key(r); });
    replaced += same != into.end() ? 1 : 0;
    if (same != into.end())
      *same = std::move(r);
    else
      into.push_back(std::move(r));
  }
  return replaced;
}

}  // namespace

bool ContactBenchmark::converged() const {
  return failure().empty();
}

std::string ContactBenchmark::failure() const {
  if (!error.empty())
    return "error: " + error;
  return label.starts_with("not converged") ? label : std::string();
}

const std::vector<schema::ContactKind>& bench_contacts() {
  static const std::vector<schema::ContactKind> order{
      schema::ContactKind::ns, schema::ContactKind::ss, schema::ContactKind::mortar};
  return order;
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
  try {
    out.sources.push_back({source, read_context(doc), 0});
    std::vector<std::pair<std::string, ContactBenchmark>> contact;
    std::vector<std::pair<std::string, AllOptionsBenchmark>> all_options;
    const json& list = doc["benchmarks"];
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Entry e = read_entry(list[i], i, source);
      if (!e.aggregate.empty() && e.aggregate != "median" && e.aggregate != "mean")
        continue;  // stddev, cv: not a time
      if (e.parts.front() == "Contact")
        contact.emplace_back(e.aggregate, contact_benchmark(e, source));
      else if (e.parts.front() == "ContactAllOptions")
        all_options.emplace_back(e.aggregate, all_options_benchmark(e, source));
      else
        ++out.sources.front().n_other;
    }
    out.contact = representatives(contact);
    out.all_options = representatives(all_options);
  } catch (const json::exception& e) {  // a field of the wrong type
    fail(source, e.what());
  }
  if (out.contact.empty() && out.all_options.empty()) {
    fail(source, fmt::format("has no Contact or ContactAllOptions benchmark ({} of other families; "
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
    all.n_replaced += merge_into(all.contact, std::move(one.contact), source);
    all.n_replaced += merge_into(all.all_options, std::move(one.all_options), source);
  }
  return all;
}

std::vector<std::vector<const ContactBenchmark*>> finest_models(const BenchResults& bench) {
  std::map<std::tuple<int, int>, BenchModel> finest;  // (problem, element) rank -> model
  for (const auto& b : bench.contact) {
    if (!b.time_ms)
      continue;
    const auto [problem, mesh, element] = model_order(b.model);
    const auto [it, added] = finest.try_emplace({problem, element}, b.model);
    if (!added && std::get<1>(model_order(it->second)) < mesh)
      it->second = b.model;
  }
  std::vector<std::vector<const ContactBenchmark*>> out;
  for (const auto& [rank, model] : finest) {
    out.emplace_back();
    for (const auto& b : bench.contact)
      out.back().insert(out.back().end(), b.model == model ? 1 : 0, &b);
  }
  return out;
}

}  // namespace cs::reports
