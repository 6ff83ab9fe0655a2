// Reading Google Benchmark JSON of bench_contact_algorithms: names decoded into model and
// options, times converted to milliseconds whatever the time_unit, counters read, a case that
// did not converge or stopped with an error surfaced, repetitions represented by their median,
// and every file the report cannot use rejected with one line naming it.
//
// data/small_bench.json is hand-written in the format of Google Benchmark 1.7 (its values are
// invented and consistent: ratio = time / reference): H_p F Q4 at mesh F with ss PM (ratio 1.4),
// AL (1.6, in us), LM (1.2, in ns, not converged), MPC (3.0, in s), ns PM (error); H_p C Q4 ss
// AL (1.9); Pprime_p F Q8 mortar LM (1.1); ContactAllOptions H_p F Q4; and one benchmark of
// another family.

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/bench/bench_results.hpp"
#include "reports/report_error.hpp"
#include "support/tolerance.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::TempDir;
using testing::write_text;

fs::path bench_path() {
  return testing::source_dir() / "tests" / "reports" / "data" / "small_bench.json";
}

/// The Contact benchmark named "problem/mesh/element/contact/algorithm" as in the file.
const BenchRow& find(const BenchResults& r, const std::string& problem, const std::string& mesh,
                     const std::string& element, const std::string& contact,
                     const std::string& algorithm) {
  const BenchModel model{schema::parse<schema::ProblemId>(problem),
                         schema::parse<schema::MeshLevel>(mesh),
                         schema::parse<schema::Element>(element)};
  const auto it = std::find_if(r.rows.begin(), r.rows.end(), [&](const auto& b) {
    return b.family == BenchFamily::Contact && b.model == model &&
           b.contact == schema::parse<schema::ContactKind>(contact) &&
           b.algorithm == schema::parse<BenchMethod>(algorithm);
  });
  if (it == r.rows.end())
    throw std::runtime_error("no case " + problem + "/" + mesh + "/" + element + "/" + contact +
                             "/" + algorithm);
  return *it;
}

// Times are exact binary fractions of the file's numbers times a power of ten: round-off only.
constexpr cs::testing::Tolerance kRoundOff{1e-12, 1e-12};

TEST(BenchResults, DecodesNamesAndReadsTheContext) {
  const BenchResults r = load_bench_files({bench_path()});
  ASSERT_EQ(r.sources.size(), 1u);
  EXPECT_EQ(r.sources[0].file, bench_path().string());
  EXPECT_EQ(r.sources[0].n_other, 1);  // BM_Assembly
  const BenchContext& c = r.sources[0].context;
  EXPECT_EQ(c.host_name, "bench-host");
  EXPECT_EQ(c.num_cpus, 2.0);
  EXPECT_EQ(c.mhz_per_cpu, 2800.0);
  EXPECT_EQ(c.library_build_type, "release");
  EXPECT_EQ(c.load_avg, (std::vector<double>{0.5, 0.25, 0.125}));
  EXPECT_EQ(c.date, "2024-05-01T10:00:00+00:00");
  EXPECT_EQ(c.executable, "build/bench/bench_contact_algorithms");
  EXPECT_FALSE(c.cpu_scaling_enabled);

  // In the report's order: P'_p before H_p, C before F, ns before ss, PM before AL.
  std::vector<std::string> contact;
  for (const BenchRow* b : r.of(BenchFamily::Contact)) {
    contact.push_back(fmt::format("{}/{}/{}/{}/{}", schema::to_string(b->model.problem),
                                  schema::to_string(b->model.mesh),
                                  schema::to_string(b->model.element),
                                  schema::to_string(b->contact), schema::to_string(b->algorithm)));
  }
  EXPECT_EQ(contact, (std::vector<std::string>{"Pprime_p/F/Q8/mortar/LM", "H_p/C/Q4/ss/AL",
                                               "H_p/F/Q4/ns/PM", "H_p/F/Q4/ss/PM", "H_p/F/Q4/ss/AL",
                                               "H_p/F/Q4/ss/LM", "H_p/F/Q4/ss/MPC"}));
  const BenchRow& lm = find(r, "Pprime_p", "F", "Q8", "mortar", "LM");
  EXPECT_EQ(lm.model.problem, schema::ProblemId::Pprime_p);
  EXPECT_EQ(lm.algorithm, BenchMethod::LM);
  EXPECT_EQ(study_algorithm(lm.algorithm), schema::Algorithm::LMP);
  const auto all_options = r.of(BenchFamily::ContactAllOptions);
  ASSERT_EQ(all_options.size(), 1u);
  EXPECT_EQ(all_options[0]->model,
            (BenchModel{schema::ProblemId::H_p, schema::MeshLevel::F, schema::Element::Q4}));
  EXPECT_EQ(all_options[0]->counter("cases"), 12.0);
  EXPECT_EQ(all_options[0]->counter("converged"), 11.0);
  EXPECT_TRUE(cs::testing::Near(*all_options[0]->counter("ratio_per_case"), 0.9, kRoundOff));
  EXPECT_TRUE(cs::testing::Near(*all_options[0]->time_ms, 108.0, kRoundOff));
  EXPECT_TRUE(r.of(BenchFamily::ModelCases).empty());
}

TEST(BenchResults, ConvertsEveryTimeUnitToMilliseconds) {
  const BenchResults r = load_bench_files({bench_path()});
  EXPECT_TRUE(cs::testing::Near(*find(r, "H_p", "F", "Q4", "ss", "PM").time_ms, 14.0, kRoundOff));
  EXPECT_TRUE(cs::testing::Near(*find(r, "H_p", "F", "Q4", "ss", "AL").time_ms, 16.0, kRoundOff));
  EXPECT_TRUE(cs::testing::Near(*find(r, "H_p", "F", "Q4", "ss", "LM").time_ms, 12.0, kRoundOff));
  EXPECT_TRUE(cs::testing::Near(*find(r, "H_p", "F", "Q4", "ss", "MPC").time_ms, 30.0, kRoundOff));
}

TEST(BenchResults, ReadsCounters) {
  const BenchResults r = load_bench_files({bench_path()});
  const BenchRow& al = find(r, "H_p", "F", "Q4", "ss", "AL");
  EXPECT_EQ(al.ratio(), 1.6);
  EXPECT_EQ(al.counter("active_set_iterations"), 5.0);
  EXPECT_EQ(al.counter("augmentations"), 3.0);
  EXPECT_TRUE(cs::testing::Near(*al.reference_ms(), 10.0, kRoundOff));  // reference_s 0.01
  EXPECT_EQ(al.counter("candidates"), 88.0);
  EXPECT_FALSE(al.counter("condensation_s").has_value());
  EXPECT_EQ(find(r, "H_p", "F", "Q4", "ss", "PM").counter_ms("condensation_s"), 6.0);
}

TEST(BenchResults, SurfacesNotConvergedAndErrors) {
  const BenchResults r = load_bench_files({bench_path()});
  EXPECT_TRUE(find(r, "H_p", "F", "Q4", "ss", "PM").converged());
  const BenchRow& lm = find(r, "H_p", "F", "Q4", "ss", "LM");
  EXPECT_FALSE(lm.converged());
  EXPECT_EQ(lm.failure(), "not converged: active set cycles between two states");
  const BenchRow& failed = find(r, "H_p", "F", "Q4", "ns", "PM");
  EXPECT_FALSE(failed.converged());
  EXPECT_FALSE(failed.time_ms.has_value());
  EXPECT_EQ(failed.failure(), "error: reference factorization failed");
}

TEST(BenchResults, ReadsNonFiniteValuesAsNoValue) {
  // A NaN ratio (a failed reference factorization) reads as no ratio, not as a bad file; NaN
  // and Infinity inside strings stay as they are.
  TempDir tmp;
  std::string text = read_text(bench_path());
  const auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("\"ratio\": 1.4", "\"ratio\": NaN");
  replace("\"augmentations\": 3", "\"augmentations\": -Infinity");
  replace("active set cycles between two states", R"(\"NaN\" at step Infinity)");
  write_text(tmp.path() / "nan.json", text);
  const BenchResults r = load_bench_files({tmp.path() / "nan.json"});
  EXPECT_FALSE(find(r, "H_p", "F", "Q4", "ss", "PM").ratio().has_value());
  EXPECT_EQ(find(r, "H_p", "F", "Q4", "ss", "PM").counter("reference_s"), 0.01);
  EXPECT_FALSE(find(r, "H_p", "F", "Q4", "ss", "AL").counter("augmentations").has_value());
  EXPECT_EQ(find(r, "H_p", "F", "Q4", "ss", "LM").label,
            R"(not converged: "NaN" at step Infinity)");
}

TEST(BenchResults, AStringOfAnyLengthIsRead) {
  // The non-finite values are replaced in one pass: a label of 300,000 characters (with an
  // escaped quote and a NaN in it) is read as written, and a NaN after it still reads as none.
  TempDir tmp;
  std::string text = read_text(bench_path());
  const std::string label(300000, 'x');
  const auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("active set cycles between two states", R"(\"NaN\" )" + label);
  replace("\"ratio\": 1.4", "\"ratio\": NaN");
  write_text(tmp.path() / "long.json", text);
  const BenchResults r = load_bench_files({tmp.path() / "long.json"});
  EXPECT_EQ(find(r, "H_p", "F", "Q4", "ss", "LM").label, "not converged: \"NaN\" " + label);
  EXPECT_FALSE(find(r, "H_p", "F", "Q4", "ss", "PM").ratio().has_value());
}

/// One entry of a benchmarks array: Contact/H_p/M/Q4/ss/PM with the given time and extras.
std::string entry(const std::string& extra, double real_time, double ratio) {
  return R"({"name": "Contact/H_p/M/Q4/ss/PM/iterations:1/manual_time)" + extra +
         R"(", "run_name": "Contact/H_p/M/Q4/ss/PM/iterations:1/manual_time", "real_time": )" +
         std::to_string(real_time) + R"(, "time_unit": "ms", "ratio": )" + std::to_string(ratio);
}

TEST(BenchResults, RepetitionsGiveTheMedianAggregate) {
  // As Google Benchmark writes them: the repetitions, then their aggregates.
  TempDir tmp;
  write_text(tmp.path() / "reps.json",
             R"({"benchmarks": [)" + entry("", 3, 1.3) + R"(, "run_type": "iteration"}, )" +
                 entry("", 1, 1.1) + R"(, "run_type": "iteration"}, )" + entry("", 2, 1.2) +
                 R"(, "run_type": "iteration"}, )" + entry("_mean", 2.2, 1.22) +
                 R"(, "run_type": "aggregate", "aggregate_name": "mean"}, )" +
                 entry("_median", 2.5, 1.25) +
                 R"(, "run_type": "aggregate", "aggregate_name": "median"}, )" +
                 entry("_stddev", 0.8, 0.1) +
                 R"(, "run_type": "aggregate", "aggregate_name": "stddev"}]})");
  const BenchResults r = load_bench_files({tmp.path() / "reps.json"});
  ASSERT_EQ(r.rows.size(), 1u);
  EXPECT_EQ(r.rows[0].time_ms, 2.5);
  EXPECT_EQ(r.rows[0].ratio(), 1.25);
  EXPECT_EQ(r.n_replaced, 0);  // repetitions in one file are not replacements
}

TEST(BenchResults, LaterFilesReplaceTheSameCase) {
  TempDir tmp;
  std::string text = read_text(bench_path());
  const std::string time = "\"real_time\": 14.0";
  text.replace(text.find(time), time.size(), "\"real_time\": 28.0");
  write_text(tmp.path() / "again.json", text);
  const BenchResults r = load_bench_files({bench_path(), tmp.path() / "again.json"});
  EXPECT_EQ(r.sources.size(), 2u);
  EXPECT_EQ(r.rows.size(), 8u);
  EXPECT_EQ(r.n_replaced, 8);  // 7 Contact + 1 ContactAllOptions
  EXPECT_EQ(find(r, "H_p", "F", "Q4", "ss", "PM").time_ms, 28.0);
}

/// The message of the ReportError that loading `file` throws ("" if none).
std::string load_error(const fs::path& file) {
  try {
    load_bench_files({file});
  } catch (const ReportError& e) {
    return e.what();
  }
  return {};
}

TEST(BenchResults, RejectsFilesItCannotUseWithOneLineNamingTheFile) {
  TempDir tmp;
  const std::string full = read_text(bench_path());
  const auto write = [&](const std::string& name, const std::string& text) {
    write_text(tmp.path() / name, text);
    return tmp.path() / name;
  };
  const std::vector<std::pair<fs::path, std::string>> cases{
      {tmp.path() / "missing.json", "does not exist"},
      {tmp.path(), "is not a regular file"},
      {write("empty.json", ""), "is empty"},
      {write("truncated.json", full.substr(0, full.size() / 2)), "is not valid JSON"},
      // nested 100,000 deep in "context" (a copy of it overflowed the stack), a key twice
      {write("deep.json", "{\"context\": " + std::string(100000, '[') + std::string(100000, ']') +
                              ", \"benchmarks\": []}"),
       "nested beyond 64 levels"},
      {write("twice.json", R"({"benchmarks": [], "benchmarks": []})"), "a key given twice"},
      {write("array.json", "[1, 2]"), "is not a JSON object"},
      {write("results.json", read_text(testing::sample_path())), "has no 'benchmarks' array"},
      {write("other.json", R"({"benchmarks": [{"name": "BM_Assembly", "real_time": 1,
                                "time_unit": "ms"}]})"),
       "has no Contact, ContactAllOptions or ModelCases benchmark (1 of other families"},
      {write("none.json", R"({"context": {}, "benchmarks": []})"),
       "has no Contact, ContactAllOptions or ModelCases benchmark"},
      {write("indexed.json", R"({"benchmarks": [{"name":
           "Contact/problem:0/mesh:1/element:0/contact:1/algorithm:2/iterations:1/manual_time",
           "real_time": 1, "time_unit": "ms"}]})"),
       "does not name its case as Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>"},
      {write("unknown.json", R"({"benchmarks": [{"name": "Contact/H_p/C/Q4/ss/LMX",
                                  "real_time": 1, "time_unit": "ms"}]})"),
       "does not name its case as Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>"},
      {write("problem.json", R"({"benchmarks": [{"name": "Contact/H_x/C/Q4/ss/LM",
                                  "real_time": 1, "time_unit": "ms"}]})"),
       "does not name its case as Contact/<problem>/<mesh>/<element>/<contact>/<algorithm>"},
      {write("unit.json", R"({"benchmarks": [{"name": "Contact/H_p/C/Q4/ss/PM",
                               "real_time": 1, "time_unit": "min"}]})"),
       "has time_unit 'min'"},
      {write("notime.json", R"({"benchmarks": [{"name": "Contact/H_p/C/Q4/ss/PM"}]})"),
       "has no numeric 'real_time'"},
      {write("noname.json", R"({"benchmarks": [{"real_time": 1, "time_unit": "ms"}]})"),
       "entry 0 of 'benchmarks' has no 'name'"},
  };
  for (const auto& [file, cause] : cases) {
    const std::string message = load_error(file);
    EXPECT_NE(message.find("bench file '" + file.string() + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(cause), std::string::npos) << file << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace cs::reports
