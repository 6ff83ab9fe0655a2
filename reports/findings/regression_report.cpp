#include "reports/findings/regression_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "reports/results/results_index.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// Drifts smaller than this (relative) are reported as "identical": round-off of the writer.
constexpr double kIdenticalRelative = 1e-12;

std::string flag(const std::optional<bool>& v, const char* yes) {
  if (!v)
    return kMissing;
  return *v ? yes : "no";
}

std::string grade_text(const std::optional<schema::Grade>& g) {
  return g ? std::string(schema::to_string(*g)) : std::string(kMissing);
}

template <schema::Axis E>
std::string name(E v) {
  return std::string(schema::to_string(v));
}

/// One quantity of a case present in both files.
QuantityDrift drift_of(const schema::CaseResult& o, const schema::CaseResult& c,
                       const schema::QuantityResult& oq, const schema::QuantityResult& q) {
  QuantityDrift d{schema::case_id(c.spec),
                  q.quantity,
                  finite(oq.value),
                  finite(q.value),
                  {},
                  {},
                  oq.grade,
                  q.grade,
                  o.status,
                  c.status};
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

}  // namespace

bool QuantityDrift::grade_worse() const {
  return grade_rank(new_grade) > grade_rank(old_grade);
}
bool QuantityDrift::grade_better() const {
  return grade_rank(new_grade) < grade_rank(old_grade);
}

bool RowVerdictChange::worse() const {
  if (old_grade && new_grade && grade_rank(*new_grade) > grade_rank(*old_grade))
    return true;
  if (old_grade && !new_grade)
    return true;
  if (old_converging.value_or(false) && !new_converging.value_or(false))
    return true;
  if (old_diverging.value_or(false) && !new_diverging.value_or(false))
    return true;
  return false;
}

Regression compare_results(const schema::ResultsDocument& baseline,
                           const schema::ResultsDocument& current) {
  Regression out;
  out.old_source = baseline.source;
  out.new_source = current.source;
  std::map<std::string, const schema::CaseResult*> old_cases;
  for (const auto& c : baseline.cases)
    old_cases.emplace(schema::case_id(c.spec), &c);
  std::map<std::string, bool> seen;
  for (const auto& c : current.cases) {
    const std::string id = schema::case_id(c.spec);
    const auto it = old_cases.find(id);
    if (it == old_cases.end()) {
      out.only_in_new.push_back(id);
      continue;
    }
    seen[id] = true;
    const schema::CaseResult& o = *it->second;
    if (o.status != c.status)
      ++out.status_changes;
    for (const auto& q : c.quantities) {
      const schema::QuantityResult* oq = o.quantity(q.quantity);
      if (oq == nullptr) {
        out.quantities_only_in_one.push_back(
            fmt::format("{}: {} (new only)", id, name(q.quantity)));
        continue;
      }
      const QuantityDrift d = drift_of(o, c, *oq, q);
      if (d.grade_worse())
        ++out.grades_worse;
      if (d.grade_better())
        ++out.grades_better;
      out.quantities.push_back(d);
    }
    for (const auto& oq : o.quantities) {
      if (c.quantity(oq.quantity) == nullptr) {
        out.quantities_only_in_one.push_back(
            fmt::format("{}: {} (baseline only)", id, name(oq.quantity)));
      }
    }
  }
  for (const auto& c : baseline.cases) {
    const std::string id = schema::case_id(c.spec);
    if (!seen.count(id))
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
        {r.id, o.grade, r.grade, o.converging, r.converging, o.diverging, r.diverging});
  }
  return out;
}

std::string regression_markdown(const Regression& r) {
  std::string out = fmt::format("# Regression report\n\nBaseline: `{}`  \nCurrent: `{}`\n\n",
                                r.old_source, r.new_source);
  const auto worse_rows = std::count_if(r.row_changes.begin(), r.row_changes.end(),
                                        [](const RowVerdictChange& c) { return c.worse(); });
  std::vector<const QuantityDrift*> drifted;
  for (const auto& q : r.quantities) {
    if (drift_magnitude(q) > kIdenticalRelative)
      drifted.push_back(&q);
  }
  std::sort(drifted.begin(), drifted.end(), [](const QuantityDrift* a, const QuantityDrift* b) {
    return drift_magnitude(*a) > drift_magnitude(*b);
  });
  out += fmt::format(
      "## Summary\n\n- {} case quantities in both files: {} drifted, {} identical (|drift| ≤ "
      "{:g}).\n- Case grades: {} worse, {} better. Status changes: {}.\n- Row verdicts (Table 2 "
      "grade, converging, diverging): {} changed, {} of them for the worse.\n- Cases only in the "
      "current file: {}; only in the baseline: {}.\n",
      r.quantities.size(), drifted.size(), r.quantities.size() - drifted.size(), kIdenticalRelative,
      r.grades_worse, r.grades_better, r.status_changes, r.row_changes.size(), worse_rows,
      r.only_in_new.size(), r.only_in_old.size());
  if (!drifted.empty()) {
    out += fmt::format("- Largest drift: `{}` {} ({}).\n", drifted.front()->case_id,
                       name(drifted.front()->quantity), drift_text(*drifted.front()));
  }
  out += "\n";

  MarkdownTable grades({"Case", "Quantity", "Grade", "Baseline", "Current", "Drift"});
  for (const auto& q : r.quantities) {
    if (q.old_grade == q.new_grade && q.old_status == q.new_status)
      continue;
    std::string change = fmt::format("{} → {}", name(q.old_grade), name(q.new_grade));
    if (q.grade_worse())
      change = "**worse** " + change;
    if (q.grade_better())
      change = "better " + change;
    if (q.old_status != q.new_status)
      change += fmt::format(" (status {} → {})", name(q.old_status), name(q.new_status));
    grades.add_row({"`" + q.case_id + "`", name(q.quantity), change, format_value(q.old_value),
                    format_value(q.new_value), drift_text(q)});
  }
  out += "## Grade and status changes per case\n\n";
  out += grades.n_rows() > 0 ? grades.render() + "\n" : "None.\n\n";

  MarkdownTable rows({"Row", "Grade", "Converging", "Diverging (Eq. 47)"});
  for (const auto& c : r.row_changes) {
    rows.add_row(
        {(c.worse() ? "**worse** `" : "`") + c.row_id + "`",
         fmt::format("{} → {}", grade_text(c.old_grade), grade_text(c.new_grade)),
         fmt::format("{} → {}", flag(c.old_converging, "c"), flag(c.new_converging, "c")),
         fmt::format("{} → {}", flag(c.old_diverging, "yes"), flag(c.new_diverging, "yes"))});
  }
  out += "## Row verdict changes (Table 2 grade on the finest mesh, converging, diverging)\n\n";
  out += rows.n_rows() > 0 ? rows.render() + "\n" : "None.\n\n";

  MarkdownTable drift({"Case", "Quantity", "Baseline", "Current", "Drift (relative)", "Grade"});
  for (const auto* q : drifted) {
    drift.add_row({"`" + q->case_id + "`", name(q->quantity), format_value(q->old_value),
                   format_value(q->new_value), drift_text(*q),
                   q->old_grade == q->new_grade
                       ? name(q->new_grade)
                       : fmt::format("{} → {}", name(q->old_grade), name(q->new_grade))});
  }
  out += "## Value drift, largest first\n\n";
  out += drift.n_rows() > 0 ? drift.render() + "\n" : "None: every common value is identical.\n\n";

  auto list = [](const std::vector<std::string>& ids) {
    std::string text;
    for (const auto& id : ids)
      text += fmt::format("- `{}`\n", id);
    return text.empty() ? std::string("None.\n") : text;
  };
  out += "## Cases only in the current file\n\n" + list(r.only_in_new) + "\n";
  out += "## Cases only in the baseline\n\n" + list(r.only_in_old) + "\n";
  if (!r.quantities_only_in_one.empty())
    out += "## Quantities only in one file\n\n" + list(r.quantities_only_in_one) + "\n";
  return out;
}

}  // namespace cs::reports
