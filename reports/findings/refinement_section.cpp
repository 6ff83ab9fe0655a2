#include "reports/findings/refinement_section.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>
#include <gsl/gsl_statistics_double.h>

#include "grading/accuracy.hpp"
#include "grading/richardson.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/findings/variant_rows.hpp"
#include "reports/render/template_text.hpp"
#include "reports/results/results_csv.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::RowVerdict;
using Fields = kainjow::mustache::object;

/// Baseline rows, then the variant rows no section of their own shows (a rigid target,
/// overrides), in document order.
std::vector<const RowVerdict*> all_rows(const ResultsIndex& index) {
  std::vector<const RowVerdict*> rows = index.baseline_rows();
  const auto others = other_variant_rows(index);
  rows.insert(rows.end(), others.begin(), others.end());
  return rows;
}

/// "H<sub>p</sub> σ̄<sub>c</sub> Q4 LMP ss", with the variant ("rigid") when there is one.
std::string row_label(const RowVerdict& row) {
  const std::string variant = variant_of(row.spec);
  return fmt::format("{} {} {} {}{}", schema::label(row.spec.problem), schema::label(row.quantity),
                     schema::to_string(row.spec.element),
                     Option{row.spec.algorithm, row.spec.contact}.label(),
                     variant.empty() ? "" : " (" + variant + ")");
}

/// The trend of three errors, `resolution` the quantity's own on the coarsest of them.
std::optional<grading::ConvergenceAssessment> trend_of(const std::optional<double>& a,
                                                       const std::optional<double>& b,
                                                       const std::optional<double>& c,
                                                       double resolution) {
  if (!a || !b || !c)
    return std::nullopt;
  return grading::assess_convergence(*a, *b, *c, resolution);
}

std::string trend_cell(const std::optional<grading::ConvergenceAssessment>& t) {
  return t ? std::string(schema::label(t->trend)) : std::string(kMissing);
}

/// The VF error, marked unless its case converged.
std::string vf_cell(const VfRow& v) {
  if (v.vf == MeshState::failed || v.vf == MeshState::missing)
    return v.vf == MeshState::failed ? "failed" : kMissing;
  const std::string value = format_error_resolved(v.row->refinement->error);
  return v.vf == MeshState::converged ? value : value + " (not converged)";
}

/// The study's claim on a row as the table and estimates.csv print it.
std::string claim_cell(bool applies, VfJudgement j) {
  constexpr const char* kText[] = {"holds",
                                   "holds",
                                   "fails: a plateau (bias)",
                                   "fails",
                                   "open: not evidence on F",
                                   "open: VF not converged",
                                   "open: no VF"};
  return applies ? kText[static_cast<int>(j)] : "n/a";
}

void add_estimate(EstimateSummary& s, std::vector<double>& gci, const ResultsIndex& index,
                  const RowVerdict& row) {
  const RowFacts f = facts_of_row(index, row);
  if (!f.fine_converged || !f.credible) {
    ++s.not_credible;  // its F value is no evidence of how the option converges
    return;
  }
  ++s.rows;
  const grading::TrustedEstimate t = grading::trusted_estimate(row);
  if (!t.estimate)
    return;
  ++s.asymptotic;
  if (t.estimate->gci_percent)
    gci.push_back(*t.estimate->gci_percent);
  const auto exact = index.exact_of(row);
  if (const auto b = exact ? grading::gci_bounds_error(row, *exact) : std::nullopt) {
    ++s.with_exact;
    s.bounded += *b ? 1 : 0;
  }
}

void add_vf(RefinementFacts& f, const ResultsIndex& index, const RowVerdict& row) {
  VfRow v{&row, index.state(row, schema::MeshLevel::VF), {}, {}, {}};
  if (index.singular(row.spec.problem)) {
    const bool counted = v.vf == MeshState::converged && row.refinement->divergence;
    f.singular_vf += counted ? 1 : 0;
    f.singular_vf_diverges += counted && row.refinement->divergence->diverges ? 1 : 0;
    return;
  }
  const double on_m = index.read_resolution_percent(row, schema::MeshLevel::M);
  v.trend_cmf = trend_of(row.errors[0], row.errors[1], row.errors[2],
                         index.read_resolution_percent(row, schema::MeshLevel::C));
  v.trend_mfvf = trend_of(row.errors[1], row.errors[2], row.refinement->error, on_m);
  v.claim_applies = refinement_claim_applies(row);
  v.judgement = vf_judgement(index, row);
  f.vf_rows.push_back(v);
}

/// The claim's and MPC's tallies over the nonsingular rows with a VF case, and MPC's medians.
void add_tallies(RefinementFacts& f, const ResultsIndex& index) {
  std::vector<const RowVerdict*> applies, mpc;
  std::vector<double> on_f, on_vf;
  for (const VfRow& v : f.vf_rows) {
    if (v.claim_applies)
      applies.push_back(v.row);
    if (v.row->spec.algorithm != schema::Algorithm::MPC || !v.row->errors[2])
      continue;
    mpc.push_back(v.row);
    if (v.judgement == VfJudgement::converges || v.judgement == VfJudgement::plateau ||
        v.judgement == VfJudgement::fails) {
      on_f.push_back(std::abs(*v.row->errors[2]));
      on_vf.push_back(std::abs(*v.row->refinement->error));
    }
  }
  f.claim = tally_vf(index, applies);
  f.mpc = tally_vf(index, mpc);
  f.mpc_median_f = on_f.empty() ? 0.0 : gsl_stats_median(on_f.data(), 1, on_f.size());
  f.mpc_median_vf = on_vf.empty() ? 0.0 : gsl_stats_median(on_vf.data(), 1, on_vf.size());
}

std::string percent(int part, int whole) {
  return whole == 0 ? std::string(kMissing) : fmt::format("{:.0f} %", 100.0 * part / whole);
}

std::string summary_table(const std::vector<EstimateSummary>& summaries) {
  constexpr Align r = Align::right;
  MarkdownTable t(
      {"Problem", "Rows", "With an estimate", "Exact value inside the GCI band", "Median GCI"},
      {Align::left, r, r, r, r});
  for (const auto& s : summaries)
    t.add_row({std::string(schema::label(s.problem)), std::to_string(s.rows),
               std::to_string(s.asymptotic), fmt::format("{} of {}", s.bounded, s.with_exact),
               s.median_gci ? fmt::format("{:.3g} %", *s.median_gci) : kMissing});
  return t.render();
}

std::string vf_table(const std::vector<VfRow>& rows) {
  constexpr Align r = Align::right, c = Align::center;
  MarkdownTable t(
      {"Row", "C", "M", "F", "VF", "Trend C-M-F", "Trend M-F-VF", "Further refinement converges"},
      {Align::left, r, r, r, r, c, c, Align::left});
  for (const VfRow& v : rows) {
    const auto& e = v.row->errors;
    t.add_row({row_label(*v.row), format_error_resolved(e[0]), format_error_resolved(e[1]),
               format_error_resolved(e[2]), vf_cell(v), trend_cell(v.trend_cmf),
               trend_cell(v.trend_mfvf), claim_cell(v.claim_applies, v.judgement)});
  }
  return t.render();
}

/// Where the claim's rows settle at a larger error, grouped: "S(1/3) a_FE Q4 (5), P_a sigma_c Q8
/// (2)", in the rows' order, so that a reader can tell one bias from another.
std::string plateau_where(const std::vector<VfRow>& rows) {
  std::vector<std::pair<std::string, int>> groups;
  for (const VfRow& v : rows) {
    if (!v.claim_applies || v.judgement != VfJudgement::plateau)
      continue;
    const schema::CaseSpec& s = v.row->spec;
    const std::string key =
        fmt::format("{} {} {}", schema::label(s.problem), schema::label(v.row->quantity),
                    schema::to_string(s.element));
    const auto it = std::ranges::find(groups, key, &std::pair<std::string, int>::first);
    if (it == groups.end())
      groups.emplace_back(key, 1);
    else
      ++it->second;
  }
  std::vector<std::string> parts;
  for (const auto& [key, n] : groups)
    parts.push_back(fmt::format("{} ({})", key, n));
  return join_words(parts, ", ");
}

std::string csv_number(const std::optional<double>& v) {
  return v ? fmt::format("{:.10g}", *v) : std::string();
}

std::string csv_line(const ResultsIndex& index, const RowVerdict& row) {
  const grading::TrustedEstimate t = grading::trusted_estimate(row);
  const schema::ErrorEstimate e = t.estimate ? *t.estimate : schema::ErrorEstimate{.note = t.note};
  const auto exact = index.exact_of(row);
  std::optional<double> limit_error;
  if (exact && e.richardson && *exact != 0.0)
    limit_error = grading::error_percent(*e.richardson, *exact);
  const auto bounded = exact && t.estimate ? grading::gci_bounds_error(row, *exact) : std::nullopt;
  std::string out = fmt::format(
      "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}", csv_field(row.id), csv_number(row.values[0]),
      csv_number(row.values[1]), csv_number(row.values[2]), csv_number(row.errors[2]),
      at_round_off(row) ? 1 : 0, e.asymptotic ? 1 : 0, csv_field(e.note),
      csv_number(e.observed_order), csv_number(e.richardson), csv_number(limit_error),
      csv_number(e.gci_percent), bounded ? (*bounded ? "1" : "0") : "", csv_number(exact),
      csv_field(variant_of(row.spec)));
  // Whether the row is evidence on F (RowFacts::evidence: converged, credible, not the luck of
  // one mesh): an estimate of a row that is not says nothing of the option.
  const std::string evidence = facts_of_row(index, row).evidence() ? "1" : "0";
  if (!row.refinement)
    return out + ",,,,,," + evidence + "\n";
  const MeshState vf = index.state(row, schema::MeshLevel::VF);
  const double on_m = index.read_resolution_percent(row, schema::MeshLevel::M);
  const auto trend = trend_of(row.errors[1], row.errors[2], row.refinement->error, on_m);
  constexpr const char* kState[] = {"missing", "failed", "not_converged", "converged"};
  return out +
         fmt::format(",{},{},{},{},{},{}\n", csv_number(row.refinement->value),
                     csv_number(row.refinement->error), kState[static_cast<int>(vf)],
                     trend ? schema::to_string(trend->trend) : "",
                     csv_field(claim_cell(refinement_claim_applies(row), vf_judgement(index, row))),
                     evidence);
}

}  // namespace

bool at_round_off(const RowVerdict& row) {
  return std::all_of(row.errors.begin(), row.errors.end(), [](const std::optional<double>& e) {
    return e && std::abs(*e) < schema::kErrorNoiseFloorPercent;
  });
}

RefinementFacts refinement_facts(const ResultsIndex& index) {
  RefinementFacts f;
  for (const schema::ProblemRecord* p : index.problems()) {
    EstimateSummary s;
    s.problem = p->id;
    std::vector<double> gci;
    for (const RowVerdict* row : all_rows(index)) {
      if (row->spec.problem != p->id || !row->estimate)
        continue;
      if (at_round_off(*row))
        ++f.round_off;
      else
        add_estimate(s, gci, index, *row);
    }
    if (!gci.empty())
      s.median_gci = gsl_stats_median(gci.data(), 1, gci.size());
    if (s.rows + s.not_credible > 0)
      f.problems.push_back(s);
  }
  for (const RowVerdict* row : all_rows(index)) {
    if (row->refinement)
      add_vf(f, index, *row);
  }
  add_tallies(f, index);
  return f;
}

std::string estimates_csv(const ResultsIndex& index) {
  std::string out =
      "row_id,value_C,value_M,value_F,error_F_percent,round_off,asymptotic,note,order,"
      "richardson,richardson_error_percent,gci_percent,exact_in_gci_band,exact,variant,"
      "value_VF,error_VF_percent,status_VF,trend_MFVF,further_refinement_claim,evidence_F\n";
  bool any = false;
  for (const RowVerdict* row : all_rows(index)) {
    if (row->estimate)
      out += csv_line(index, *row);
    any = any || row->estimate;
  }
  return any ? out : std::string();
}

std::string refinement_section(const ResultsIndex& index) {
  const RefinementFacts f = refinement_facts(index);
  if (f.problems.empty() && f.round_off == 0)
    return {};
  int rows = 0, asymptotic = 0, bounded = 0, with_exact = 0, not_credible = 0;
  for (const auto& s : f.problems) {
    rows += s.rows;
    not_credible += s.not_credible;
    asymptotic += s.asymptotic;
    bounded += s.bounded;
    with_exact += s.with_exact;
  }
  std::vector<VfRow> shown;
  std::copy_if(f.vf_rows.begin(), f.vf_rows.end(), std::back_inserter(shown),
               [](const VfRow& v) { return v.claim_applies; });
  const auto n = [](int v) { return std::to_string(v); };
  Fields d{{"round_off", n(f.round_off)},
           {"not_credible", n(not_credible)},
           {"rows", n(rows)},
           {"asymptotic", n(asymptotic)},
           {"bounded", n(bounded)},
           {"with_exact", n(with_exact)},
           {"bounded_share", percent(bounded, with_exact)},
           // Roache's factor 1.25 is meant to cover the exact value about 95 % of the time.
           {"band_understates", with_exact > 0 && bounded < 0.95 * with_exact},
           {"problems", summary_table(f.problems)},
           {"has_vf", !f.vf_rows.empty() || f.singular_vf > 0},
           {"n_vf", n(static_cast<int>(f.vf_rows.size()))},
           {"applies", n(std::accumulate(f.claim.by.begin(), f.claim.by.end(), 0))},
           {"holds", n(f.claim[VfJudgement::converges] + f.claim[VfJudgement::at_resolution])},
           {"judged", n(f.claim.trends() + f.claim[VfJudgement::at_resolution])},
           {"plateau", count_or_false(f.claim[VfJudgement::plateau])},
           {"plateau_where", plateau_where(shown)},
           {"not_evidence", count_or_false(f.claim[VfJudgement::not_evidence])},
           {"vf_not_converged", count_or_false(f.claim[VfJudgement::vf_not_converged])},
           {"vf_rows", vf_table(shown)},
           {"has_shown", !shown.empty()}};
  const VfTally& m = f.mpc;
  if (m.trends() + m[VfJudgement::at_resolution] + m[VfJudgement::not_evidence] > 0)
    d["mpc"] = Fields{{"judged", n(m.trends())},
                      {"converges", n(m[VfJudgement::converges])},
                      {"plateau", n(m[VfJudgement::plateau])},
                      {"fails", n(m[VfJudgement::fails])},
                      {"at_resolution", n(m[VfJudgement::at_resolution])},
                      {"not_evidence", n(m[VfJudgement::not_evidence])},
                      {"not_converged", n(m[VfJudgement::vf_not_converged])},
                      {"has_judged", m.trends() > 0},
                      {"median_f", fmt::format("{:.3g}", f.mpc_median_f)},
                      {"median_vf", fmt::format("{:.3g}", f.mpc_median_vf)},
                      {"mostly", m[VfJudgement::converges] * 2 > m.trends()}};
  if (f.singular_vf > 0)
    d["singular"] = Fields{{"n", n(f.singular_vf)}, {"diverges", n(f.singular_vf_diverges)}};
  return render_template(templates::refinement_section, d);
}

}  // namespace cs::reports
