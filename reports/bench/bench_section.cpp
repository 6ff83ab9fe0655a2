#include "reports/bench/bench_section.hpp"

#include <algorithm>
#include <functional>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/render/template_text.hpp"
#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

bool contains(const auto& range, const auto& value) {
  return std::ranges::find(range, value) != std::ranges::end(range);
}

std::string format_ms(const std::optional<double>& ms) {
  return ms ? format_milliseconds(*ms) : std::string(kMissing);
}

/// `value` with `decimals` decimals, or the em dash.
std::string fixed(const std::optional<double>& value, int decimals) {
  return value ? fmt::format("{:.{}f}", *value, decimals) : std::string(kMissing);
}

/// The ratio with every measurement of it: "1.27 ± 0.02 (earlier: 1.40, 1.78 ± 0.41)", each
/// with its spread over its file's repetitions.
std::string ratio_text(const BenchRow& b) {
  const auto one = [](const BenchRow::Measurement& m) {
    return fmt::format("{:.2f}", m.ratio) + (m.stddev ? fmt::format(" ± {:.2f}", *m.stddev) : "");
  };
  std::vector<std::string> earlier;
  for (const auto& m : b.earlier)
    earlier.push_back(one(m));
  const std::string last = b.ratio() ? one({*b.ratio(), b.ratio_stddev}) : fixed(b.ratio(), 2);
  return last + (earlier.empty() ? "" : fmt::format(" (earlier: {})", join_words(earlier, ", ")));
}

/// A benchmark's facts for the template's tables and lists.
TemplateData row_data(const BenchRow* b) {
  TemplateData d("model", model_md(b->model));
  d.set("contact", name_of(b->contact));
  d.set("algorithm", name_of(b->algorithm));
  d.set("time", format_ms(b->time_ms));
  d.set("ratio", fixed(b->ratio(), 2));
  d.set("measurements", ratio_text(*b));
  d.set("failure", escape_cell(b->failure()));
  d.set("error", text_or_false(escape_cell(b->error)));
  d.set("reference", format_ms(b->reference_ms()));
  d.set("cases", fixed(b->counter("cases"), 0));
  d.set("converged", fixed(b->counter("converged"), 0));
  d.set("ratio_per_case", fixed(b->counter("ratio_per_case"), 2));
  d.set("one_case", format_ms(b->counter_ms("one_case_s")));
  d.set("ratio_cpu", fixed(b->counter("ratio_cpu"), 2));
  d.set("blas_threads", fixed(b->counter("blas_threads"), 0));
  return d;
}

/// The models whose reference (one assembly + factorization + solve) differs between the files
/// that measured them by more than 10 %, the largest first: "H_p, mesh F, Q4: 15.0 to 20.6 ms".
/// A ratio divides by its own file's reference, so across files it moves with it.
TemplateData reference_spread(const std::vector<const BenchRow*>& contact) {
  std::map<BenchModel, std::pair<double, double>> range;  // model -> (lowest, highest) in ms
  for (const BenchRow* b : contact) {
    for (const auto& m : b->measurements()) {
      if (!m.reference_ms)
        continue;
      auto [it, added] = range.try_emplace(b->model, *m.reference_ms, *m.reference_ms);
      it->second = {std::min(it->second.first, *m.reference_ms),
                    std::max(it->second.second, *m.reference_ms)};
    }
  }
  std::vector<std::pair<double, std::string>> wide;
  for (const auto& [model, r] : range) {
    if (r.second > 1.1 * r.first)
      wide.emplace_back(r.second / r.first,
                        fmt::format("{}: {:.3g} to {:.3g} ms", model_md(model), r.first, r.second));
  }
  std::ranges::sort(wide, std::greater<>());
  std::vector<std::string> text;
  for (const auto& w : wide)
    text.push_back(w.second);
  return joined_or_false(text, "; ");
}

/// The cases with a ratio below the physical floor of 1, and the lowest of them.
TemplateData below_floor(const std::vector<const BenchRow*>& contact) {
  std::vector<const BenchRow*> below;
  std::ranges::copy_if(contact, std::back_inserter(below),
                       [](const BenchRow* b) { return b->ratio() && *b->ratio() < 1; });
  if (below.empty())
    return TemplateData(false);
  const double lowest = *(*std::ranges::min_element(below, {}, [](const BenchRow* b) {
                           return *b->ratio();
                         }))->ratio();
  // the lowest, and those that print alike (two decimals, as the tables print them)
  const auto printed = [](double ratio) { return fmt::format("{:.2f}", ratio); };
  std::vector<std::string> names;
  for (const BenchRow* b : below) {
    if (printed(*b->ratio()) == printed(lowest))
      names.push_back(
          fmt::format("{} {} {}", model_md(b->model), name_of(b->contact), name_of(b->algorithm)));
  }
  TemplateData d("below", std::to_string(below.size()));
  d.set("with_ratio", std::to_string(std::ranges::count_if(
                          contact, [](const BenchRow* b) { return b->ratio().has_value(); })));
  d.set("lowest", fmt::format("{}", fmt::join(names, "; ")));
  d.set("lowest_ratio", printed(lowest));
  d.set("spread", reference_spread(contact));
  return d;
}

/// The target's verdict when no case was measured at its mesh: the meshes that were, and the
/// finest one's count for orientation.
TemplateData not_judged(const BenchResults& bench, BenchTarget target) {
  const auto contact = bench.of(BenchFamily::Contact);
  std::vector<schema::MeshLevel> meshes;
  std::ranges::copy_if(kMeshes, std::back_inserter(meshes), [&](schema::MeshLevel m) {
    return std::ranges::any_of(contact, [m](const BenchRow* b) { return b->model.mesh == m; });
  });
  TemplateData d("files", bench.sources.size() > 1 ? "s" : "");
  d.set("meshes", meshes.empty() ? std::string("none") : join_words(names_of(meshes)));
  d.set("finest", TemplateData(false));
  if (meshes.empty())
    return d;
  target.mesh = meshes.back();
  const TargetCheck there = check_target(bench, target);
  if (there.n_cases() > 0) {
    TemplateData f("mesh", name_of(target.mesh));
    f.set("met", std::to_string(there.met.size()));
    f.set("cases", std::to_string(there.n_cases()));
    d.set("finest", f);
  }
  return d;
}

TemplateData target_data(const BenchResults& bench, const BenchTarget& target) {
  const TargetCheck check = check_target(bench, target);
  std::vector<std::string> problems;
  for (const auto p : target.problems)
    problems.emplace_back(schema::label(p));
  TemplateData d("max_ratio", fmt::format("{:g}", target.max_ratio));
  d.set("algorithms", join_words(names_of(target.algorithms)));
  d.set("algorithms_or", join_words(names_of(target.algorithms), " or "));
  d.set("mesh", name_of(target.mesh));
  d.set("problems", join_words(problems));
  d.set("judged", check.n_cases() > 0);
  d.set("not_judged", check.n_cases() > 0 ? TemplateData(false) : not_judged(bench, target));
  d.set("cases", std::to_string(check.n_cases()));
  d.set("met", std::to_string(check.met.size()));
  d.set("n_missed", count_or_false(check.missed.size()));
  d.set("missed", template_list(check.missed, row_data));
  d.set("n_split", count_or_false(check.split.size()));
  d.set("split", template_list(check.split, row_data));
  d.set("n_tied", count_or_false(check.tied.size()));
  d.set("tied", template_list(check.tied, row_data));
  std::vector<std::pair<std::string, std::string>> met;  // model, "ss PM 1.40, ..."
  for (const BenchRow* b : check.met) {
    const std::string item =
        fmt::format("{} {} {}", name_of(b->contact), name_of(b->algorithm), fixed(b->ratio(), 2));
    if (met.empty() || met.back().first != model_md(b->model))
      met.emplace_back(model_md(b->model), item);
    else
      met.back().second += ", " + item;
  }
  d.set("has_met", !met.empty());
  d.set("met_models", template_list(met, [](const auto& m) {
          TemplateData e("model", m.first);
          e.set("items", m.second);
          return e;
        }));
  d.set("not_measured", text_or_false(join_words(check.not_measured)));
  return d;
}

/// The ModelCases benchmarks: a model's full set of cases against one analysis of it, in wall
/// and process CPU time, checked against `max_ratio` (issue #27). A wall-time ratio below the
/// physical floor of 1 (the load changed between the two measurements) does not count as met.
TemplateData model_cases_data(const std::vector<const BenchRow*>& rows, double max_ratio) {
  if (rows.empty())
    return TemplateData(false);
  const auto count = [&](auto met) { return std::ranges::count_if(rows, met); };
  TemplateData d("max_ratio", fmt::format("{:g}", max_ratio));
  d.set("models", std::to_string(rows.size()));
  d.set("met_wall", std::to_string(count([&](const BenchRow* b) {
          return b->ratio() && *b->ratio() >= 1 && *b->ratio() <= max_ratio;
        })));
  d.set("met_cpu", std::to_string(count([&](const BenchRow* b) {
          return b->counter("ratio_cpu") && *b->counter("ratio_cpu") <= max_ratio;
        })));
  d.set("below_one",
        count_or_false(count([](const BenchRow* b) { return b->ratio() && *b->ratio() < 1; })));
  d.set("rows", template_list(rows, row_data));
  return d;
}

/// One cell of a model table: "4.10 ms · 1.28× · 2 it." (+ " + 3 aug." for AL, " ✗" when the
/// case did not converge or stopped with an error).
std::string case_cell(const BenchRow* b) {
  if (b == nullptr)
    return kMissing;
  std::string out = b->time_ms ? format_milliseconds(*b->time_ms) + " ms" : std::string("error");
  if (b->ratio())
    out += " · " + fixed(b->ratio(), 2) + "×";
  if (const auto iterations = b->counter("active_set_iterations"))
    out += fmt::format(" · {:.0f} it.", *iterations);
  if (const auto augmentations = b->counter("augmentations"); augmentations && *augmentations > 0)
    out += fmt::format(" + {:.0f} aug.", *augmentations);
  return b->converged() ? out : out + " ✗";
}

/// The table of one model's cases (algorithms x contact discretizations) and its failures.
TemplateData model_data(const BenchGrid& grid) {
  std::vector<std::string> header{"Algorithm"};
  std::ranges::transform(grid.contacts, std::back_inserter(header), name_of<schema::ContactKind>);
  const MarkdownTable table = table_of(header, grid.methods, [&](BenchMethod a) {
    std::vector<std::string> row{name_of(a)};
    for (const auto c : grid.contacts)
      row.push_back(case_cell(grid.at(c, a)));
    return row;
  });
  std::vector<const BenchRow*> failures;
  std::ranges::copy_if(grid.cases, std::back_inserter(failures),
                       [](const BenchRow* b) { return !b->converged(); });
  TemplateData d("model", model_md(grid.model));
  d.set("reference", format_ms(grid.reference_ms()));
  d.set("table", table.render());
  d.set("failures", template_list(failures, row_data));
  return d;
}

TemplateData figure_set_data(const FigureSet& figures) {
  if (figures.figures.empty() && figures.unavailable.empty())
    return TemplateData(false);
  TemplateData d("unavailable", text_or_false(figures.unavailable));
  d.set("list", template_list(figures.figures, [](const Figure& f) { return figure_data(f); }));
  return d;
}

/// The machine line of one file: what its context says, in the line's order.
TemplateData machine_data(const BenchSource& source) {
  const BenchContext& c = source.context;
  const std::pair<const char*, std::string> facts[]{
      {"host", c.host_name},
      {"cpus", c.num_cpus ? fixed(c.num_cpus, 0) : ""},
      {"loads", fmt::format("{:.2f}", fmt::join(c.load_avg, " / "))},
      {"build_type", c.library_build_type},
      {"executable", c.executable},
      {"date", c.date}};
  TemplateData parts{TemplateData::type::list};
  for (const auto& [key, value] : facts) {
    TemplateData part(key, value);
    part.set("first", parts.is_empty_list());
    part.set("mhz", text_or_false(c.mhz_per_cpu ? fixed(c.mhz_per_cpu, 0) : ""));
    if (!value.empty())
      parts.push_back(part);
  }
  TemplateData d("file", source.file);
  d.set("parts", parts);
  d.set("scaling", c.cpu_scaling_enabled);
  d.set("n_other", count_or_false(source.n_other));
  return d;
}

}  // namespace

TargetCheck check_target(const BenchResults& bench, const BenchTarget& target) {
  TargetCheck check;
  const auto contact = bench.of(BenchFamily::Contact);
  for (const BenchRow* b : contact) {
    if (b->model.mesh != target.mesh || !contains(target.problems, b->model.problem) ||
        !contains(target.algorithms, b->algorithm))
      continue;
    // Each measurement meets the target, misses it, or ties with it (within its spread).
    int meets = 0, misses = 0, ties = 0;
    for (const auto& m : b->measurements()) {
      if (m.stddev && std::abs(m.ratio - target.max_ratio) <= *m.stddev)
        ++ties;
      else
        (m.ratio <= target.max_ratio ? meets : misses) += 1;
    }
    std::vector<const BenchRow*>& outcome = !b->converged() || !b->ratio() ? check.missed
                                            : meets > 0 && misses > 0      ? check.split
                                            : ties > 0                     ? check.tied
                                            : misses > 0                   ? check.missed
                                                                           : check.met;
    outcome.push_back(b);
  }
  // The worst first: the largest ratio, then those without one.
  std::ranges::stable_sort(check.missed, std::greater{},
                           [](const BenchRow* b) { return b->ratio().value_or(-1); });
  for (const auto problem : target.problems) {
    for (const auto element : schema::values<schema::Element>()) {
      const BenchModel model{problem, target.mesh, element};
      if (std::ranges::none_of(contact, [&](const BenchRow* b) { return b->model == model; }))
        check.not_measured.push_back(
            fmt::format("{} {}", schema::label(problem), name_of(element)));
    }
  }
  return check;
}

BenchProvenance bench_provenance(const BenchResults& bench, const ResultsIndex& index) {
  std::map<std::string, const schema::CaseResult*> baseline;  // by case id
  for (const auto& c : index.results().cases) {
    if (c.is_baseline())
      baseline.emplace(schema::case_id(c.spec), &c);
  }
  BenchProvenance p;
  for (const BenchRow* b : bench.of(BenchFamily::Contact)) {
    const auto iterations = b->counter("active_set_iterations");
    const schema::CaseSpec spec{.problem = b->model.problem,
                                .mesh = b->model.mesh,
                                .element = b->model.element,
                                .algorithm = study_algorithm(b->algorithm),
                                .contact = b->contact};
    const auto c = baseline.find(schema::case_id(spec));
    if (!iterations || c == baseline.end())
      continue;
    ++p.compared;
    if (static_cast<int>(*iterations) == c->second->iterations)
      continue;
    if (++p.differing == 1)
      p.example = fmt::format("{} {} {} {} {}: {:.0f} iterations benchmarked, {} in the results",
                              schema::label(spec.problem), name_of(spec.mesh),
                              name_of(spec.element), name_of(spec.contact), name_of(b->algorithm),
                              *iterations, c->second->iterations);
  }
  return p;
}

std::string bench_section(const BenchResults& bench, const FigureSet& figures,
                          const BenchTarget& target, const ResultsIndex* results) {
  const auto contact = bench.of(BenchFamily::Contact);
  const auto all_options = bench.of(BenchFamily::ContactAllOptions);
  TemplateData d("n_contact", std::to_string(contact.size()));
  d.set("n_all_options", std::to_string(all_options.size()));
  d.set("machines", template_list(bench.sources, machine_data));
  d.set("below_floor", below_floor(contact));
  d.set("replaced", count_or_false(bench.n_replaced));
  if (results != nullptr) {
    const BenchProvenance p = bench_provenance(bench, *results);
    TemplateData prov("compared", std::to_string(p.compared));
    prov.set("differing", count_or_false(p.differing));
    prov.set("example", p.example);
    d.set("provenance", p.compared > 0 ? prov : TemplateData(false));
  }
  d.set("target", target_data(bench, target));
  d.set("figures", figure_set_data(figures));
  d.set("has_all_options", !all_options.empty());
  d.set("all_options", template_list(all_options, row_data));
  d.set("model_cases",
        model_cases_data(bench.of(BenchFamily::ModelCases), target.max_model_cases_ratio));
  d.set("has_models", !contact.empty());
  d.set("models", template_list(contact_grids(bench), model_data));
  return tidy_markdown(render_template(templates::bench_section, d));
}

}  // namespace cs::reports
