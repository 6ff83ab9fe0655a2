#pragma once
// The timings of bench/bench_contact_algorithms, read from the JSON Google Benchmark writes
// (`--benchmark_out=FILE --benchmark_out_format=json`): the machine from `context`, and one
// BenchRow per entry of `benchmarks` named
//   Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>[/...],
//   ContactAllOptions/<problem>/<mesh>/<element>[/...]   or
//   ModelCases/<problem>/<mesh>/<element>[/...]
// (named as in results.json, the algorithm as in bench_method.hpp; Google Benchmark's suffixes
// such as /iterations:1/manual_time ignored). Benchmarks of other families are counted and left
// out. A case measured more than once is represented by the median aggregate Google Benchmark
// writes after its repetitions: in a file as across files, a later measurement of a case
// replaces an earlier one. Google Benchmark writes a non-finite counter as a bare NaN or
// Infinity, which is not JSON: it reads as no value.
//
// A file that cannot be used (missing, not JSON, an entry that cannot be read or whose name does
// not decode, e.g. the index-coded names of older versions, or no entry of the three families)
// is a ReportError of one line naming the file and the cause.

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "reports/bench/bench_method.hpp"

namespace cs::reports {

/// The machine a benchmark file was measured on (Google Benchmark's `context`); what the file
/// does not say stays empty.
struct BenchContext {
  std::string host_name, library_build_type, executable, date;
  std::optional<double> num_cpus, mhz_per_cpu;
  std::vector<double> load_avg;  ///< the 1, 5 and 15 minute load averages when the run began
  bool cpu_scaling_enabled = false;
};

/// One model of the timing matrix. Ordered as the report lists models: the battery's problem
/// order, then C, M, F, then Q4, Q8.
struct BenchModel {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::MeshLevel mesh = schema::MeshLevel::C;
  schema::Element element = schema::Element::Q4;
  auto operator<=>(const BenchModel&) const = default;
};

/// The benchmark families the report reads (their names' first part): one contact analysis
/// (counters ratio = time / reference, reference_s, active_set_iterations, augmentations); every
/// option of a model on one shared factorization (cases, converged, ratio_per_case, reference_s);
/// the main job's full set of cases of a model (cases, converged, one_case_s, ratio, ratio_cpu,
/// blas_threads).
enum class BenchFamily : std::uint8_t { Contact, ContactAllOptions, ModelCases };

/// The contact discretizations in the order the benchmarks are registered (the solver's).
inline constexpr std::array<schema::ContactKind, 3> kBenchContacts{
    schema::ContactKind::ns, schema::ContactKind::ss, schema::ContactKind::mortar};

/// One benchmark of any family: its model, its time and its counters by name.
struct BenchRow {
  BenchFamily family = BenchFamily::Contact;
  BenchModel model;
  schema::ContactKind contact = schema::ContactKind::ss;  ///< Contact rows only
  BenchMethod algorithm = BenchMethod::PM;                ///< Contact rows only
  /// The real (i.e. manual) time in milliseconds; nullopt when the run stopped with an error.
  std::optional<double> time_ms;
  std::map<std::string, double> counters;  ///< every finite number of the entry, by name
  std::string label;  ///< Google Benchmark's label, e.g. "not converged: <reason>"
  std::string error;  ///< error or skip message; non-empty when the run did not finish
  /// The ratio's standard deviation over the repetitions (the stddev aggregate), if repeated.
  std::optional<double> ratio_stddev;
  /// The standard deviations over the repetitions of the time (ms) and of every counter, by
  /// name (the stddev aggregate); none when the case was timed once.
  std::optional<double> time_stddev_ms;
  std::map<std::string, double> counter_stddev;
  /// A ratio as measured in one file: its median and its spread over repetitions, if any.
  struct Measurement {
    double ratio = 0.0;
    std::optional<double> stddev{};
    std::optional<double> reference_ms{};  ///< the model's reference in that file
  };
  /// The same case measured in earlier files (this row is the last file's).
  std::vector<Measurement> earlier;
  /// Every measurement of the case with a ratio: the earlier ones, then this row's.
  std::vector<Measurement> measurements() const;

  /// The counter `key`; nullopt when the entry has none (or a non-finite one).
  std::optional<double> counter(std::string_view key) const;
  /// The counter `key`, written in seconds, in milliseconds.
  std::optional<double> counter_ms(std::string_view key) const;
  std::optional<double> ratio() const { return counter("ratio"); }
  std::optional<double> reference_ms() const { return counter_ms("reference_s"); }
  /// "" when the run finished and converged, else what went wrong ("error: ...", or the label).
  std::string failure() const;
  bool converged() const { return failure().empty(); }
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
  std::vector<BenchRow> rows;
  /// Cases measured in more than one file: the later file's measurement is shown, the
  /// earlier ones kept beside it (BenchRow::earlier).
  int n_replaced = 0;
  /// The rows of `family` in the report's order: model, contact (kBenchContacts), algorithm.
  std::vector<const BenchRow*> of(BenchFamily family) const;
};

/// The Contact benchmarks of one model: a grid of the options measured.
struct BenchGrid {
  BenchModel model;
  std::vector<const BenchRow*> cases;         ///< in the report's order
  std::vector<schema::ContactKind> contacts;  ///< in kBenchContacts' order
  std::vector<BenchMethod> methods;           ///< in the solver's order
  /// The case of this option; nullptr when there is none.
  const BenchRow* at(schema::ContactKind contact, BenchMethod method) const;
  /// The model's reference time: that of its first case with one.
  std::optional<double> reference_ms() const;
};

/// The Contact benchmarks of `bench`, one grid per model in the report's order.
std::vector<BenchGrid> contact_grids(const BenchResults& bench);

/// "H<sub>p</sub>, mesh F, Q4".
std::string model_md(const BenchModel& model);

/// Reads every file and merges them in order (see BenchResults::n_replaced). Throws ReportError
/// for the first file that cannot be used.
BenchResults load_bench_files(const std::vector<std::filesystem::path>& files);

}  // namespace cs::reports
