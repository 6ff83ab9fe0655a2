#include "reports/pages/verdict_page.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/accuracy.hpp"
#include "reports/facts/solvers.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::Element;

/// A difference of percentages, unsigned: "0.012 points".
std::string format_points(double points) {
  const double p = std::abs(points);
  if (p == 0.0)
    return "0 points";
  return fmt::format("{:.2g} point{}", p, p == 1.0 ? "" : "s");
}

/// A signed error to three significant digits ("+0.0449 %", "−0.929 %"; below 0.01 % as
/// format_error_resolved), where two groups of errors are told apart.
std::string format_error_precise(double percent) {
  if (std::abs(percent) < 0.01)
    return format_error_resolved(percent);
  return with_minus_sign(fmt::format("{:+.3g} %", percent));
}

std::string singular_cell(const OptionCell& c) {
  const int n = static_cast<int>(c.singular_rows.size());
  const std::string mark = c.n_not_credible > 0 ? " ✗" : "";
  if (c.n_strict == n)
    return "diverges" + mark;
  if (c.n_eq47 == n)
    return "Eq. 47 only" + mark;
  return fmt::format("fails Eq. 47 ({} of {}){}", n - c.n_eq47, n, mark);
}

/// One matrix per element: rows family x discretization, columns the situations.
TemplateData matrix(const std::vector<SituationVerdict>& situations, Element element) {
  // Ours first (by family and discretization), then the other codes' options.
  using Row = std::tuple<std::string, OptionFamily, schema::ContactKind>;
  const auto row_of = [](const OptionCell& c) { return Row{c.code, c.family, c.contact}; };
  std::set<Row> options;
  std::map<Row, OptionCell> label_of;  // the family's row: every member run in any situation
  for (const auto& s : situations) {
    for (const auto& c : s.cells) {
      if (c.element == element) {
        options.insert(row_of(c));
        OptionCell& row = label_of.try_emplace(row_of(c), c).first->second;
        row.algorithm.reset();
        row.members.insert(c.members.begin(), c.members.end());
      }
    }
  }
  std::vector<std::string> header{"Option"};
  for (const auto& s : situations)
    header.push_back(s.title);
  MarkdownTable table(header);
  for (const Row& option : options) {
    std::vector<std::string> row{option_label(label_of.at(option))};
    for (const auto& s : situations) {
      // One cell, or one per algorithm where the family's members differ ("AL s −7.07 % · PM
      // u +10.5 %").
      std::vector<std::string> parts, texts;
      for (const auto& c : s.cells) {
        if (c.element != element || row_of(c) != option)
          continue;
        texts.push_back(verdict_cell(c));
        // A cell of fewer members than its row names them ("PM e +0.55 %" in the row "AL, PM
        // ss" where only PM was run on the situation).
        const bool fewer = !c.algorithm && c.members != label_of.at(option).members;
        parts.push_back(
            c.algorithm ? fmt::format("{} {}", schema::to_string(*c.algorithm), texts.back())
            : fewer     ? fmt::format("{} {}", members_label(c.family, c.members), texts.back())
                        : texts.back());
        if (fewer)
          texts.back() = parts.back();
      }
      // Split cells that read alike to the printed digits are shown once.
      const bool alike = std::all_of(texts.begin(), texts.end(),
                                     [&](const std::string& t) { return t == texts.front(); });
      row.push_back(parts.empty() ? std::string(kMissing)
                    : alike       ? texts.front()
                                  : fmt::format("{}", fmt::join(parts, " · ")));
    }
    table.add_row(std::move(row));
  }
  TemplateData m("element", std::string(schema::to_string(element)));
  m.set("table", table.render());
  return m;
}

/// The largest measure of each failed check over the cells, e.g. "force balance up to 19.2".
/// Only the checks `shown` accepts are listed.
std::string failure_evidence(const std::vector<const OptionCell*>& cells,
                             const std::function<bool(const std::string&)>& shown) {
  std::map<std::string, double> worst;
  double worst_error = 0.0;
  int eq47_failures = 0, singular = 0, not_converged = 0, rows = 0, failed = 0;
  std::string failed_reason;
  for (const OptionCell* c : cells) {
    not_converged += c->n_not_converged;
    failed += c->n_failed;
    if (failed_reason.empty())
      failed_reason = c->failed_reason;
    rows += static_cast<int>(c->rows.size() + c->singular_rows.size()) + c->n_failed;
    const auto add = [&](const std::vector<CheckFailure>& failures) {
      for (const auto& failure : failures)
        if (shown(failure.check))
          worst[failure.check] = std::max(worst[failure.check], failure.measure.value_or(0.0));
    };
    for (const RowFacts* f : c->rows)
      add(f->failures);
    for (const DivergenceFacts* d : c->singular_rows)
      add(d->failures);
    if (c->worst_error && std::abs(*c->worst_error) > std::abs(worst_error))
      worst_error = *c->worst_error;
    eq47_failures += static_cast<int>(c->singular_rows.size()) - c->n_eq47;
    singular += static_cast<int>(c->singular_rows.size());
  }
  std::vector<std::string> parts;
  for (const auto& [check, measure] : worst)
    parts.push_back(fmt::format("{} up to {}", check, fmt::format("{:.3g}", measure)));
  if (singular > 0)
    parts.push_back(fmt::format("Eq. 47 fails on {} of {} rows", eq47_failures, singular));
  if (not_converged > 0)
    parts.push_back(fmt::format("F not converged on {} of {} rows", not_converged, rows));
  if (failed > 0)
    parts.push_back(fmt::format("F failed on {} of {} rows{}", failed, rows,
                                failed_reason.empty() ? "" : " (" + failed_reason + ")"));
  if (parts.empty() && worst_error != 0.0)
    parts.push_back("F error " + format_error_resolved(worst_error));
  return fmt::format("{}", fmt::join(parts, "; "));
}

TemplateData failures(const SituationVerdict& s) {
  const auto common = [&](const std::string& check) {
    return std::find(s.common_failures.begin(), s.common_failures.end(), check) !=
           s.common_failures.end();
  };
  std::map<std::tuple<std::string, OptionFamily, std::optional<schema::Algorithm>>,
           std::vector<const OptionCell*>>
      by_option;
  for (const OptionCell* c : s.avoid)
    by_option[{c->code, c->family, c->algorithm}].push_back(c);
  TemplateData list{TemplateData::type::list};
  if (!s.common_failures.empty()) {
    std::vector<const OptionCell*> all;
    for (const auto& c : s.cells)
      all.push_back(&c);
    TemplateData d;
    d.set("situation", s.title);
    d.set("options", "every option alike");
    d.set("evidence", failure_evidence(all, common));
    list.push_back(d);
  }
  for (const auto& [family, cells] : by_option) {
    TemplateData d;
    d.set("situation", s.title);
    d.set("options", cells_label(cells));
    d.set("evidence",
          failure_evidence(cells, [&](const std::string& check) { return !common(check); }));
    list.push_back(d);
  }
  return list;
}

TemplateData advice(const SituationVerdict& s) {
  TemplateData d;
  d.set("title", s.title);
  d.set("singular", s.singular);
  d.set("has_best", !s.best.empty());
  d.set("best", cells_label(s.best));
  d.set("has_avoid", !s.avoid.empty());
  d.set("avoid", cells_label(s.avoid));
  // The flat punch, each avoided option under its reason: an F case fails an interface check
  // (which makes any Eq. 47 verdict of it no evidence); else Eq. 47 fails on a row; else an F
  // case failed; else one did not converge.
  std::array<std::vector<const OptionCell*>, 4> why;
  for (const OptionCell* c : s.avoid) {
    const bool eq47 = c->n_eq47 < static_cast<int>(c->singular_rows.size());
    why[c->n_not_credible > 0 ? 1 : eq47 ? 0 : c->n_failed > 0 ? 2 : 3].push_back(c);
  }
  for (const auto& [i, key] : {std::pair{0, "eq47_avoid"}, std::pair{1, "check_avoid"},
                               std::pair{2, "failed_avoid"}, std::pair{3, "unconverged_avoid"}}) {
    d.set(std::string("has_") + key, !why[i].empty());
    d.set(key, cells_label(why[i]));
  }
  d.set("has_common", !s.common_failures.empty());
  d.set("common", join_words(s.common_failures));  // "force balance and tensile pressure"
  if (s.best_grade && s.best_min && s.best_max) {
    const double spread = s.best_abs_spread;
    d.set("grade", std::string(schema::to_string(*s.best_grade)));
    d.set("min", format_error_resolved(*s.best_min));
    d.set("max", format_error_resolved(*s.best_max));
    d.set("spread", format_points(spread));
    d.set("noise", format_points(s.best_noise));
    d.set("within_noise", spread <= s.best_noise);
    const double band = grading::grade_band_width(*s.best_grade);
    d.set("wider_than_grade", spread <= s.best_noise && s.best_noise > band);
    d.set("band", format_points(band));
    // Not tied: those with the smallest F errors apart from the others of the grade.
    std::vector<const OptionCell*> others;
    double lo = INFINITY, hi = -INFINITY;
    for (const OptionCell* c : s.best) {
      if (std::ranges::count(s.leaders, c) > 0)
        continue;
      others.push_back(c);
      lo = std::min(lo, *c->worst_error), hi = std::max(hi, *c->worst_error);
    }
    d.set("leaders", cells_label(s.leaders));
    std::string largest = format_error_precise(s.leaders_max_abs);  // a magnitude: no sign
    if (largest.starts_with('+'))
      largest.erase(0, 1);
    d.set("leaders_max", largest);
    d.set("leaders_noise", format_points(s.leaders_noise));
    d.set("leaders_extended", s.leaders_extended);
    d.set("others", cells_label(others));
    d.set("others_min", others.empty() ? "" : format_error_precise(lo));
    d.set("others_max", others.empty() ? "" : format_error_precise(hi));
    d.set("others_range", !others.empty() && lo != hi);
    d.set("one", s.best.size() == 1);
    d.set("range", *s.best_min != *s.best_max);
  }
  return d;
}

}  // namespace

std::string verdict_cell(const OptionCell& c) {
  const std::string failed =
      c.n_failed > 0 ? fmt::format("F failed on {} row{}", c.n_failed, c.n_failed > 1 ? "s" : "")
                     : std::string();
  std::string lacking = failed;
  if (c.n_missing > 0)
    lacking += fmt::format("{}no F on {} row{}", lacking.empty() ? "" : " · ", c.n_missing,
                           c.n_missing > 1 ? "s" : "");
  if (!c.not_run_on.empty()) {
    std::vector<std::string> labels;
    for (const auto p : c.not_run_on)
      labels.emplace_back(schema::label(p));
    lacking += fmt::format("{}not run on {}", lacking.empty() ? "" : " · ", join_words(labels));
  }
  if (!c.singular_rows.empty())
    return singular_cell(c) + (lacking.empty() ? "" : " (" + lacking + ")");
  if (!c.worst_error)
    return lacking.empty() ? std::string(kMissing) : lacking;
  // A fine case that did not converge: its last iterate's error, and no grade.
  std::string out = c.worst_grade ? fmt::format("{} {}", schema::to_string(*c.worst_grade),
                                                format_error_resolved(*c.worst_error))
                                  : format_error_resolved(*c.worst_error);
  if (c.worst_resolution > 0.0)
    out += fmt::format(" ± {:.3g}", c.worst_resolution);
  if (c.n_not_credible > 0)
    out += " ✗";
  if (c.n_luck > 0)
    out += " ‡";
  if (c.n_not_converged > 0)
    out += " †";
  // What the cell lacks in parentheses, so that a split cell's " · " separates algorithms only.
  return lacking.empty() ? out : out + " (" + lacking + ")";
}

std::string verdict_page(const ResultsIndex& index, const std::vector<SituationVerdict>& situations,
                         const OtherCodesNote& others) {
  TemplateData d;
  TemplateData matrices{TemplateData::type::list};
  for (const Element e : schema::values<Element>()) {
    const bool present = std::any_of(situations.begin(), situations.end(), [&](const auto& s) {
      return std::any_of(s.cells.begin(), s.cells.end(),
                         [&](const OptionCell& c) { return c.element == e; });
    });
    if (present)
      matrices.push_back(matrix(situations, e));
  }
  d.set("matrices", matrices);
  d.set("has_verdict", !matrices.is_empty_list());
  d.set("advice", template_list(situations, advice));
  TemplateData all_failures{TemplateData::type::list};
  for (const auto& s : situations) {
    const TemplateData f = failures(s);
    for (const auto& item : f.list_value())
      all_failures.push_back(item);
  }
  d.set("failures", all_failures);
  // The matrix's rows: our baseline, and the other codes' beside it.
  const bool other_rows = std::any_of(situations.begin(), situations.end(), [](const auto& s) {
    return std::any_of(s.cells.begin(), s.cells.end(),
                       [](const OptionCell& c) { return !c.code.empty(); });
  });
  d.set("solver", other_rows ? solver_names(index) : solver_display_name(builtin_solver_label()));
  d.set("solvers", solver_names(index));
  d.set("has_others", !others.advice.empty());
  d.set("others",
        template_list(others.advice, [](const std::string& a) { return TemplateData(a); }));
  d.set("others_file", others.appendix_file);
  d.set("others_title", others.appendix_title);
  return render_template(templates::verdict_page, d);
}

}  // namespace cs::reports
