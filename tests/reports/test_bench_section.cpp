// Section 7 of the report, "Benchmarks": the target of issue #7 judged case by case (a ratio
// of 1.6 at mesh F misses it, 1.4 meets it, a case that did not converge misses it, MPC and the
// coarser meshes are not judged), the machine line computed from the file's context, the tables
// per model, and the section in report.md only when a bench file is given; a bad bench file
// leaves the output directory untouched.
//
// Data: data/small_bench.json (see test_bench_results.cpp for what it holds).

#include <algorithm>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/bench/bench_results.hpp"
#include "reports/bench/bench_section.hpp"
#include "reports/figures/bench_figure.hpp"
#include "reports/figures/gnuplot.hpp"
#include "reports/report_error.hpp"
#include "reports/report_writer.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::reports::test_bench_section {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::TempDir;
using testing::write_text;

fs::path bench_path() {
  return testing::source_dir() / "tests" / "reports" / "data" / "small_bench.json";
}

const BenchResults& sample() {
  static const BenchResults r = load_bench_files({bench_path()});
  return r;
}

/// "H_p/F/Q4/ss/AL" of each case, in order.
std::vector<std::string> names(const std::vector<const BenchRow*>& cases) {
  std::vector<std::string> out;
  for (const auto* b : cases) {
    out.push_back(fmt::format("{}/{}/{}/{}/{}", schema::to_string(b->model.problem),
                              schema::to_string(b->model.mesh), schema::to_string(b->model.element),
                              schema::to_string(b->contact), schema::to_string(b->algorithm)));
  }
  return out;
}

/// The text of `md` from the line starting with `from` up to the next line starting with `to`.
std::string between(const std::string& md, const std::string& from, const std::string& to) {
  const auto start = md.find(from);
  if (start == std::string::npos)
    return {};
  const auto end = md.find("\n" + to, start);
  return md.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

TEST(BenchTarget, JudgesTheTimedAlgorithmsAtMeshFOnly) {
  const TargetCheck check = check_target(sample());
  // Met: converged with ratio <= 1.5. Missed, worst first: AL 1.6, LM 1.2 but not converged,
  // ns PM without a ratio (an error). MPC (3.0) and the C mesh (AL 1.9) are not judged.
  EXPECT_EQ(names(check.met),
            (std::vector<std::string>{"Pprime_p/F/Q8/mortar/LM", "H_p/F/Q4/ss/PM"}));
  EXPECT_EQ(names(check.missed),
            (std::vector<std::string>{"H_p/F/Q4/ss/AL", "H_p/F/Q4/ss/LM", "H_p/F/Q4/ns/PM"}));
  EXPECT_EQ(check.n_cases(), 5);
  EXPECT_EQ(check.not_measured, (std::vector<std::string>{"H<sub>p</sub> Q8", "S(1/7) Q4",
                                                          "S(1/7) Q8", "P′<sub>p</sub> Q4"}));
}

TEST(BenchTarget, FollowsTheTargetItIsGiven) {
  BenchTarget strict;
  strict.max_ratio = 1.3;
  EXPECT_EQ(names(check_target(sample(), strict).met),
            (std::vector<std::string>{"Pprime_p/F/Q8/mortar/LM"}));
  BenchTarget coarse;
  coarse.mesh = schema::MeshLevel::C;
  EXPECT_EQ(names(check_target(sample(), coarse).missed),
            (std::vector<std::string>{"H_p/C/Q4/ss/AL"}));
}

TEST(BenchSection, ListsTheMissesWithTheirRatioAndNotTheCasesThatMeetTheTarget) {
  const std::string md = bench_section(sample(), {});
  EXPECT_EQ(md.rfind("## Benchmarks\n", 0), 0u);
  EXPECT_NE(md.find("### Target: ratio ≤ 1.5 for PM, AL and LM at mesh F"), std::string::npos);
  EXPECT_NE(md.find("**2 of 5 cases meet it; 3 miss it:**"), std::string::npos) << md;
  const std::string misses = between(md, "**2 of 5", "Meet it");
  EXPECT_NE(misses.find("| H<sub>p</sub>, mesh F, Q4 | ss | AL | 1.60 | 16.0 |"), std::string::npos)
      << misses;
  EXPECT_NE(misses.find("| ss | LM | 1.20 | 12.0 | not converged: active set cycles"),
            std::string::npos)
      << misses;
  EXPECT_NE(misses.find("| ns | PM | — | — | error: reference factorization failed |"),
            std::string::npos)
      << misses;
  EXPECT_EQ(misses.find("1.40"), std::string::npos) << misses;  // ss PM meets it
  EXPECT_EQ(misses.find("MPC"), std::string::npos) << misses;   // not a target algorithm
  EXPECT_EQ(misses.find("1.90"), std::string::npos) << misses;  // mesh C: not judged
  const std::string met = between(md, "Meet it", "Not measured");
  EXPECT_NE(met.find("- H<sub>p</sub>, mesh F, Q4: ss PM 1.40"), std::string::npos) << met;
  EXPECT_NE(met.find("- P′<sub>p</sub>, mesh F, Q8: mortar LM 1.10"), std::string::npos) << met;
  EXPECT_NE(md.find("Not measured at mesh F (not judged): H<sub>p</sub> Q8, S(1/7) Q4, "
                    "S(1/7) Q8 and P′<sub>p</sub> Q4."),
            std::string::npos);
}

TEST(BenchSection, MachineLineComesFromTheContext) {
  EXPECT_NE(bench_section(sample(), {})
                .find("\n**Machine** (`" + bench_path().string() +
                      "`): host `bench-host`, 2 CPUs at 2800 MHz, load average 0.50 / 0.25 / "
                      "0.12 when the run began, Google Benchmark library built as release (the "
                      "library's own build, not the timed code's), program "
                      "`build/bench/bench_contact_algorithms`, run 2024-05-01T10:00:00+00:00. 1 "
                      "benchmarks of other families left out.\n"),
            std::string::npos);
  BenchResults bare;
  bare.sources.push_back({"x.json", {}, 0});
  EXPECT_NE(bench_section(bare, {}).find(
                "\n**Machine** (`x.json`): the file does not say (no `context`).\n"),
            std::string::npos);
  bare.sources[0].context.cpu_scaling_enabled = true;
  EXPECT_NE(bench_section(bare, {}).find("CPU frequency scaling was on"), std::string::npos);
}

TEST(BenchSection, OneTablePerModelWithEveryCaseAndWhyItFailed) {
  const std::string md = bench_section(sample(), {});
  const std::string f = between(md, "#### H<sub>p</sub>, mesh F, Q4", "####");
  EXPECT_NE(f.find("(reference 10.0 ms)"), std::string::npos) << f;
  EXPECT_NE(f.find("| Algorithm | ns | ss |"), std::string::npos) << f;
  EXPECT_NE(f.find("| AL | — | 16.0 ms · 1.60× · 5 it. + 3 aug. |"), std::string::npos) << f;
  EXPECT_NE(f.find("| LM | — | 12.0 ms · 1.20× · 50 it. ✗ |"), std::string::npos) << f;
  EXPECT_NE(f.find("| PM | error ✗ | 14.0 ms · 1.40× · 2 it. |"), std::string::npos) << f;
  EXPECT_NE(f.find("✗ ss LM: not converged: active set cycles between two states"),
            std::string::npos);
  EXPECT_NE(f.find("✗ ns PM: error: reference factorization failed"), std::string::npos);
  // Models in the study's order: P'_p before H_p; C before F.
  const auto pprime = md.find("#### P′<sub>p</sub>, mesh F, Q8");
  const auto hc = md.find("#### H<sub>p</sub>, mesh C, Q4");
  const auto hf = md.find("#### H<sub>p</sub>, mesh F, Q4");
  EXPECT_LT(pprime, hc);
  EXPECT_LT(hc, hf);
  EXPECT_NE(md.find("| H<sub>p</sub>, mesh F, Q4 | 108 | 12 | 11 | 0.90 | 10.0 |"),
            std::string::npos);
}

TEST(BenchSection, ALabelCannotBreakATable) {
  BenchResults r = sample();
  for (auto& b : r.rows) {
    if (!b.label.empty())
      b.label = "not converged: a | b\nc";
  }
  EXPECT_NE(bench_section(r, {}).find("| ss | LM | 1.20 | 12.0 | not converged: a \\| b c |\n"),
            std::string::npos);
}

TEST(BenchSection, WithoutMeshFTheTargetIsNotJudged) {
  BenchResults coarse = sample();
  std::erase_if(coarse.rows, [](const auto& b) {
    return b.family == BenchFamily::Contact && b.model.mesh == schema::MeshLevel::F;
  });
  const std::string md = bench_section(coarse, {});
  EXPECT_NE(md.find("**Not judged:** no PM, AL or LM case at mesh F in the bench file (meshes "
                    "measured: C). For orientation, at mesh C, the finest measured, 0 of 1 such "
                    "cases have a ratio ≤ 1.5."),
            std::string::npos)
      << md;
}

TEST(BenchSection, RatiosBelowThePhysicalFloorAreFlagged) {
  EXPECT_EQ(bench_section(sample(), {}).find("below 1"), std::string::npos);
  BenchResults low = sample();
  for (auto& b : low.rows) {
    if (b.family == BenchFamily::Contact && b.model.mesh == schema::MeshLevel::C)
      b.counters["ratio"] = 0.8;
  }
  EXPECT_NE(bench_section(low, {}).find("**1 of 6 cases have a ratio below 1** (the lowest, "
                                        "0.80: H<sub>p</sub>, mesh C, Q4 ss AL)"),
            std::string::npos);
  // Ratios that print alike are a tie: every one is named.
  for (BenchRow& b : low.rows) {
    if (b.model.mesh == schema::MeshLevel::F && b.contact == schema::ContactKind::ss &&
        b.algorithm == BenchMethod::PM)
      b.counters["ratio"] = 0.803;
  }
  const std::string md = bench_section(low, {});
  EXPECT_NE(md.find("**2 of 6 cases have a ratio below 1** (the lowest, 0.80: "), std::string::npos)
      << md;
  EXPECT_NE(md.find("Q4 ss AL; H<sub>p</sub>, mesh F, Q4 ss PM)"), std::string::npos) << md;
  // Within 0.005 but printed otherwise (0.8049 and 0.806 read 0.80 and 0.81): not a tie.
  for (BenchRow& b : low.rows) {
    if (b.family == BenchFamily::Contact && b.model.mesh == schema::MeshLevel::C)
      b.counters["ratio"] = 0.8049;
    else if (b.counters.contains("ratio") && b.counters.at("ratio") == 0.803)
      b.counters["ratio"] = 0.806;
  }
  const std::string apart = bench_section(low, {});
  EXPECT_NE(apart.find("(the lowest, 0.80: H<sub>p</sub>, mesh C, Q4 ss AL)"), std::string::npos)
      << apart;
}

const schema::ResultsDocument& results() {
  static const schema::ResultsDocument doc = schema::read_results_file(testing::sample_path());
  return doc;
}

ReportOptions options_with_bench(const fs::path& out, std::vector<fs::path> bench) {
  ReportOptions o;
  o.out_dir = out;
  o.study_data = testing::study_dir();
  o.figures = false;
  o.bench = std::move(bench);
  return o;
}

TEST(BenchSection, InTheReportOnlyWithABenchFile) {
  TempDir tmp;
  write_report(results(), options_with_bench(tmp.path() / "plain", {}));
  const std::string plain = read_text(tmp.path() / "plain" / "report.md");
  EXPECT_EQ(plain.find("[Benchmarks]"), std::string::npos);
  EXPECT_NE(plain.find("- *Benchmarks*: no benchmark file was given"), std::string::npos);
  write_report(results(), options_with_bench(tmp.path() / "bench", {bench_path()}));
  const std::string md = read_text(tmp.path() / "bench" / "report.md");
  EXPECT_NE(md.find("[Benchmarks](appendix-benchmarks.md)"), std::string::npos);
  const std::string page = read_text(tmp.path() / "bench" / "appendix-benchmarks.md");
  EXPECT_EQ(page.rfind("# Benchmarks\n", 0), 0u);
  EXPECT_NE(page.find("**2 of 5 cases meet it"), std::string::npos);
}

TEST(BenchSection, ABadBenchFileLeavesTheOutputDirectoryUntouched) {
  TempDir tmp;
  const fs::path out = tmp.path() / "out";
  fs::create_directories(out);
  write_text(out / "report.md", "the user's previous report\n");
  write_text(tmp.path() / "bad.json", R"({"benchmarks": [)");
  EXPECT_THROW(
      write_report(results(), options_with_bench(out, {bench_path(), tmp.path() / "bad.json"})),
      ReportError);
  EXPECT_EQ(read_text(out / "report.md"), "the user's previous report\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 1);
  // A directory that did not exist is not created.
  EXPECT_THROW(
      write_report(results(), options_with_bench(tmp.path() / "new", {tmp.path() / "nope.json"})),
      ReportError);
  EXPECT_FALSE(fs::exists(tmp.path() / "new"));
}

bool is_png(const fs::path& p) {
  const std::string bytes = read_text(p);
  return bytes.size() > 1000 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

TEST(BenchFigure, DrawsOnePngOfTheFinestMeshes) {
  if (!find_gnuplot())
    GTEST_SKIP() << "gnuplot with a PNG terminal is not installed";
  TempDir tmp;
  const FigureSet set = render_bench_figures(sample(), tmp.path());
  EXPECT_TRUE(set.unavailable.empty());
  ASSERT_EQ(set.figures.size(), 1u);
  const Figure& f = set.figures[0];
  EXPECT_TRUE(f.produced) << f.error;
  EXPECT_TRUE(is_png(tmp.path() / f.file));
  // H_p Q4 at F (its finest), P'_p Q8 at F; the C mesh of H_p Q4 is not drawn.
  EXPECT_NE(f.caption_md.find("P′<sub>p</sub>, mesh F, Q8; H<sub>p</sub>, mesh F, Q4"),
            std::string::npos)
      << f.caption_md;
  EXPECT_NE(f.caption_md.find("marked * is of a case that did not converge"), std::string::npos);
  const std::string md = bench_section(sample(), set);
  EXPECT_NE(md.find("![benchmark times](figures/bench_time.png)"), std::string::npos);
}

TEST(BenchFigure, WithoutGnuplotTheSectionSaysSo) {
  TempDir tmp;
  FigureOptions options;
  options.gnuplot_program = "/nonexistent/gnuplot";
  const FigureSet set = render_bench_figures(sample(), tmp.path(), {}, options);
  EXPECT_FALSE(set.unavailable.empty());
  EXPECT_FALSE(fs::exists(tmp.path() / "figures"));
  const std::string md = bench_section(sample(), set);
  EXPECT_NE(md.find("**No figure:** `/nonexistent/gnuplot` with a PNG terminal was not found"),
            std::string::npos)
      << md;
}

// Requirement: the ModelCases table shows each model's numbers as the JSON gives them (the median
// aggregate of repeated runs, the counters one_case_s in ms, ratio, ratio_cpu, blas_threads), and
// the count of models within issue #27's 1.3 in wall and in CPU time. Data:
// data/small_model_cases.json (invented, consistent: ratio = time / one_case_s): S(1/7) F Q8 in
// three runs of 1500, 1200 and 1300 ms (median 1300 ms, ratio 1.3, 1.25 in CPU time), H_p F Q8
// once, 29 of 30 converged, ratio 2.0 (1.2 in CPU time) on 2 BLAS threads.
TEST(BenchSection, ModelCasesTableShowsTheNumbersOfTheFile) {
  const BenchResults r =
      load_bench_files({testing::source_dir() / "tests/reports/data/small_model_cases.json"});
  ASSERT_EQ(r.of(BenchFamily::ModelCases).size(), 2u);
  EXPECT_TRUE(r.of(BenchFamily::Contact).empty());
  const std::string md = bench_section(r, {});
  EXPECT_NE(md.find("| Model | Cases converged | Time of the cases (ms) | One analysis (ms) | "
                    "Ratio (wall) | Ratio (CPU) | BLAS threads |"),
            std::string::npos)
      << md;
  const auto hp = md.find("| H<sub>p</sub>, mesh F, Q8 | 29 of 30 | 500 | 250 | 2.00 | 1.20 | 2 |");
  const auto s17 = md.find("| S(1/7), mesh F, Q8 | 30 of 30 | 1300 | 1000 | 1.30 | 1.25 | 1 |");
  EXPECT_NE(hp, std::string::npos) << md;
  EXPECT_NE(s17, std::string::npos) << md;
  EXPECT_LT(hp, s17);  // the battery's problem order
  // The stddev aggregate's spreads stay on the repeated case's row (claim 7 reads them).
  for (const BenchRow* b : r.of(BenchFamily::ModelCases)) {
    const bool repeated = b->model.problem == schema::ProblemId::S_1_7;
    EXPECT_EQ(b->time_stddev_ms.has_value(), repeated);
    if (repeated) {
      EXPECT_DOUBLE_EQ(*b->time_stddev_ms, 152.8);
      EXPECT_DOUBLE_EQ(b->counter_stddev.at("ratio"), 0.15);
    }
  }
  EXPECT_NE(md.find("at most 1.3 × one analysis"), std::string::npos);
  EXPECT_NE(md.find("**1 of 2 models meet it in wall time, 2 in CPU time.**"), std::string::npos);
  EXPECT_EQ(md.find("below 1, under the physical floor"), std::string::npos);
  // A wall-time ratio below 1 (load that changed between the two measurements) is named.
  BenchResults loaded = r;
  for (auto& b : loaded.rows) {
    if (b.model.problem == schema::ProblemId::S_1_7)
      b.counters["ratio"] = 0.4;
  }
  EXPECT_NE(
      bench_section(loaded, {})
          .find("**0 of 2 models meet it in wall time, 2 in CPU "
                "time.** Models with a wall-time ratio below 1, under the physical floor: 1."),
      std::string::npos);
  // Without ModelCases benchmarks there is no such table.
  EXPECT_EQ(bench_section(sample(), {}).find("ModelCases"), std::string::npos);
}

}  // namespace
}  // namespace cs::reports::test_bench_section

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::reports::test_bench_section {
namespace {

/// A Google Benchmark entry of Contact/H_p/F/Q4/<contact>/PM with `ratio`, or its aggregate.
nlohmann::json contact_entry(const std::string& contact, double ratio,
                             const std::string& aggregate = "") {
  const std::string run = "Contact/H_p/F/Q4/" + contact + "/PM/iterations:1/manual_time";
  nlohmann::json e{{"name", aggregate.empty() ? run : run + "_" + aggregate},
                   {"run_name", run},
                   {"run_type", aggregate.empty() ? "iteration" : "aggregate"},
                   {"real_time", 10.0 * ratio},
                   {"time_unit", "ms"},
                   {"active_set_iterations", 5},
                   {"ratio", ratio},
                   {"reference_s", 0.01}};
  if (!aggregate.empty())
    e["aggregate_name"] = aggregate;
  return e;
}

// Requirement: a case measured in several files meets or misses the target only when every
// measurement agrees (ss: 1.6 once, then 1.3: measured on both sides); a median within one
// standard deviation of the target ties with it (ns: 1.48 ± 0.17); the count of cases measured
// twice counts cases, not measurements.
TEST(BenchTarget, EveryMeasurementAndTheNoiseCount) {
  TempDir dir;
  const auto file = [&](const std::string& name, nlohmann::json entries) {
    write_text(dir.path() / name, nlohmann::json{{"benchmarks", entries}}.dump());
    return dir.path() / name;
  };
  // mortar: 1.55 ± 0.1 (a tie) in the first file, 1.25 in the second: a tie, not both sides.
  const auto first = file("first.json", {contact_entry("ss", 1.6), contact_entry("mortar", 1.55),
                                         contact_entry("mortar", 1.55, "median"),
                                         contact_entry("mortar", 0.1, "stddev")});
  const auto second =
      file("second.json",
           {contact_entry("ss", 1.3), contact_entry("ns", 1.5), contact_entry("ns", 1.48, "median"),
            contact_entry("ns", 0.17, "stddev"), contact_entry("mortar", 1.25)});
  const BenchResults bench = load_bench_files({first, second});
  EXPECT_EQ(bench.n_replaced, 2);  // ss and mortar
  const TargetCheck check = check_target(bench);
  EXPECT_EQ(names(check.split), (std::vector<std::string>{"H_p/F/Q4/ss/PM"}));
  EXPECT_EQ(names(check.tied), (std::vector<std::string>{"H_p/F/Q4/ns/PM", "H_p/F/Q4/mortar/PM"}));
  EXPECT_TRUE(check.met.empty());
  const std::string md = bench_section(bench, {});
  EXPECT_NE(md.find("1 are measured on both sides of it:** H<sub>p</sub>, mesh F, Q4 ss PM 1.30 "
                    "(earlier: 1.60);"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("1.48 ± 0.17"), std::string::npos) << md;
}

// Requirement: where a model's reference differs between files by more than 10 % (one assembly
// + factorization + solve, measured once per file: 15.0 and 20.6 ms for H_p F Q4 in the
// committed files), the page says so beside the ratios below 1, since a ratio moves with it.
TEST(BenchTarget, ReferencesThatDifferBetweenFilesAreNamed) {
  TempDir dir;
  const auto file = [&](const std::string& name, double reference_s, double ratio) {
    auto e = contact_entry("ss", ratio);
    e["reference_s"] = reference_s;
    write_text(dir.path() / name, nlohmann::json{{"benchmarks", {e}}}.dump());
    return dir.path() / name;
  };
  const BenchResults wide =
      load_bench_files({file("a.json", 0.0150, 1.35), file("b.json", 0.0206, 0.98)});
  const std::string md = bench_section(wide, {});
  EXPECT_NE(md.find("it differs between the files by more than 10 % on H<sub>p</sub>, mesh F, "
                    "Q4: 15 to 20.6 ms"),
            std::string::npos)
      << md;
  const BenchResults close =
      load_bench_files({file("c.json", 0.0150, 0.99), file("d.json", 0.0155, 0.98)});
  EXPECT_NE(bench_section(close, {}).find("it differs between the files by at most 10 % here"),
            std::string::npos);
}

// Requirement: benchmarks whose cases took another number of active-set iterations than the
// same cases of the results are said not to time the analyses of the results (another build, or
// other contact settings: the benchmarks once ran the solver's defaults, not the problem's FKN).
TEST(BenchTarget, SaysWhenTheTimingsAreNotOfTheResultsAnalyses) {
  TempDir dir;
  write_text(
      dir.path() / "b.json",
      nlohmann::json{{"benchmarks", {contact_entry("ss", 1.2), contact_entry("ns", 1.2)}}}.dump());
  const BenchResults bench = load_bench_files({dir.path() / "b.json"});
  schema::ResultsDocument doc;
  for (const auto contact : {schema::ContactKind::ss, schema::ContactKind::ns}) {
    schema::CaseResult c;
    c.spec = {.problem = schema::ProblemId::H_p,
              .mesh = schema::MeshLevel::F,
              .element = schema::Element::Q4,
              .algorithm = schema::Algorithm::PM,
              .contact = contact};
    c.iterations = contact == schema::ContactKind::ss ? 5 : 9;  // the benchmarks took 5
    doc.cases.push_back(c);
  }
  const ResultsIndex index(doc);
  const BenchProvenance p = bench_provenance(bench, index);
  EXPECT_EQ(p.compared, 2);
  EXPECT_EQ(p.differing, 1);
  const std::string md = bench_section(bench, {}, {}, &index);
  EXPECT_NE(md.find("of 2 benchmarked cases that are also cases of the results, 1 took another "
                    "number of active-set iterations (the first: H<sub>p</sub> F Q4 ns PM: 5 "
                    "iterations benchmarked, 9 in the results): another build of the solver, or "
                    "other contact settings, timed them."),
            std::string::npos)
      << md;
}

}  // namespace
}  // namespace cs::reports::test_bench_section
