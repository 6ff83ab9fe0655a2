#pragma once
// The timings of bench/bench_contact_algorithms, read from the JSON Google Benchmark writes
// (`--benchmark_out=FILE --benchmark_out_format=json`, or `--benchmark_format=json` on stdout)
// into plain records for the report's benchmark section.
//
// What is read: `context` (the machine: date, host_name, num_cpus, mhz_per_cpu,
// library_build_type, load_avg) and each entry of `benchmarks` whose name decodes as
//   Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>[/...],
//   ContactAllOptions/<problem>/<mesh>/<element>[/...]   or
//   ModelCases/<problem>/<mesh>/<element>[/...]
// (problem, mesh, element and contact named as in results.json, e.g. Pprime_p/F/Q4/ss, read with
// the vocabulary of schema/; the algorithm as the solver names its methods, see bench_method.hpp;
// Google Benchmark's own suffixes such as /iterations:1/manual_time are ignored): real_time
// converted to milliseconds from its time_unit, the counters (every other numeric top-level key),
// `label` ("not converged: ..."), error_occurred/error_message and skipped/skip_message, into one
// shape of row (BenchRow) for every family. Benchmarks of other families are counted and left
// out.
//
// Repetitions: a case measured more than once is represented by its `median` aggregate when the
// file has one, else its `mean` aggregate, else the repetition of median time.
//
// Google Benchmark writes a non-finite counter as a bare NaN or Infinity, which is not JSON;
// those read as "no value".
//
// A file that is missing, unreadable, not JSON, without a `benchmarks` array, with an entry
// that cannot be read, with a Contact entry whose name does not decode (e.g. the index-coded
// names of older versions), or with no entry of the three families at all is an error
// (ReportError, one line naming the file and the cause).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/bench/bench_method.hpp"

namespace cs::reports {

/// The machine a benchmark file was measured on (Google Benchmark's `context`); what the file
/// does not say stays empty.
struct BenchContext {
  std::string date;                ///< as written, e.g. "2024-05-01T10:00:00+00:00"
  std::string host_name;           ///< e.g. "ci-runner-3"
  std::string executable;          ///< the benchmark program's path as it was run
  std::string library_build_type;  ///< of the Google Benchmark library: "release" | "debug"
  std::optional<int> num_cpus;
  std::optional<double> mhz_per_cpu;
  std::vector<double> load_avg;  ///< the 1, 5 and 15 minute load averages when the run began
  std::optional<bool> cpu_scaling_enabled;
};

/// One model of the timing matrix: the problem, mesh level and element.
struct BenchModel {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::MeshLevel mesh = schema::MeshLevel::C;
  schema::Element element = schema::Element::Q4;
  bool operator==(const BenchModel&) const = default;
};

/// The benchmark families the report reads (their names' first part).
enum class BenchFamily : std::uint8_t {
  /// Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>: one contact analysis; counters
  /// ratio (time / reference), reference_s (one assembly + factorization + solve),
  /// active_set_iterations (linear solves of the condensed problem), augmentations (AL).
  Contact,
  /// ContactAllOptions/<problem>/<mesh>/<element>: every contact discretization x algorithm of
  /// one model on one shared factorization; counters cases, converged, ratio_per_case
  /// (time / cases / reference), reference_s.
  ContactAllOptions,
  /// ModelCases/<problem>/<mesh>/<element>: the main job's full set of cases of one model on one
  /// executor; counters cases, converged, one_case_s (one analysis of the model), ratio
  /// (time / one_case_s), one_case_cpu_s and ratio_cpu (the same in process CPU time),
  /// blas_threads.
  ModelCases,
};

/// One benchmark of any family: its model, its time and its counters by name.
struct BenchRow {
  BenchFamily family = BenchFamily::Contact;
  std::string name;  ///< as in the file
  BenchModel model;
  schema::ContactKind contact = schema::ContactKind::ss;  ///< Contact rows only
  BenchMethod algorithm = BenchMethod::PM;                ///< Contact rows only
  /// The benchmark's real (i.e. manual) time in milliseconds, whatever the file's time_unit;
  /// nullopt when the run stopped with an error.
  std::optional<double> time_ms;
  std::map<std::string, double> counters;  ///< every finite counter, by name
  std::string label;       ///< Google Benchmark's label, e.g. "not converged: <reason>"
  std::string error;       ///< error or skip message; non-empty when the run did not finish
  std::size_t source = 0;  ///< index of its file in BenchResults::sources

  /// The counter `key`; nullopt when the file has none (or a non-finite one).
  std::optional<double> counter(std::string_view key) const;
  /// The counter `key`, written in seconds, in milliseconds.
  std::optional<double> counter_ms(std::string_view key) const;
  /// The counter `key` rounded to a count (cases, converged, threads).
  std::optional<int> count(std::string_view key) const;
  std::optional<double> ratio() const { return counter("ratio"); }
  std::optional<double> reference_ms() const { return counter_ms("reference_s"); }
  /// Ran to the end and is not labelled "not converged".
  bool converged() const;
  /// "" when converged, else what went wrong ("error: ...", or the label).
  std::string failure() const;
};

/// One benchmark file as read.
struct BenchSource {
  std::string file;  ///< the path as given
  BenchContext context;
  int n_other = 0;  ///< benchmarks of other families, left out
};

/// Every benchmark of one or more files.
struct BenchResults {
  std::vector<BenchSource> sources;
  std::vector<BenchRow> contact;      ///< BenchFamily::Contact
  std::vector<BenchRow> all_options;  ///< BenchFamily::ContactAllOptions
  std::vector<BenchRow> model_cases;  ///< BenchFamily::ModelCases
  /// Cases measured in more than one file: the later file's measurement is kept.
  int n_replaced = 0;
};

/// The contact discretizations in the order the benchmarks are registered (the solver's):
/// ns, ss, mortar.
const std::vector<schema::ContactKind>& bench_contacts();

/// The options that Contact rows measure: their discretizations in bench_contacts()' order and
/// their methods in the solver's.
struct BenchOptions {
  std::vector<schema::ContactKind> contacts;
  std::vector<BenchMethod> methods;
};
BenchOptions options_of(const std::vector<const BenchRow*>& cases);

/// The rank of a model in the report's order: the battery's problem order, then C, M, F, then
/// Q4, Q8. Compare with <.
std::tuple<int, int, int> model_order(const BenchModel& model);

/// Milliseconds per unit of Google Benchmark's time_unit ("ns", "us", "ms", "s"); nullopt for
/// anything else.
std::optional<double> milliseconds_per(std::string_view time_unit);

/// `text` with Google Benchmark's bare NaN, -NaN, Infinity and -Infinity values (outside
/// strings) replaced by null, so that it parses as JSON.
std::string json_without_nonfinite(std::string_view text);

/// "H<sub>p</sub>, mesh F, Q4".
std::string model_md(const BenchModel& model);

/// Per problem and element, in the report's order, the benchmarks of its finest mesh with a
/// timed case.
std::vector<std::vector<const BenchRow*>> finest_models(const BenchResults& bench);

/// Reads one parsed benchmark document; `source` names it in errors. Throws ReportError.
BenchResults parse_bench_document(const nlohmann::json& doc, const std::string& source);

/// Reads one benchmark file. Throws ReportError.
BenchResults load_bench_file(const std::filesystem::path& file);

/// Reads every file and merges them in order (see BenchResults::n_replaced). Throws ReportError
/// for the first file that cannot be used.
BenchResults load_bench_files(const std::vector<std::filesystem::path>& files);

}  // namespace cs::reports
