#include "reports/results/results_csv.hpp"

#include <algorithm>
#include <map>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/convergence.hpp"
#include "grading/divergence.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

std::string number(const std::optional<double>& v) {
  return v ? fmt::format("{:.10g}", *v) : std::string();
}

std::string number(double v) {
  return number(finite(v));
}

std::string overrides_text(const schema::CaseSpec& s) {
  std::string out;
  for (const auto& [k, v] : s.overrides)
    out += fmt::format("{}{}={}", out.empty() ? "" : ";", k, v);
  return out;
}

std::string flag(const std::optional<bool>& b) {
  return b ? (*b ? "true" : "false") : "";
}

/// The row verdicts of a case's quantity (C, M or F of some row), to repeat its verdicts on the
/// case's line: the study's c, the noise-aware trend, Eq. 47 and the strict divergence verdict.
using RowsByCase =
    std::map<std::pair<const schema::CaseResult*, schema::Quantity>, const schema::RowVerdict*>;

RowsByCase rows_by_case(const ResultsIndex& index) {
  RowsByCase out;
  for (const auto& r : index.results().rows) {
    for (const auto mesh : kMeshes) {
      if (const schema::CaseResult* c = index.case_of(r, mesh))
        out.emplace(std::pair(c, r.quantity), &r);
    }
  }
  return out;
}

/// The row's verdicts (converging, trend, Eq. 47, strict divergence); none for a row with a
/// case that did not converge: its values are last iterates.
std::vector<std::string> verdict_fields(const ResultsIndex& index, const schema::RowVerdict* r) {
  if (r == nullptr || index.any_not_converged(*r))
    return {"", "", "", ""};
  const auto& e = r->errors;
  const auto& v = r->values;
  std::string trend, eq47, strict;
  if (index.singular(r->spec.problem)) {
    if (v[0] && v[1] && v[2]) {
      const auto d = grading::divergence_verdict(*v[0], *v[1], *v[2]);
      eq47 = flag(d.eq47);
      strict = flag(d.diverges);
    }
  } else if (e[0] && e[1] && e[2]) {
    const double resolution = index.read_resolution_percent(*r, schema::MeshLevel::C);
    trend = schema::to_string(grading::assess_convergence(*e[0], *e[1], *e[2], resolution).trend);
  }
  return {flag(r->converging), trend, eq47, strict};
}

/// The CSV's columns: the case's, its quantity's, then its row's verdicts (verdict_fields).
constexpr std::string_view kColumns =
    "case_id,problem,mesh,element,algorithm,contact,target,recovery,overrides,status,reason,"
    "iterations,wall_seconds,n_elements,n_equations,element_size_h,quantity,value,exact,"
    "error_percent,grade,contact_pressure,study_exact,ansys_value,ansys_table,converging,trend,"
    "eq47,strict_divergence";

/// One line of the CSV: `fields`, each quoted where it must be.
std::string csv_line(const std::vector<std::string>& fields) {
  std::vector<std::string> quoted;
  for (const auto& f : fields)
    quoted.push_back(csv_field(f));
  return fmt::format("{}\n", fmt::join(quoted, ","));
}

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos)
    return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"')
      out += "\"\"";
    else
      out += c;
  }
  return out + "\"";
}

std::string results_csv(const ResultsIndex& index, const schema::StudyReference& study) {
  const RowsByCase rows = rows_by_case(index);
  std::string out = std::string(kColumns) + "\n";
  for (const auto& c : index.results().cases) {
    const schema::CaseSpec& s = c.spec;
    const std::vector<std::string> head{schema::case_id(s),
                                        name_of(s.problem),
                                        name_of(s.mesh),
                                        name_of(s.element),
                                        name_of(s.algorithm),
                                        name_of(s.contact),
                                        name_of(s.target),
                                        name_of(s.recovery),
                                        overrides_text(s),
                                        name_of(c.status),
                                        c.reason,
                                        std::to_string(c.iterations),
                                        number(c.wall_seconds),
                                        std::to_string(c.n_elements),
                                        std::to_string(c.n_equations),
                                        number(c.element_size_h)};
    if (c.quantities.empty()) {
      std::vector<std::string> fields = head;  // and every quantity's column empty
      fields.resize(std::ranges::count(kColumns, ',') + 1);
      out += csv_line(fields);
      continue;
    }
    for (const auto& q : c.quantities) {
      std::string ansys_value, ansys_table;
      if (c.is_baseline()) {
        const auto match =
            study.find_value(s.problem, q.quantity, s.element, s.algorithm, s.contact, s.mesh);
        if (match.value != nullptr) {
          ansys_value = match.value->printed;
          ansys_table = match.value->table;
        }
      }
      const auto row = rows.find({&c, q.quantity});
      const bool converged = c.status == schema::CaseStatus::converged;  // else no grade
      std::vector<std::string> fields = head;
      fields.insert(fields.end(),
                    {name_of(q.quantity), number(q.value), q.singular() ? "inf" : number(q.exact),
                     number(q.error_percent), converged ? name_of(q.grade) : "",
                     number(q.contact_pressure), number(q.study_exact), ansys_value, ansys_table});
      for (auto& f : verdict_fields(index, row == rows.end() ? nullptr : row->second))
        fields.push_back(std::move(f));
      out += csv_line(fields);
    }
  }
  return out;
}

}  // namespace cs::reports
