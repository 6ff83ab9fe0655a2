#include "reports/bench/bench_results.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

using nlohmann::json;

/// Errors about one file: "bench file 'X': <what>".
class Where {
 public:
  explicit Where(std::string source) : source_(std::move(source)) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw ReportError(fmt::format("bench file '{}': {}", source_, what));
  }
  [[noreturn]] void fail(const std::string& benchmark, const std::string& what) const {
    fail(fmt::format("benchmark '{}' {}", benchmark, what));
  }

 private:
  std::string source_;
};

/// The keys of a benchmark entry that Google Benchmark writes itself; the rest are counters.
bool is_counter_key(const std::string& key) {
  static const std::set<std::string> own{"name",
                                         "family_index",
                                         "per_family_instance_index",
                                         "run_name",
                                         "run_type",
                                         "repetitions",
                                         "repetition_index",
                                         "threads",
                                         "iterations",
                                         "real_time",
                                         "cpu_time",
                                         "time_unit",
                                         "aggregate_name",
                                         "aggregate_unit",
                                         "error_occurred",
                                         "error_message",
                                         "skipped",
                                         "skip_message",
                                         "label",
                                         "big_o",
                                         "rms",
                                         "complexity",
                                         "allocs_per_iter",
                                         "max_bytes_used",
                                         "total_allocated_bytes",
                                         "net_heap_growth",
                                         "memory_iterations"};
  return own.count(key) == 0;
}

/// The fields of one entry of `benchmarks` that the report uses.
struct Entry {
  std::string name;                ///< as written
  std::vector<std::string> parts;  ///< run_name (name without aggregate suffix) split at '/'
  std::string run_type;            ///< "iteration" | "aggregate"
  std::string aggregate;           ///< "mean", "median", ... for aggregates
  std::optional<double> time_ms;
  std::map<std::string, double> counters;
  std::string label, error;
};

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator))
    parts.push_back(part);
  return parts;
}

std::string string_field(const json& e, const char* key) {
  const auto it = e.find(key);
  return it != e.end() && it->is_string() ? it->get<std::string>() : std::string();
}

bool true_field(const json& e, const char* key) {
  const auto it = e.find(key);
  return it != e.end() && it->is_boolean() && it->get<bool>();
}

/// Why the run did not finish: error_occurred/error_message, or skipped/skip_message.
std::string stop_reason(const json& e) {
  if (true_field(e, "error_occurred")) {
    const std::string message = string_field(e, "error_message");
    return message.empty() ? "error (no message)" : message;
  }
  if (true_field(e, "skipped")) {
    const std::string message = string_field(e, "skip_message");
    return message.empty() ? "skipped" : "skipped: " + message;
  }
  return {};
}

/// real_time in milliseconds; throws when it or its time_unit is missing or unknown.
double time_ms(const json& e, const std::string& name, const Where& where) {
  const auto time = e.find("real_time");
  const auto unit = e.find("time_unit");
  if (time == e.end() || !time->is_number() || unit == e.end() || !unit->is_string())
    where.fail(name, "has no numeric 'real_time' with a 'time_unit'");
  const auto factor = milliseconds_per(unit->get<std::string>());
  if (!factor)
    where.fail(name, fmt::format("has time_unit '{}' (expected ns, us, ms or s)",
                                 unit->get<std::string>()));
  return time->get<double>() * *factor;
}

Entry read_entry(const json& e, std::size_t i, const Where& where) {
  if (!e.is_object())
    where.fail(fmt::format("entry {} of 'benchmarks' is not an object", i));
  Entry out;
  out.name = string_field(e, "name");
  if (out.name.empty())
    where.fail(fmt::format("entry {} of 'benchmarks' has no 'name'", i));
  const std::string run_name = string_field(e, "run_name");
  out.parts = split(run_name.empty() ? out.name : run_name, '/');
  out.run_type = string_field(e, "run_type");
  out.aggregate = string_field(e, "aggregate_name");
  out.label = string_field(e, "label");
  out.error = stop_reason(e);
  if (out.error.empty())  // a run stopped by an error has no time worth showing
    out.time_ms = time_ms(e, out.name, where);
  for (const auto& [key, value] : e.items()) {
    if (value.is_number() && is_counter_key(key) && std::isfinite(value.get<double>()))
      out.counters[key] = value.get<double>();
  }
  return out;
}

std::optional<double> counter(const Entry& e, const char* key) {
  const auto it = e.counters.find(key);
  return it == e.counters.end() ? std::nullopt : std::optional<double>(it->second);
}

std::optional<double> seconds_to_ms(const std::optional<double>& seconds) {
  return seconds ? std::optional<double>(*seconds * 1000) : std::nullopt;
}

std::optional<int> count(const std::optional<double>& value) {
  return value ? std::optional<int>(static_cast<int>(std::lround(*value))) : std::nullopt;
}

/// The model of parts[1..3]; throws naming the expected form when a part is not a known name.
BenchModel decode_model(const Entry& e, const std::string& form, const Where& where) {
  const auto problem = schema::try_parse<schema::ProblemId>(e.parts[1]);
  const auto mesh = schema::try_parse<schema::MeshLevel>(e.parts[2]);
  const auto element = schema::try_parse<schema::Element>(e.parts[3]);
  if (!problem || !mesh || !element) {
    where.fail(e.name, fmt::format("does not name its case as {} (written by an older "
                                   "bench_contact_algorithms?)",
                                   form));
  }
  return {*problem, *mesh, *element};
}

ContactBenchmark contact_benchmark(const Entry& e, const Where& where) {
  const std::string form = "Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>";
  if (e.parts.size() < 6)
    where.fail(e.name, "does not name its case as " + form);
  ContactBenchmark b;
  b.name = e.name;
  b.model = decode_model(e, form, where);
  const auto contact = schema::try_parse<schema::ContactKind>(e.parts[4]);
  const auto algorithm = schema::try_parse<BenchMethod>(e.parts[5]);
  if (!contact || !algorithm)
    where.fail(e.name, "does not name its case as " + form);
  b.contact = *contact;
  b.algorithm = *algorithm;
  b.time_ms = e.time_ms;
  b.ratio = counter(e, "ratio");
  b.reference_ms = seconds_to_ms(counter(e, "reference_s"));
  b.active_set_iterations = counter(e, "active_set_iterations");
  b.augmentations = counter(e, "augmentations");
  b.counters = e.counters;
  b.label = e.label;
  b.error = e.error;
  return b;
}

AllOptionsBenchmark all_options_benchmark(const Entry& e, const Where& where) {
  const std::string form = "ContactAllOptions/<problem>/<mesh>/<element>";
  if (e.parts.size() < 4)
    where.fail(e.name, "does not name its case as " + form);
  AllOptionsBenchmark b;
  b.name = e.name;
  b.model = decode_model(e, form, where);
  b.time_ms = e.time_ms;
  b.ratio_per_case = counter(e, "ratio_per_case");
  b.reference_ms = seconds_to_ms(counter(e, "reference_s"));
  b.cases = count(counter(e, "cases"));
  b.converged = count(counter(e, "converged"));
  b.label = e.label;
  b.error = e.error;
  return b;
}

/// The case a record measures, to find repetitions and the same case in another file.
std::string model_key(const BenchModel& m) {
  return fmt::format("{}/{}/{}", schema::to_string(m.problem), schema::to_string(m.mesh),
                     schema::to_string(m.element));
}
std::string case_key(const ContactBenchmark& b) {
  return fmt::format("{}/{}/{}", model_key(b.model), schema::to_string(b.contact),
                     schema::to_string(b.algorithm));
}
std::string case_key(const AllOptionsBenchmark& b) {
  return model_key(b.model);
}

/// The measurements of each case in file order; one() picks the one that represents it.
template <class Record>
class Repetitions {
 public:
  void add(const Entry& e, Record record) {
    const std::string key = case_key(record);
    if (!runs_.count(key))
      order_.push_back(key);
    runs_[key].push_back(
        {e.run_type == "aggregate" ? e.aggregate : std::string(), std::move(record)});
  }
  /// Per case, in order of first appearance: the median aggregate, else the mean aggregate,
  /// else the repetition of median time (the lower median of an even count; errors last).
  std::vector<Record> chosen() const {
    std::vector<Record> out;
    for (const auto& key : order_)
      out.push_back(one(runs_.at(key)));
    return out;
  }

 private:
  struct Run {
    std::string aggregate;  ///< empty for a repetition
    Record record;
  };
  static Record one(const std::vector<Run>& runs) {
    for (const char* preferred : {"median", "mean"}) {
      for (const Run& r : runs) {
        if (r.aggregate == preferred)
          return r.record;
      }
    }
    std::vector<const Record*> repetitions;
    for (const Run& r : runs) {
      if (r.aggregate.empty())
        repetitions.push_back(&r.record);
    }
    if (repetitions.empty())  // only other aggregates (stddev, cv): nothing to show as a time
      return runs.front().record;
    std::stable_sort(repetitions.begin(), repetitions.end(), [](const Record* a, const Record* b) {
      return a->time_ms.value_or(INFINITY) < b->time_ms.value_or(INFINITY);
    });
    return *repetitions[(repetitions.size() - 1) / 2];
  }
  std::vector<std::string> order_;
  std::map<std::string, std::vector<Run>> runs_;
};

BenchContext read_context(const json& doc, const Where& where) {
  BenchContext c;
  const auto it = doc.find("context");
  if (it == doc.end())
    return c;
  if (!it->is_object())
    where.fail("'context' is not an object");
  const json& j = *it;
  c.date = string_field(j, "date");
  c.host_name = string_field(j, "host_name");
  c.executable = string_field(j, "executable");
  c.library_build_type = string_field(j, "library_build_type");
  if (j.contains("num_cpus") && j["num_cpus"].is_number())
    c.num_cpus = j["num_cpus"].get<int>();
  if (j.contains("mhz_per_cpu") && j["mhz_per_cpu"].is_number())
    c.mhz_per_cpu = j["mhz_per_cpu"].get<double>();
  if (j.contains("cpu_scaling_enabled") && j["cpu_scaling_enabled"].is_boolean())
    c.cpu_scaling_enabled = j["cpu_scaling_enabled"].get<bool>();
  if (j.contains("load_avg") && j["load_avg"].is_array()) {
    for (const auto& v : j["load_avg"]) {
      if (v.is_number())
        c.load_avg.push_back(v.get<double>());
    }
  }
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
    if (same != into.end()) {
      *same = std::move(r);
      ++replaced;
    } else {
      into.push_back(std::move(r));
    }
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
  if (label.rfind("not converged", 0) == 0)
    return label;
  return {};
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
  if (time_unit == "ns")
    return 1e-6;
  if (time_unit == "us")
    return 1e-3;
  if (time_unit == "ms")
    return 1.0;
  if (time_unit == "s")
    return 1e3;
  return std::nullopt;
}

std::string json_without_nonfinite(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size())
        out += text[++i];
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
      out += c;
      continue;
    }
    const std::size_t start = i + (c == '-' ? 1 : 0);
    bool replaced = false;
    for (std::string_view word : {"NaN", "Infinity"}) {
      const std::size_t end = start + word.size();
      if (text.substr(start, word.size()) == word &&
          (end == text.size() || std::isalnum(static_cast<unsigned char>(text[end])) == 0)) {
        out += "null";
        i = end - 1;
        replaced = true;
        break;
      }
    }
    if (!replaced)
      out += c;
  }
  return out;
}

BenchResults parse_bench_document(const json& doc, const std::string& source) {
  const Where where(source);
  if (!doc.is_object())
    where.fail("is not a JSON object (not Google Benchmark JSON output?)");
  const auto list = doc.find("benchmarks");
  if (list == doc.end() || !list->is_array())
    where.fail("has no 'benchmarks' array (not Google Benchmark JSON output?)");
  BenchResults out;
  out.sources.push_back({source, read_context(doc, where), 0});
  Repetitions<ContactBenchmark> contact;
  Repetitions<AllOptionsBenchmark> all_options;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const Entry e = read_entry((*list)[i], i, where);
    if (e.run_type == "aggregate" && e.aggregate != "median" && e.aggregate != "mean")
      continue;  // stddev, cv: not a time
    if (e.parts.front() == "Contact")
      contact.add(e, contact_benchmark(e, where));
    else if (e.parts.front() == "ContactAllOptions")
      all_options.add(e, all_options_benchmark(e, where));
    else
      ++out.sources.front().n_other;
  }
  out.contact = contact.chosen();
  out.all_options = all_options.chosen();
  if (out.contact.empty() && out.all_options.empty()) {
    where.fail(
        fmt::format("has no Contact or ContactAllOptions benchmark ({} of other families; "
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
  if (!in)
    throw ReportError(fmt::format("bench file '{}' cannot be read", name));
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().empty())
    throw ReportError(fmt::format("bench file '{}' is empty", name));
  json doc;
  try {
    doc = json::parse(json_without_nonfinite(text.str()));
  } catch (const json::parse_error& e) {
    throw ReportError(
        fmt::format("bench file '{}' is not valid JSON (truncated?): {}", name, e.what()));
  }
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
