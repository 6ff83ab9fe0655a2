#include "reports/tables/conformal_section.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include <fmt/format.h>

#include "grading/convergence.hpp"

#include "reports/tables/grade_tables.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::Quantity;

std::optional<double> fine_error(const schema::RowVerdict* row) {
  return row == nullptr ? std::nullopt : row->errors[mesh_index(kFinestMesh)];
}

/// "−0.12 % / +3.4 % (e / g)": mean pressure error / arc deviation and their grades; "—"
/// without either row.
std::string option_cell(const ResultsIndex& index, schema::ProblemId id, schema::Element element,
                        const Option& option) {
  const auto* mean = index.row(id, Quantity::p_mean, element, option);
  const auto* arc = index.row(id, Quantity::p_arc, element, option);
  if (mean == nullptr && arc == nullptr)
    return kMissing;
  return fmt::format("{} / {} ({} / {})", format_error_resolved(fine_error(mean)),
                     format_error_resolved(fine_error(arc)), format_marked_grade_cell(index, mean),
                     format_marked_grade_cell(index, arc));
}

std::string options_table(const ResultsIndex& index, const schema::ProblemRecord& p) {
  std::vector<std::string> header{"Element", "Contact"};
  for (const auto a : schema::values<schema::Algorithm>())
    header.emplace_back(schema::to_string(a));
  MarkdownTable table(header);
  for (const auto element : schema::values<schema::Element>()) {
    for (const auto contact : schema::values<schema::ContactKind>()) {
      std::vector<std::string> cells{name_of(element), name_of(contact)};
      for (const auto a : schema::values<schema::Algorithm>())
        cells.push_back(option_cell(index, p.id, element, {a, contact}));
      if (std::any_of(cells.begin() + 2, cells.end(),
                      [](const std::string& c) { return c != kMissing; }))
        table.add_row(cells);
    }
  }
  return rendered_if_any(table);
}

/// The largest |p_mean error| on F over the LM options (LMP, PLM) with ss and mortar, and the
/// options that were run ("LMP ss, LMP mortar").
std::optional<double> lm_mean_error(const ResultsIndex& index, schema::ProblemId id,
                                    std::string& run) {
  std::optional<double> out;
  std::vector<std::string> labels;
  for (const auto a : {schema::Algorithm::LMP, schema::Algorithm::PLM}) {
    for (const auto c : {schema::ContactKind::ss, schema::ContactKind::mortar}) {
      bool any = false;
      for (const auto element : schema::values<schema::Element>()) {
        const auto e = fine_error(index.row(id, Quantity::p_mean, element, {a, c}));
        any = any || e.has_value();
        if (e && (!out || std::abs(*e) > std::abs(*out)))
          out = *e;
      }
      if (any)
        labels.push_back(Option{a, c}.label());
    }
  }
  run = join_words(labels, ", ");
  return out;
}

/// "−0.01 % … +3.0e-03 %": a signed range of F errors, one value where both ends print alike.
std::string signed_range(double low, double high) {
  const std::string a = format_error_resolved(low), b = format_error_resolved(high);
  return a == b ? a : a + " … " + b;
}

/// Every option's arc deviation on F (the error of p_arc), by element and option.
std::vector<ArcExtreme> arc_deviations(const ResultsIndex& index, schema::ProblemId id) {
  std::vector<ArcExtreme> out;
  for (const auto element : schema::values<schema::Element>()) {
    for (const Option& option : all_options()) {
      if (const auto e = fine_error(index.row(id, Quantity::p_arc, element, option)))
        out.push_back({*e, element, option});
    }
  }
  return out;
}

double magnitude(const ArcExtreme& x) {
  return std::abs(x.deviation_percent);
}

/// Every option whose arc deviation on F lies within the study's resolution of |`extreme`| (a
/// tie is named whole, not by its first member: "Q8 LMP mortar, Q8 PLM mortar"), and the signed
/// range of their deviations, which a tie of magnitudes may give both signs.
std::pair<std::string, std::string> tied_options(const std::vector<ArcExtreme>& deviations,
                                                 double extreme) {
  std::vector<std::string> tied;
  double low = extreme, high = extreme;
  for (const ArcExtreme& x : deviations) {
    if (std::abs(magnitude(x) - std::abs(extreme)) <= grading::kErrorResolutionPercent) {
      tied.push_back(fmt::format("{} {}", schema::to_string(x.element), x.option.label()));
      low = std::min(low, x.deviation_percent);
      high = std::max(high, x.deviation_percent);
    }
  }
  return {signed_range(low, high), join_words(tied, ", ")};
}

/// The part of one problem; false when it has no row to show.
bool problem_part(const ResultsIndex& index, const schema::ProblemRecord& p, TemplateData& d) {
  const std::string table = options_table(index, p);
  d.set("table", table);
  std::string lm_run;
  const auto lm = lm_mean_error(index, p.id, lm_run);
  d.set("lm_run", lm_run);
  d.set("lm", text_or_false(lm ? format_error_resolved(*lm) : ""));
  d.set("lm_within", lm && std::abs(*lm) < 1.0);
  if (const auto arc = arc_range(index, p.id)) {
    const auto deviations = arc_deviations(index, p.id);
    const auto [low, high] = std::ranges::minmax(deviations, {}, &ArcExtreme::deviation_percent);
    d.set("arc", true);
    d.set("all", signed_range(low.deviation_percent, high.deviation_percent));
    for (const auto& [key, e] : {std::pair{"worst", arc->worst}, {"best", arc->best}}) {
      const auto [range, options] = tied_options(deviations, e.deviation_percent);
      d.set(key, range);
      d.set(std::string(key) + "_option", options);
    }
  }
  return !table.empty();
}

}  // namespace

std::optional<ArcRange> arc_range(const ResultsIndex& index, schema::ProblemId problem) {
  const auto deviations = arc_deviations(index, problem);
  if (deviations.empty())
    return std::nullopt;
  // The first of equal magnitudes.
  return ArcRange{*std::ranges::min_element(deviations, {}, magnitude),
                  *std::ranges::max_element(deviations, {}, magnitude)};
}

std::string conformal_section(const ResultsIndex& index) {
  return per_problem_section(index, Quantity::p_mean, templates::conformal_section,
                             std::bind_front(problem_part, std::cref(index)));
}

}  // namespace cs::reports
