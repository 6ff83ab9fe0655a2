#include "reports/bench/bench_section.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/render/template_text.hpp"
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
auto case_rank(const BenchRow& b) {
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

/// `rows` in the report's order of cases (of models, for the families without options).
std::vector<const BenchRow*> sorted_cases(const std::vector<BenchRow>& rows) {
  std::vector<const BenchRow*> out;
  for (const auto& b : rows)
    out.push_back(&b);
  std::stable_sort(out.begin(), out.end(),
                   [](const auto* a, const auto* b) { return case_rank(*a) < case_rank(*b); });
  return out;
}

/// The models of the Contact benchmarks, each with its cases, in the report's order.
std::vector<std::pair<BenchModel, std::vector<const BenchRow*>>> by_model(
    const BenchResults& bench) {
  std::vector<std::pair<BenchModel, std::vector<const BenchRow*>>> out;
  for (const BenchRow* b : sorted_cases(bench.contact)) {
    if (out.empty() || !(out.back().first == b->model))
      out.emplace_back(b->model, std::vector<const BenchRow*>{});
    out.back().second.push_back(b);
  }
  return out;
}

/// The cases with a ratio below the physical floor of 1, and the lowest of them.
TemplateData below_floor(const BenchResults& bench) {
  int below = 0, with_ratio = 0;
  const BenchRow* lowest = nullptr;
  for (const auto& b : bench.contact) {
    with_ratio += b.ratio() ? 1 : 0;
    if (!b.ratio() || *b.ratio() >= 1)
      continue;
    ++below;
    if (lowest == nullptr || *b.ratio() < *lowest->ratio())
      lowest = &b;
  }
  if (below == 0)
    return TemplateData(false);
  TemplateData d;
  d.set("below", std::to_string(below));
  d.set("with_ratio", std::to_string(with_ratio));
  d.set("lowest",
        fmt::format("{}: {} {} {}", format_ratio(lowest->ratio()), model_md(lowest->model),
                    name(lowest->contact), name(lowest->algorithm)));
  return d;
}

/// The target's verdict when no case was measured at its mesh: the meshes that were, and the
/// finest one's count for orientation.
TemplateData not_judged(const BenchResults& bench, const BenchTarget& target) {
  std::vector<schema::MeshLevel> meshes;
  for (const auto m : kMeshes) {
    if (std::any_of(bench.contact.begin(), bench.contact.end(),
                    [&](const auto& b) { return b.model.mesh == m; }))
      meshes.push_back(m);
  }
  TemplateData d;
  d.set("files", bench.sources.size() > 1 ? "s" : "");
  d.set("meshes", meshes.empty() ? std::string("none") : join_words(names(meshes)));
  d.set("finest", TemplateData(false));
  if (!meshes.empty()) {
    BenchTarget finest = target;
    finest.mesh = meshes.back();
    const TargetCheck there = check_target(bench, finest);
    if (there.n_cases() > 0) {
      TemplateData f;
      f.set("mesh", name(finest.mesh));
      f.set("met", std::to_string(there.met.size()));
      f.set("cases", std::to_string(there.n_cases()));
      d.set("finest", f);
    }
  }
  return d;
}

TemplateData target_data(const BenchResults& bench, const BenchTarget& target) {
  std::vector<std::string> problems;
  for (const auto p : target.problems)
    problems.emplace_back(schema::label(p));
  TemplateData d;
  d.set("max_ratio", fmt::format("{:g}", target.max_ratio));
  d.set("algorithms", join_words(names(target.algorithms)));
  d.set("algorithms_or", join_words(names(target.algorithms), " or "));
  d.set("mesh", name(target.mesh));
  d.set("problems", join_words(problems));
  const TargetCheck check = check_target(bench, target);
  d.set("judged", check.n_cases() > 0);
  d.set("not_judged", check.n_cases() > 0 ? TemplateData(false) : not_judged(bench, target));
  d.set("cases", std::to_string(check.n_cases()));
  d.set("met", std::to_string(check.met.size()));
  d.set("n_missed", text_or_false(check.missed.empty() ? "" : std::to_string(check.missed.size())));
  MarkdownTable missed({"Model", "Contact", "Algorithm", "Ratio", "Time (ms)", "Note"});
  for (const BenchRow* b : check.missed) {
    missed.add_row({model_md(b->model), name(b->contact), name(b->algorithm),
                    format_ratio(b->ratio()), format_ms(b->time_ms),
                    b->converged() ? "" : b->failure()});
  }
  d.set("missed", missed.render());
  std::vector<std::pair<std::string, std::string>> met;  // model, "ss PM 1.40, ..."
  for (const BenchRow* b : check.met) {
    const std::string item =
        fmt::format("{} {} {}", name(b->contact), name(b->algorithm), format_ratio(b->ratio()));
    if (met.empty() || met.back().first != model_md(b->model))
      met.emplace_back(model_md(b->model), item);
    else
      met.back().second += ", " + item;
  }
  d.set("has_met", !met.empty());
  d.set("met_models", template_list(met, [](const auto& m) {
          TemplateData e;
          e.set("model", m.first);
          e.set("items", m.second);
          return e;
        }));
  d.set("not_measured", text_or_false(join_words(check.not_measured)));
  return d;
}

/// A column of a table with one row per model: its header and its cell of a row.
struct ModelColumn {
  const char* header;
  std::function<std::string(const BenchRow&)> cell;
};

std::string count_cell(const std::optional<int>& n) {
  return n ? std::to_string(*n) : std::string(kMissing);
}

/// One row per benchmark of `rows`, in the report's order of models.
std::string model_table(const std::vector<BenchRow>& rows,
                        const std::vector<ModelColumn>& columns) {
  std::vector<std::string> header{"Model"};
  for (const auto& c : columns)
    header.emplace_back(c.header);
  MarkdownTable table(header);
  for (const BenchRow* b : sorted_cases(rows)) {
    std::vector<std::string> row{model_md(b->model)};
    for (const auto& c : columns)
      row.push_back(c.cell(*b));
    table.add_row(std::move(row));
  }
  return table.render();
}

std::string all_options_table(const BenchResults& bench) {
  return model_table(
      bench.all_options,
      {{"Time (ms)",
        [](const BenchRow& b) {
          return b.error.empty() ? format_ms(b.time_ms) : "error: " + b.error;
        }},
       {"Cases", [](const BenchRow& b) { return count_cell(b.count("cases")); }},
       {"Converged", [](const BenchRow& b) { return count_cell(b.count("converged")); }},
       {"Ratio per case",
        [](const BenchRow& b) { return format_ratio(b.counter("ratio_per_case")); }},
       {"Reference (ms)", [](const BenchRow& b) { return format_ms(b.reference_ms()); }}});
}

/// The ModelCases benchmarks: a model's full set of cases against one analysis of it, in wall
/// and process CPU time, checked against `max_ratio` (issue #27). A wall-time ratio below the
/// physical floor of 1 (the load changed between the two measurements) does not count as met.
TemplateData model_cases_data(const BenchResults& bench, double max_ratio) {
  if (bench.model_cases.empty())
    return TemplateData(false);
  const auto converged = [](const BenchRow& b) {
    const auto n = b.count("converged"), cases = b.count("cases");
    return b.error.empty() ? fmt::format("{} of {}", count_cell(n), count_cell(cases))
                           : "error: " + b.error;
  };
  int wall = 0, cpu = 0, below_one = 0;
  for (const auto& b : bench.model_cases) {
    below_one += b.ratio() && *b.ratio() < 1 ? 1 : 0;
    wall += b.ratio() && *b.ratio() >= 1 && *b.ratio() <= max_ratio ? 1 : 0;
    cpu += b.counter("ratio_cpu") && *b.counter("ratio_cpu") <= max_ratio ? 1 : 0;
  }
  TemplateData d;
  d.set("max_ratio", fmt::format("{:g}", max_ratio));
  d.set("models", std::to_string(bench.model_cases.size()));
  d.set("met_wall", std::to_string(wall));
  d.set("met_cpu", std::to_string(cpu));
  d.set("below_one", text_or_false(below_one > 0 ? std::to_string(below_one) : ""));
  d.set(
      "table",
      model_table(
          bench.model_cases,
          {{"Cases converged", converged},
           {"Time of the cases (ms)", [](const BenchRow& b) { return format_ms(b.time_ms); }},
           {"One analysis (ms)",
            [](const BenchRow& b) { return format_ms(b.counter_ms("one_case_s")); }},
           {"Ratio (wall)", [](const BenchRow& b) { return format_ratio(b.ratio()); }},
           {"Ratio (CPU)", [](const BenchRow& b) { return format_ratio(b.counter("ratio_cpu")); }},
           {"BLAS threads",
            [](const BenchRow& b) { return count_cell(b.count("blas_threads")); }}}));
  return d;
}

/// One cell of a model table: "4.10 ms · 1.28× · 2 it." (+ " + 3 aug." for AL, " ✗" when the
/// case did not converge or stopped with an error).
std::string case_cell(const BenchRow& b) {
  std::string out = b.time_ms ? format_milliseconds(*b.time_ms) + " ms" : std::string("error");
  if (b.ratio())
    out += " · " + format_ratio(b.ratio()) + "×";
  if (const auto iterations = b.counter("active_set_iterations"))
    out += fmt::format(" · {:.0f} it.", *iterations);
  if (const auto augmentations = b.counter("augmentations"); augmentations && *augmentations > 0)
    out += fmt::format(" + {:.0f} aug.", *augmentations);
  return b.converged() ? out : out + " ✗";
}

TemplateData model_data(const BenchModel& model, const std::vector<const BenchRow*>& cases) {
  std::optional<double> reference;
  for (const BenchRow* b : cases)
    reference = reference ? reference : b->reference_ms();
  const auto [contacts, algorithms] = options_of(cases);
  MarkdownTable table([&] {
    std::vector<std::string> header{"Algorithm"};
    for (const auto c : contacts)
      header.push_back(name(c));
    return header;
  }());
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
  std::vector<std::string> failures;
  for (const BenchRow* b : cases) {
    if (!b->converged())
      failures.push_back(
          fmt::format("✗ {} {}: {}", name(b->contact), name(b->algorithm), b->failure()));
  }
  TemplateData d;
  d.set("model", model_md(model));
  d.set("reference", format_ms(reference));
  d.set("table", table.render());
  d.set("has_failures", !failures.empty());
  d.set("failures", template_list(failures, [](const std::string& f) { return TemplateData(f); }));
  return d;
}

TemplateData figure_set_data(const FigureSet& figures) {
  if (figures.figures.empty() && figures.unavailable.empty())
    return TemplateData(false);
  TemplateData d;
  d.set("unavailable", text_or_false(figures.unavailable));
  d.set("list", template_list(figures.figures, [](const Figure& f) { return figure_data(f); }));
  return d;
}

}  // namespace

TargetCheck check_target(const BenchResults& bench, const BenchTarget& target) {
  TargetCheck check;
  for (const BenchRow* b : sorted_cases(bench.contact)) {
    const bool listed = std::find(target.problems.begin(), target.problems.end(),
                                  b->model.problem) != target.problems.end();
    const bool timed_algorithm = std::find(target.algorithms.begin(), target.algorithms.end(),
                                           b->algorithm) != target.algorithms.end();
    if (!listed || !timed_algorithm || b->model.mesh != target.mesh)
      continue;
    const bool meets = b->converged() && b->ratio() && *b->ratio() <= target.max_ratio;
    (meets ? check.met : check.missed).push_back(b);
  }
  // The worst first: the largest ratio, then those without one.
  std::stable_sort(check.missed.begin(), check.missed.end(), [](const auto* a, const auto* b) {
    return a->ratio().value_or(-1) > b->ratio().value_or(-1);
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
  TemplateData parts{TemplateData::type::list};
  const auto part = [&](const char* key, const std::string& value, TemplateData p = {}) {
    p.set(key, value);
    p.set("first", parts.is_empty_list());
    parts.push_back(p);
  };
  if (!c.host_name.empty())
    part("host", c.host_name);
  if (c.num_cpus)
    part("cpus", std::to_string(*c.num_cpus),
         c.mhz_per_cpu ? TemplateData("mhz", fmt::format("{:.0f}", *c.mhz_per_cpu))
                       : TemplateData());
  std::vector<std::string> loads;
  for (double l : c.load_avg)
    loads.push_back(fmt::format("{:.2f}", l));
  if (!loads.empty())
    part("loads", fmt::format("{}", fmt::join(loads, " / ")));
  if (!c.library_build_type.empty())
    part("build_type", c.library_build_type);
  if (!c.executable.empty())
    part("executable", c.executable);
  if (!c.date.empty())
    part("date", c.date);
  TemplateData d("file", source.file);
  d.set("parts", parts);
  d.set("scaling", c.cpu_scaling_enabled.value_or(false));
  d.set("n_other", text_or_false(source.n_other > 0 ? std::to_string(source.n_other) : ""));
  std::string out = render_template(templates::machine_line, d);
  std::erase(out, '\n');
  return out;
}

std::string bench_section(const BenchResults& bench, const FigureSet& figures,
                          const BenchTarget& target) {
  TemplateData d;
  d.set("n_contact", std::to_string(bench.contact.size()));
  d.set("n_all_options", std::to_string(bench.all_options.size()));
  d.set("machines", template_list(bench.sources, [](const BenchSource& s) {
          return TemplateData(machine_line(s));
        }));
  d.set("below_floor", below_floor(bench));
  d.set("replaced", text_or_false(bench.n_replaced > 0 ? std::to_string(bench.n_replaced) : ""));
  d.set("target", target_data(bench, target));
  d.set("figures", figure_set_data(figures));
  d.set("all_options", text_or_false(bench.all_options.empty() ? "" : all_options_table(bench)));
  d.set("model_cases", model_cases_data(bench, target.max_model_cases_ratio));
  d.set("al", name(BenchMethod::AL));
  d.set("has_models", !bench.contact.empty());
  d.set("models", template_list(by_model(bench),
                                [](const auto& m) { return model_data(m.first, m.second); }));
  return tidy_markdown(render_template(templates::bench_section, d));
}

}  // namespace cs::reports
