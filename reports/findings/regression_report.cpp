#include "reports/findings/regression_report.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include <fmt/format.h>

#include "grading/grade_change.hpp"
#include "reports/render/template_text.hpp"
#include "reports/results/results_index.hpp"
#include "reports/tables/markdown_table.hpp"
#include "schema/baseline_file.hpp"

namespace cs::reports {
namespace {

/// Drifts smaller than this (relative) are reported as "identical": round-off of the writer.
constexpr double kIdenticalRelative = 1e-12;

using Fields = kainjow::mustache::object;

std::string flag(const std::optional<bool>& v, const char* yes) {
  return v ? (*v ? yes : "no") : kMissing;
}

std::string grade_text(const std::optional<schema::Grade>& g) {
  return g ? name_of(*g) : kMissing;
}

/// The round-off a grade change is judged with here: the gate's, for its default tolerance
/// (a results file carries no per-quantity tolerances).
double edge_tolerance() {
  return grading::round_off_tolerance(schema::kDefaultGateTolerance);
}

/// One quantity of a case present in both files.
QuantityDrift drift_of(const schema::CaseResult& o, const schema::CaseResult& c,
                       const schema::QuantityResult& oq, const schema::QuantityResult& q) {
  QuantityDrift d{.case_id = schema::case_id(c.spec),
                  .quantity = q.quantity,
                  .old_value = finite(oq.value),
                  .new_value = finite(q.value),
                  .old_error = finite(oq.error_percent),
                  .new_error = finite(q.error_percent),
                  .old_grade = oq.grade,
                  .new_grade = q.grade,
                  .old_status = o.status,
                  .new_status = c.status};
  if (d.old_value && d.new_value) {
    d.absolute = *d.new_value - *d.old_value;
    if (*d.old_value != 0.0)
      d.relative = *d.absolute / std::abs(*d.old_value);
  }
  return d;
}

double drift_magnitude(const QuantityDrift& d) {
  if (d.relative)
    return std::abs(*d.relative);
  if (d.old_value.has_value() != d.new_value.has_value())
    return INFINITY;
  return d.absolute ? std::abs(*d.absolute) : 0.0;
}

std::string drift_text(const QuantityDrift& d) {
  if (d.relative)
    return fmt::format("{:+.3g} %", *d.relative * 100);
  if (!d.old_value && d.new_value)
    return "value gained";
  if (d.old_value && !d.new_value)
    return "value lost";
  if (d.absolute)
    return fmt::format("{:+.3g} (absolute)", *d.absolute);
  return kMissing;
}

/// "e → s" when the grade changed, else the grade.
std::string grade_change(const QuantityDrift& q) {
  return q.old_grade == q.new_grade
             ? name_of(q.new_grade)
             : fmt::format("{} → {}", name_of(q.old_grade), name_of(q.new_grade));
}

/// The mark of a grade change: "**worse** ", "better ", "at a band's edge " or none.
std::string change_mark(bool worse, bool better, bool at_edge) {
  return worse ? "**worse** " : better ? "better " : at_edge ? "at a band's edge " : "";
}

/// The grade change marked (change_mark), and any status change.
std::string marked_change(const QuantityDrift& q) {
  const std::string mark = change_mark(q.grade_worse(), q.grade_better(), q.grade_at_edge());
  if (q.old_status == q.new_status)
    return mark + grade_change(q);
  return fmt::format("{}{} (status {} → {})", mark, grade_change(q), name_of(q.old_status),
                     name_of(q.new_status));
}

}  // namespace

bool QuantityDrift::grade_at_edge() const {
  return old_grade != new_grade &&
         grading::grade_change_is_round_off({old_value, old_error}, {new_value, new_error},
                                            edge_tolerance());
}
bool QuantityDrift::grade_worse() const {
  return new_grade > old_grade && !grade_at_edge();  // schema::Grade is ordered best first
}
bool QuantityDrift::grade_better() const {
  return new_grade < old_grade && !grade_at_edge();
}

bool RowVerdictChange::better() const {
  return old_grade && new_grade && *new_grade < *old_grade && !grade_at_edge;
}

bool RowVerdictChange::worse() const {
  const auto lost = [](std::optional<bool> was, std::optional<bool> is) {
    return was.value_or(false) && !is.value_or(false);
  };
  const bool grade_lost = old_grade && (!new_grade || (*new_grade > *old_grade && !grade_at_edge));
  return grade_lost || lost(old_converging, new_converging) || lost(old_diverging, new_diverging);
}

Regression compare_results(const schema::ResultsDocument& baseline,
                           const schema::ResultsDocument& current) {
  Regression out;
  out.old_source = baseline.source;
  out.new_source = current.source;
  std::map<std::string, const schema::CaseResult*> old_cases;
  for (const auto& c : baseline.cases)
    old_cases.emplace(schema::case_id(c.spec), &c);
  std::set<std::string> seen;  // ids of the cases in both files
  for (const auto& c : current.cases) {
    const std::string id = schema::case_id(c.spec);
    const auto it = old_cases.find(id);
    if (it == old_cases.end()) {
      out.only_in_new.push_back(id);
      continue;
    }
    seen.insert(id);
    const schema::CaseResult& o = *it->second;
    out.status_changes += o.status != c.status ? 1 : 0;
    for (const auto& q : c.quantities) {
      const schema::QuantityResult* oq = o.quantity(q.quantity);
      if (oq == nullptr) {
        out.quantities_only_in_one.push_back(
            fmt::format("{}: {} (new only)", id, name_of(q.quantity)));
        continue;
      }
      const QuantityDrift d = drift_of(o, c, *oq, q);
      out.grades_worse += d.grade_worse() ? 1 : 0;
      out.grades_better += d.grade_better() ? 1 : 0;
      out.grades_at_edge += d.grade_at_edge() ? 1 : 0;
      out.quantities.push_back(d);
    }
    for (const auto& oq : o.quantities) {
      if (c.quantity(oq.quantity) == nullptr) {
        out.quantities_only_in_one.push_back(
            fmt::format("{}: {} (baseline only)", id, name_of(oq.quantity)));
      }
    }
  }
  for (const auto& c : baseline.cases) {
    if (const std::string id = schema::case_id(c.spec); !seen.contains(id))
      out.only_in_old.push_back(id);
  }
  std::map<std::string, const schema::RowVerdict*> old_rows;
  for (const auto& r : baseline.rows)
    old_rows.emplace(r.id, &r);
  for (const auto& r : current.rows) {
    const auto it = old_rows.find(r.id);
    if (it == old_rows.end())
      continue;
    const schema::RowVerdict& o = *it->second;
    if (o.grade == r.grade && o.converging == r.converging && o.diverging == r.diverging)
      continue;
    out.row_changes.push_back(
        {r.id, o.grade, r.grade, o.converging, r.converging, o.diverging, r.diverging,
         o.grade != r.grade && grading::grade_change_is_round_off(o, r, edge_tolerance())});
  }
  return out;
}

std::string regression_markdown(const Regression& r) {
  std::vector<const QuantityDrift*> drifted, changed;
  for (const auto& q : r.quantities) {
    if (drift_magnitude(q) > kIdenticalRelative)
      drifted.push_back(&q);
    if (q.old_grade != q.new_grade || q.old_status != q.new_status)
      changed.push_back(&q);
  }
  std::ranges::sort(drifted, std::greater{},
                    [](const QuantityDrift* q) { return drift_magnitude(*q); });
  constexpr Align l = Align::left, right = Align::right;
  const MarkdownTable changes = table_of(
      {"Case", "Quantity", "Grade", "Baseline", "Current", "Drift"}, changed,
      [](const QuantityDrift* q) -> std::vector<std::string> {
        return {fmt::format("`{}`", q->case_id), name_of(q->quantity),       marked_change(*q),
                format_value(q->old_value),      format_value(q->new_value), drift_text(*q)};
      },
      {l, l, l, right, right, right});
  const auto arrow = [](const std::string& a, const std::string& b) { return a + " → " + b; };
  const MarkdownTable rows = table_of(
      {"Row", "Grade", "Converging", "Diverging (Eq. 47)"}, r.row_changes,
      [&](const RowVerdictChange& c) -> std::vector<std::string> {
        return {
            fmt::format("{}`{}`", change_mark(c.worse(), c.better(), c.grade_at_edge), c.row_id),
            arrow(grade_text(c.old_grade), grade_text(c.new_grade)),
            arrow(flag(c.old_converging, "c"), flag(c.new_converging, "c")),
            arrow(flag(c.old_diverging, "yes"), flag(c.new_diverging, "yes"))};
      },
      {l, l, l, l});
  const MarkdownTable drifts = table_of(
      {"Case", "Quantity", "Baseline", "Current", "Drift (relative)", "Grade"}, drifted,
      [&](const QuantityDrift* q) -> std::vector<std::string> {
        return {fmt::format("`{}`", q->case_id), name_of(q->quantity), format_value(q->old_value),
                format_value(q->new_value),      drift_text(*q),       grade_change(*q)};
      },
      {l, l, right, right, right, l});
  const auto table = [](const MarkdownTable& t) {
    return text_or_false(t.n_rows() == 0 ? std::string() : t.render());
  };
  const auto ids = [](const std::vector<std::string>& list) {
    return template_list(list, [](const std::string& id) { return TemplateData("id", id); });
  };
  const auto n = [](std::size_t v) { return std::to_string(v); };
  Fields d{{"old_source", r.old_source},
           {"new_source", r.new_source},
           {"n_common", n(r.quantities.size())},
           {"n_drifted", n(drifted.size())},
           {"n_identical", n(r.quantities.size() - drifted.size())},
           {"identical", fmt::format("{:g}", kIdenticalRelative)},
           {"grades_worse", n(r.grades_worse)},
           {"grades_better", n(r.grades_better)},
           {"grades_at_edge", n(r.grades_at_edge)},
           {"edge_tolerance", fmt::format("{:g}", edge_tolerance())},
           {"status_changes", n(r.status_changes)},
           {"row_changes", n(r.row_changes.size())},
           {"rows_worse", n(std::ranges::count_if(r.row_changes, &RowVerdictChange::worse))},
           {"n_only_in_new", n(r.only_in_new.size())},
           {"n_only_in_old", n(r.only_in_old.size())},
           {"changed", table(changes)},
           {"rows", table(rows)},
           {"drifted", table(drifts)},
           {"only_in_new", ids(r.only_in_new)},
           {"has_only_in_new", !r.only_in_new.empty()},
           {"only_in_old", ids(r.only_in_old)},
           {"has_only_in_old", !r.only_in_old.empty()},
           {"only_in_one", ids(r.quantities_only_in_one)},
           {"has_only_in_one", !r.quantities_only_in_one.empty()}};
  if (!drifted.empty()) {
    const QuantityDrift* q = drifted.front();
    d["largest"] =
        Fields{{"case", q->case_id}, {"quantity", name_of(q->quantity)}, {"drift", drift_text(*q)}};
  }
  return tidy_markdown(render_template(templates::regression_report, d));
}

}  // namespace cs::reports
