#include "reports/findings/refinement_section.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/findings/variant_rows.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::RowVerdict;

/// Baseline rows, then the variant rows no section of their own shows (a rigid target,
/// overrides), in document order.
std::vector<const RowVerdict*> all_rows(const ResultsIndex& index) {
  std::vector<const RowVerdict*> rows = index.baseline_rows();
  const auto others = other_variant_rows(index);
  rows.insert(rows.end(), others.begin(), others.end());
  return rows;
}

/// "H<sub>p</sub> sigma_c Q4 LMP ss", with the variant ("rigid") when there is one.
std::string row_label(const RowVerdict& row) {
  const std::string variant = variant_of(row.spec);
  return fmt::format("{} {} {} {} {}{}", schema::label(row.spec.problem),
                     schema::to_string(row.quantity), schema::to_string(row.spec.element),
                     schema::to_string(row.spec.algorithm), schema::to_string(row.spec.contact),
                     variant.empty() ? "" : " (" + variant + ")");
}

std::string number_cell(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : std::string(kMissing);
}

std::string percent_cell(const std::optional<double>& v) {
  return v ? format_percent(*v) : std::string(kMissing);
}

/// "asymptotic", or the estimator's reason for no estimate.
std::string estimate_verdict(const schema::ErrorEstimate& e) {
  return e.asymptotic ? "asymptotic" : "not asymptotic: " + e.note;
}

std::string converging_cell(const std::optional<bool>& converging) {
  if (!converging)
    return kMissing;
  return *converging ? "c" : "not c";
}

std::string divergence_cell(const std::optional<schema::DivergenceVerdict>& d) {
  if (!d)
    return kMissing;
  const std::string alpha = d->exponent ? fmt::format(" (α {:.2f})", *d->exponent) : "";
  if (d->diverges)
    return "diverges" + alpha;
  return (d->eq47 ? "Eq. 47 only" : "does not diverge") + alpha;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  if (n == 0)
    return 0.0;
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The estimates beside Table 2′, with the count of rows whose GCI band holds the exact value.
std::string estimates_table(const ResultsIndex& index) {
  MarkdownTable table(
      {"row", "F value", "F error", "p", "Richardson limit", "its error", "GCI", "verdict"});
  int asymptotic = 0, bounded = 0, counted = 0;
  for (const RowVerdict* row : all_rows(index)) {
    if (!row->estimate)
      continue;
    const schema::ErrorEstimate& e = *row->estimate;
    const std::optional<double> exact = index.exact_of(*row);
    std::optional<double> limit_error;
    if (exact && e.richardson && *exact != 0.0)
      limit_error = grading::error_percent(*e.richardson, *exact);
    table.add_row({row_label(*row), format_value(row->values[2]), percent_cell(row->errors[2]),
                   number_cell(e.observed_order, "{:.2f}"), format_value(e.richardson),
                   percent_cell(limit_error),
                   e.gci_percent ? fmt::format("{:.3g} %", *e.gci_percent) : std::string(kMissing),
                   estimate_verdict(e)});
    asymptotic += e.asymptotic ? 1 : 0;
    if (const auto b = exact ? gci_bounds_error(*row, *exact) : std::nullopt) {
      ++counted;
      bounded += *b ? 1 : 0;
    }
  }
  if (table.n_rows() == 0)
    return {};
  return fmt::format(
             "Of {} rows with C, M and F values, {} are in the asymptotic range (differences of "
             "one sign that shrink). The exact value lies within the GCI band of the F value in "
             "{} of those {}.\n\n",
             table.n_rows(), asymptotic, bounded, counted) +
         table.render() + "\n";
}

std::string claim_cell(RefinementClaim claim) {
  switch (claim) {
    case RefinementClaim::not_applicable:
      return "n/a";
    case RefinementClaim::holds:
      return "yes: converges over M-F-VF";
    case RefinementClaim::fails:
      return "no";
    case RefinementClaim::no_vf:
      return "VF missing";
  }
  return {};
}

/// One row of the side-by-side table: errors (or values, singular) per mesh and the verdicts.
std::vector<std::string> refinement_cells(const RowVerdict& row) {
  const schema::RefinementVerdict& vf = *row.refinement;
  const bool singular = row.divergence.has_value() || vf.divergence.has_value();
  std::vector<std::string> cells{row_label(row)};
  for (std::size_t m = 0; m < 3; ++m)
    cells.push_back(singular ? format_value(row.values[m]) : percent_cell(row.errors[m]));
  cells.push_back(singular ? format_value(vf.value) : percent_cell(vf.error));
  if (singular) {
    cells.push_back(divergence_cell(row.divergence));
    cells.push_back(divergence_cell(vf.divergence));
  } else {
    cells.push_back(converging_cell(row.converging));
    cells.push_back(converging_cell(vf.converging));
  }
  cells.push_back(number_cell(vf.pair_order, "{:.2f}"));
  cells.push_back(claim_cell(refinement_claim(row)));
  return cells;
}

std::string claim_summary(const std::vector<const RowVerdict*>& rows) {
  int applies = 0, holds = 0, fails = 0;
  for (const RowVerdict* row : rows) {
    const RefinementClaim c = refinement_claim(*row);
    applies += c == RefinementClaim::not_applicable ? 0 : 1;
    holds += c == RefinementClaim::holds ? 1 : 0;
    fails += c == RefinementClaim::fails ? 1 : 0;
  }
  if (applies == 0) {
    return "The study's \"further mesh refinement would lead to converging results\" applies to "
           "no row run on VF here: every such row graded s or better is already c over C-M-F, "
           "or is graded u.\n\n";
  }
  return fmt::format(
      "The study's \"It is probable that in instances not demarked by c's with satisfactory or "
      "better results, further mesh refinement would lead to converging results\" applies to "
      "{} of the rows run on VF (graded s or better on F, not c over C-M-F). It holds for {} of "
      "them (c over M-F-VF) and fails for {}{}.\n\n",
      applies, holds, fails,
      applies > holds + fails ? fmt::format("; {} lack a VF value", applies - holds - fails) : "");
}

std::string mpc_summary(const ResultsIndex& index) {
  const MpcRefinement m = mpc_refinement(index);
  if (m.rows == 0)
    return {};
  return fmt::format(
      "MPC (the study's IMC) with refinement: in {} of {} MPC rows with F and VF values the "
      "error shrinks from F to VF; the median |error| goes from {:.3g} % on F to {:.3g} % on "
      "VF. The study's \"this performance could be improved with further mesh refinement\" "
      "{}.\n\n",
      m.improved, m.rows, m.median_f, m.median_vf,
      m.improved * 2 > m.rows ? "holds for most of these rows"
                              : "does not hold for most of these rows");
}

std::string refinement_table(const ResultsIndex& index) {
  std::vector<const RowVerdict*> rows;
  for (const RowVerdict* row : all_rows(index)) {
    if (row->refinement)
      rows.push_back(row);
  }
  if (rows.empty()) {
    return "No case of this run is on the fourth mesh VF (h/8); `bash ci/refine.sh` runs "
           "them and adds the C-M-F and M-F-VF verdicts side by side here.\n\n";
  }
  MarkdownTable table(
      {"row", "C", "M", "F", "VF", "C-M-F", "M-F-VF", "p F→VF", "further refinement converges?"});
  for (const RowVerdict* row : rows)
    table.add_row(refinement_cells(*row));
  return fmt::format(
             "### The fourth mesh VF (h/8)\n\n"
             "{} rows have a VF case. Per mesh: the % error (singular rows: the value); "
             "the verdicts over C-M-F and over M-F-VF (c: converging by the study's "
             "rule; singular rows: the strict divergence verdict and α of |s| ~ h^-α); "
             "p F→VF = log2(|e_F| / |e_VF|).\n\n",
             rows.size()) +
         claim_summary(rows) + mpc_summary(index) + table.render() + "\n";
}

}  // namespace

RefinementClaim refinement_claim(const RowVerdict& row) {
  if (!row.grade || !row.converging || *row.converging ||
      schema::is_worse(*row.grade, schema::Grade::s))
    return RefinementClaim::not_applicable;
  if (!row.refinement || !row.refinement->converging)
    return RefinementClaim::no_vf;
  return *row.refinement->converging ? RefinementClaim::holds : RefinementClaim::fails;
}

std::optional<bool> gci_bounds_error(const RowVerdict& row, double exact) {
  if (!row.estimate || !row.estimate->gci_percent || !row.values[2] || *row.values[2] == 0.0)
    return std::nullopt;
  const double error = std::abs(*row.values[2] - exact) / std::abs(*row.values[2]) * 100.0;
  return error <= *row.estimate->gci_percent;
}

MpcRefinement mpc_refinement(const ResultsIndex& index) {
  MpcRefinement out;
  std::vector<double> f, vf;
  for (const RowVerdict* row : all_rows(index)) {
    if (row->spec.algorithm != schema::Algorithm::MPC || !row->refinement ||
        !row->refinement->error || !row->errors[2])
      continue;
    ++out.rows;
    f.push_back(std::abs(*row->errors[2]));
    vf.push_back(std::abs(*row->refinement->error));
    out.improved += vf.back() < f.back() ? 1 : 0;
  }
  out.median_f = median(f);
  out.median_vf = median(vf);
  return out;
}

std::string refinement_section(const ResultsIndex& index) {
  const std::string estimates = estimates_table(index);
  if (estimates.empty())
    return {};
  return "## Error estimates and refinement\n\n"
         "Beside each row of Table 2′ (and each variant row), from its values on C, M, F (h "
         "halving): the observed order p = log2(|f_C − f_M| / |f_M − f_F|), the Richardson limit "
         "f_F + (f_F − f_M)/(2^p − 1) with its error against the exact value, and Roache's grid "
         "convergence index GCI = 1.25 |(f_F − f_M)/f_F| / (2^p − 1) of the F value. There is "
         "no estimate when the sequence is oscillatory, its differences do not shrink, or they "
         "are at round-off.\n\n" +
         estimates + refinement_table(index);
}

}  // namespace cs::reports
