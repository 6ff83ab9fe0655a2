#include "reports/bench/bench_section.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::ContactKind;

int contact_rank(ContactKind c) {
  const auto& order = bench_contacts();
  return static_cast<int>(std::find(order.begin(), order.end(), c) - order.begin());
}

/// The report's order of cases: model, then contact discretization, then algorithm.
auto case_rank(const ContactBenchmark& b) {
  return std::tuple_cat(model_order(b.model),
                        std::make_tuple(contact_rank(b.contact), static_cast<int>(b.algorithm)));
}

template <schema::Axis E>
std::string name(E v) {
  return std::string(schema::to_string(v));
}

template <schema::Axis E>
std::vector<std::string> names(const std::vector<E>& values) {
  std::vector<std::string> out;
  for (const E v : values)
    out.push_back(name(v));
  return out;
}

std::string format_ms(const std::optional<double>& ms) {
  return ms ? format_milliseconds(*ms) : std::string(kMissing);
}

std::string format_ratio(const std::optional<double>& ratio) {
  return ratio ? fmt::format("{:.2f}", *ratio) : std::string(kMissing);
}

/// "a, b and c" (or "a, b or c" with `last` = "or").
std::string join_and(const std::vector<std::string>& items, const char* last = "and") {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? fmt::format(" {} ", last) : ", ") + items[i];
  return out;
}

std::vector<const ContactBenchmark*> sorted_cases(const BenchResults& bench) {
  std::vector<const ContactBenchmark*> out;
  for (const auto& b : bench.contact)
    out.push_back(&b);
  std::stable_sort(out.begin(), out.end(),
                   [](const auto* a, const auto* b) { return case_rank(*a) < case_rank(*b); });
  return out;
}

/// The models of the Contact benchmarks, each with its cases, in the report's order.
std::vector<std::pair<BenchModel, std::vector<const ContactBenchmark*>>> by_model(
    const BenchResults& bench) {
  std::vector<std::pair<BenchModel, std::vector<const ContactBenchmark*>>> out;
  for (const ContactBenchmark* b : sorted_cases(bench)) {
    if (out.empty() || !(out.back().first == b->model))
      out.emplace_back(b->model, std::vector<const ContactBenchmark*>{});
    out.back().second.push_back(b);
  }
  return out;
}

/// A word on ratios below the physical floor of 1, when there are any.
std::string below_floor_note(const BenchResults& bench) {
  int below = 0, with_ratio = 0;
  const ContactBenchmark* lowest = nullptr;
  for (const auto& b : bench.contact) {
    if (!b.ratio)
      continue;
    ++with_ratio;
    if (*b.ratio >= 1)
      continue;
    ++below;
    if (lowest == nullptr || *b.ratio < *lowest->ratio)
      lowest = &b;
  }
  if (below == 0)
    return {};
  return fmt::format(
      "**{} of {} cases have a ratio below 1** (the lowest, {}: {} {} {}): the contact analysis "
      "was measured faster than one solve of its model. Each case is timed once, so part of "
      "this is noise (`--benchmark_repetitions=N` gives medians); below 1 on most cases of a "
      "model, it means the contact analysis's factorization (its own fill-reducing ordering, "
      "the contact DOFs last) was cheaper than the reference's.\n\n",
      below, with_ratio, format_ratio(lowest->ratio), model_md(lowest->model),
      name(lowest->contact), name(lowest->algorithm));
}

std::string intro(const BenchResults& bench) {
  std::string out = fmt::format(
      "Timings of the contact algorithms by Google Benchmark (`bench_contact_algorithms`; {} "
      "Contact and {} ContactAllOptions benchmarks). *Time* is one contact analysis: assembly, "
      "constraint rows, condensation onto the contact DOFs, the active-set iterations and the "
      "displacement recovery. *Ratio* is that time over one assembly + factorization + solve of "
      "the same model measured in the same run (the *reference*): the physical floor is 1.\n\n",
      bench.contact.size(), bench.all_options.size());
  for (const auto& source : bench.sources)
    out += machine_line(source) + "\n\n";
  out += below_floor_note(bench);
  if (bench.n_replaced > 0) {
    out += fmt::format(
        "{} cases were measured in more than one file; the later file's measurement is shown.\n\n",
        bench.n_replaced);
  }
  return out;
}

std::string target_section(const BenchResults& bench, const BenchTarget& target) {
  std::vector<std::string> problems;
  for (const auto p : target.problems)
    problems.emplace_back(schema::label(p));
  std::string out = fmt::format(
      "### Target: ratio ≤ {:g} for {} at mesh {}\n\n"
      "Issue #7's target for {}: the contact analysis costs at most {:g} × one assembly + "
      "factorization + solve. A case that did not converge misses it whatever its ratio.\n\n",
      target.max_ratio, join_and(names(target.algorithms)), name(target.mesh), join_and(problems),
      target.max_ratio);
  const TargetCheck check = check_target(bench, target);
  if (check.n_cases() == 0) {
    std::vector<schema::MeshLevel> meshes;
    for (const auto m : kMeshes) {
      const bool present = std::any_of(bench.contact.begin(), bench.contact.end(),
                                       [&](const auto& b) { return b.model.mesh == m; });
      if (present)
        meshes.push_back(m);
    }
    out += fmt::format(
        "**Not judged:** no {} case at mesh {} in the bench file{} (meshes "
        "measured: {}).",
        join_and(names(target.algorithms), "or"), name(target.mesh),
        bench.sources.size() > 1 ? "s" : "",
        meshes.empty() ? std::string("none") : join_and(names(meshes)));
    if (!meshes.empty()) {
      BenchTarget finest = target;
      finest.mesh = meshes.back();
      const TargetCheck there = check_target(bench, finest);
      if (there.n_cases() > 0) {
        out += fmt::format(
            " For orientation, at mesh {}, the finest measured, {} of {} such "
            "cases have a ratio ≤ {:g}.",
            name(finest.mesh), there.met.size(), there.n_cases(), target.max_ratio);
      }
    }
    return out + "\n\n";
  }
  if (check.missed.empty()) {
    out += fmt::format("**All {} cases meet it.**\n\n", check.n_cases());
  } else {
    out += fmt::format("**{} of {} cases meet it; {} miss it:**\n\n", check.met.size(),
                       check.n_cases(), check.missed.size());
    MarkdownTable table({"Model", "Contact", "Algorithm", "Ratio", "Time (ms)", "Note"});
    for (const ContactBenchmark* b : check.missed) {
      table.add_row({model_md(b->model), name(b->contact), name(b->algorithm),
                     format_ratio(b->ratio), format_ms(b->time_ms),
                     b->converged() ? "" : b->failure()});
    }
    out += table.render() + "\n";
  }
  if (!check.met.empty()) {
    out += "Meet it (ratio):\n\n";
    std::string line;
    for (std::size_t i = 0; i < check.met.size(); ++i) {
      const ContactBenchmark& b = *check.met[i];
      if (i == 0 || !(check.met[i - 1]->model == b.model))
        line += fmt::format("{}- {}: ", i == 0 ? "" : "\n", model_md(b.model));
      else
        line += ", ";
      line += fmt::format("{} {} {}", name(b.contact), name(b.algorithm), format_ratio(b.ratio));
    }
    out += line + "\n\n";
  }
  if (!check.not_measured.empty()) {
    out += fmt::format("Not measured at mesh {} (not judged): {}.\n\n", name(target.mesh),
                       join_and(check.not_measured));
  }
  return out;
}

std::string all_options_section(const BenchResults& bench) {
  if (bench.all_options.empty())
    return {};
  std::vector<const AllOptionsBenchmark*> rows;
  for (const auto& b : bench.all_options)
    rows.push_back(&b);
  std::stable_sort(rows.begin(), rows.end(), [](const auto* a, const auto* b) {
    return model_order(a->model) < model_order(b->model);
  });
  MarkdownTable table(
      {"Model", "Time (ms)", "Cases", "Converged", "Ratio per case", "Reference (ms)"});
  for (const AllOptionsBenchmark* b : rows) {
    const auto count = [](const std::optional<int>& n) {
      return n ? std::to_string(*n) : std::string(kMissing);
    };
    table.add_row({model_md(b->model),
                   b->error.empty() ? format_ms(b->time_ms) : "error: " + b->error, count(b->cases),
                   count(b->converged), format_ratio(b->ratio_per_case),
                   format_ms(b->reference_ms)});
  }
  return "### All options of a model on one factorization (ContactAllOptions)\n\n"
         "Every contact discretization × algorithm of one model on one shared sparse "
         "factorization, as `contact-suite run` solves a model's cases; ratio per case = time / "
         "cases / reference.\n\n" +
         table.render() + "\n";
}

/// One cell of a model table: "4.10 ms · 1.28× · 2 it." (+ " + 3 aug." for AL, " ✗" when the
/// case did not converge or stopped with an error).
std::string case_cell(const ContactBenchmark& b) {
  std::string out = b.time_ms ? format_milliseconds(*b.time_ms) + " ms" : std::string("error");
  if (b.ratio)
    out += " · " + format_ratio(b.ratio) + "×";
  if (b.active_set_iterations)
    out += fmt::format(" · {:.0f} it.", *b.active_set_iterations);
  if (b.augmentations && *b.augmentations > 0)
    out += fmt::format(" + {:.0f} aug.", *b.augmentations);
  return b.converged() ? out : out + " ✗";
}

std::string model_table(const BenchModel& model,
                        const std::vector<const ContactBenchmark*>& cases) {
  std::optional<double> reference;
  for (const ContactBenchmark* b : cases)
    reference = reference ? reference : b->reference_ms;
  std::string out =
      fmt::format("#### {} (reference {} ms)\n\n", model_md(model), format_ms(reference));
  std::vector<ContactKind> contacts;
  std::vector<BenchMethod> algorithms;
  for (const auto c : bench_contacts()) {
    if (std::any_of(cases.begin(), cases.end(), [&](const auto* b) { return b->contact == c; }))
      contacts.push_back(c);
  }
  for (const auto a : schema::values<BenchMethod>()) {
    if (std::any_of(cases.begin(), cases.end(), [&](const auto* b) { return b->algorithm == a; }))
      algorithms.push_back(a);
  }
  std::vector<std::string> header{"Algorithm"};
  for (const auto c : contacts)
    header.push_back(name(c));
  MarkdownTable table(header);
  for (const auto a : algorithms) {
    std::vector<std::string> row{name(a)};
    for (const auto c : contacts) {
      const auto it = std::find_if(cases.begin(), cases.end(), [&](const auto* b) {
        return b->contact == c && b->algorithm == a;
      });
      row.push_back(it == cases.end() ? std::string(kMissing) : case_cell(**it));
    }
    table.add_row(std::move(row));
  }
  out += table.render() + "\n";
  for (const ContactBenchmark* b : cases) {
    if (!b->converged())
      out += fmt::format("✗ {} {}: {}\n", name(b->contact), name(b->algorithm), b->failure());
  }
  return std::any_of(cases.begin(), cases.end(), [](const auto* b) { return !b->converged(); })
             ? out + "\n"
             : out;
}

std::string models_section(const BenchResults& bench) {
  if (bench.contact.empty())
    return {};
  std::string out = fmt::format(
      "### Time per model and option\n\n"
      "Each cell: the time of the contact analysis, its ratio to the model's reference (one "
      "assembly + factorization + solve) and the active-set iterations (for {}, + the "
      "augmentations); ✗ marks a case that did not converge or stopped with an error, named "
      "below its table.\n\n",
      name(BenchMethod::AL));
  for (const auto& [model, cases] : by_model(bench))
    out += model_table(model, cases);
  return out;
}

std::string figure_section(const FigureSet& figures) {
  if (figures.figures.empty() && figures.unavailable.empty())
    return {};
  std::string out = "### Time per algorithm at the finest mesh\n\n";
  if (!figures.unavailable.empty())
    return out + fmt::format("**No figure:** {}.\n\n", figures.unavailable);
  for (const Figure& f : figures.figures) {
    if (f.produced)
      out += fmt::format("![{}]({})\n\n", "benchmark times", f.file);
    else
      out += fmt::format("*(figure not drawn: {})*\n\n",
                         f.error.empty() ? "nothing to plot" : f.error);
    out += f.caption_md + "\n\n";
    for (const auto& n : f.notes)
      out += fmt::format("*Note: {}*\n\n", n);
  }
  return out;
}

}  // namespace

TargetCheck check_target(const BenchResults& bench, const BenchTarget& target) {
  TargetCheck check;
  for (const ContactBenchmark* b : sorted_cases(bench)) {
    const bool listed = std::find(target.problems.begin(), target.problems.end(),
                                  b->model.problem) != target.problems.end();
    const bool timed_algorithm = std::find(target.algorithms.begin(), target.algorithms.end(),
                                           b->algorithm) != target.algorithms.end();
    if (!listed || !timed_algorithm || b->model.mesh != target.mesh)
      continue;
    const bool meets = b->converged() && b->ratio && *b->ratio <= target.max_ratio;
    (meets ? check.met : check.missed).push_back(b);
  }
  // The worst first: the largest ratio, then those without one.
  std::stable_sort(check.missed.begin(), check.missed.end(), [](const auto* a, const auto* b) {
    return a->ratio.value_or(-1) > b->ratio.value_or(-1);
  });
  for (const auto problem : target.problems) {
    for (const auto element : schema::values<schema::Element>()) {
      const BenchModel model{problem, target.mesh, element};
      const bool measured = std::any_of(bench.contact.begin(), bench.contact.end(),
                                        [&](const auto& b) { return b.model == model; });
      if (!measured) {
        check.not_measured.push_back(
            fmt::format("{} {}", schema::label(problem), schema::to_string(element)));
      }
    }
  }
  return check;
}

std::string machine_line(const BenchSource& source) {
  const BenchContext& c = source.context;
  std::vector<std::string> parts;
  if (!c.host_name.empty())
    parts.push_back(fmt::format("host `{}`", c.host_name));
  if (c.num_cpus) {
    parts.push_back(c.mhz_per_cpu
                        ? fmt::format("{} CPUs at {:.0f} MHz", *c.num_cpus, *c.mhz_per_cpu)
                        : fmt::format("{} CPUs", *c.num_cpus));
  }
  if (!c.load_avg.empty()) {
    std::string loads;
    for (double l : c.load_avg)
      loads += fmt::format("{}{:.2f}", loads.empty() ? "" : " / ", l);
    parts.push_back(fmt::format("load average {} when the run began", loads));
  }
  if (!c.library_build_type.empty())
    parts.push_back(
        fmt::format("Google Benchmark library built as {} (the library's own build, "
                    "not the timed code's)",
                    c.library_build_type));
  if (!c.executable.empty())
    parts.push_back(fmt::format("program `{}`", c.executable));
  if (!c.date.empty())
    parts.push_back(fmt::format("run {}", c.date));
  std::string out = fmt::format("**Machine** (`{}`): {}.", source.file,
                                parts.empty() ? std::string("the file does not say (no `context`)")
                                              : fmt::format("{}", fmt::join(parts, ", ")));
  if (c.cpu_scaling_enabled && *c.cpu_scaling_enabled)
    out += " CPU frequency scaling was on: times may vary from run to run.";
  if (source.n_other > 0)
    out += fmt::format(" {} benchmarks of other families left out.", source.n_other);
  return out;
}

std::string bench_section(const BenchResults& bench, const FigureSet& figures,
                          const BenchTarget& target) {
  return "## Benchmarks\n\n" + intro(bench) + target_section(bench, target) +
         figure_section(figures) + all_options_section(bench) + models_section(bench);
}

}  // namespace cs::reports
