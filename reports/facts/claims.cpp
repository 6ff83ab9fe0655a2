#include "reports/facts/claims.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "grading/convergence.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::Element;
using schema::Grade;
using schema::ProblemId;

/// The fraction of the rows examined for which a claim must hold to be reproduced as stated;
/// below it but above kRefined, the claim holds with exceptions we name (refined).
constexpr double kReproduced = 1.0;
constexpr double kRefined = 0.75;

ClaimVerdict verdict_of(int n_hold, int n, double reproduced = kReproduced) {
  if (n == 0)
    return ClaimVerdict::not_testable;
  const double share = static_cast<double>(n_hold) / n;
  if (share >= reproduced)
    return ClaimVerdict::reproduced;
  return share >= kRefined ? ClaimVerdict::refined : ClaimVerdict::not_reproduced;
}

/// A claim of two parts: reproduced when both are, not reproduced when the first is not, not
/// testable when the first is not, else refined. A second part with no data leaves the first's.
ClaimVerdict both_parts(ClaimVerdict first, ClaimVerdict second) {
  if (second == ClaimVerdict::not_testable || first == second)
    return first;
  if (first == ClaimVerdict::not_reproduced || first == ClaimVerdict::not_testable)
    return first;
  return ClaimVerdict::refined;
}

bool good_or_better(const RowFacts& f) {
  return f.grade && !schema::is_worse(*f.grade, Grade::g);
}

/// A patch test whose nodes do not meet (the problem record's situation).
bool mismatched(const RowFacts& f) {
  return f.situation == schema::Situation::mismatched_patch ||
         f.situation == schema::Situation::mismatched_patch_equal_moduli;
}

bool patch_test(const RowFacts& f) {
  return f.situation == schema::Situation::matched_patch || mismatched(f);
}

bool small_radius(ProblemId p) {
  return p == ProblemId::S_1_3 || p == ProblemId::S_1_7;
}

std::string row_name(const RowFacts& f) {
  return fmt::format("{} {} {} {}", schema::label(f.problem), schema::to_string(f.element),
                     f.option.label(), format_error_resolved(*f.errors[2]));
}

void add_example(ClaimEvidence& c, const std::string& text) {
  if (std::count(c.examples.begin(), c.examples.end(), ';') >= 3)
    return;
  c.examples += (c.examples.empty() ? "" : "; ") + text;
}

using TwinKey = std::tuple<ProblemId, schema::Quantity, Element, Algorithm, ContactKind>;

std::map<TwinKey, const RowFacts*> by_key(const std::vector<RowFacts>& rows) {
  std::map<TwinKey, const RowFacts*> out;
  for (const auto& f : rows)
    out[{f.problem, f.quantity, f.element, f.option.algorithm, f.option.contact}] = &f;
  return out;
}

/// AL = PM and LMP = PLM: the pairs' values agree to the printed digits on every mesh.
ClaimEvidence same_results(const std::vector<RowFacts>& rows, Algorithm a, Algorithm b,
                           const char* key) {
  ClaimEvidence c{.key = key};
  const auto index = by_key(rows);
  double largest = 0.0;
  for (const auto& f : rows) {
    if (f.option.algorithm != a)
      continue;
    const auto twin = index.find({f.problem, f.quantity, f.element, b, f.option.contact});
    if (twin == index.end())
      continue;
    ++c.n;
    if (coincide(*f.row, *twin->second->row)) {
      ++c.n_hold;
      continue;
    }
    const double d = std::abs(*f.errors[2] - *twin->second->errors[2]);
    largest = std::max(largest, d);
    add_example(c, fmt::format("{} {} {} ({} points on F)", schema::label(f.problem),
                               schema::to_string(f.element), schema::to_string(f.option.contact),
                               fmt::format("{:.3g}", d)));
  }
  if (c.n_hold < c.n)
    c.figure = largest;
  c.verdict = verdict_of(c.n_hold, c.n, 0.95);
  return c;
}

/// ss and ns give essentially the same results for LMP, PLM and MPC: the same grade on F.
ClaimEvidence ss_equals_ns(const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "ss_equals_ns"};
  const auto index = by_key(rows);
  double largest = 0.0;
  for (const auto& f : rows) {
    if (f.option.contact != ContactKind::ss ||
        family_of(f.option.algorithm) == OptionFamily::penalty)
      continue;
    const auto twin =
        index.find({f.problem, f.quantity, f.element, f.option.algorithm, ContactKind::ns});
    if (twin == index.end())
      continue;
    if (!f.evidence() || !twin->second->evidence()) {
      ++c.n_excluded;
      continue;
    }
    ++c.n;
    largest = std::max(largest, std::abs(*f.errors[2] - *twin->second->errors[2]));
    if (f.grade == twin->second->grade)
      ++c.n_hold;
    else
      add_example(c, fmt::format("{} vs ns {}", row_name(f),
                                 format_error_resolved(*twin->second->errors[2])));
  }
  c.figure = largest;
  c.verdict = verdict_of(c.n_hold, c.n);
  return c;
}

/// Whether |a| exceeds |b| by more than the study's printed resolution: closer F errors are a tie
/// (e.g. two patch-test errors of 3.3e-12 % and 3.4e-12 %, which round-off orders either way).
bool clearly_larger(double a, double b) {
  return std::abs(a) > std::abs(b) + grading::kErrorResolutionPercent;
}

/// A Table 2 trend: the selected evidence rows are g or better on F (n_hold of n), and each one's
/// twin (`twin_of` gives its key) has the clearly larger |F error| (n2_hold of n2).
template <class Select, class Twin>
ClaimEvidence trend_claim(const std::vector<RowFacts>& rows, const char* key, Select select,
                          Twin twin_of) {
  ClaimEvidence c{.key = key};
  const auto index = by_key(rows);
  for (const auto& f : rows) {
    if (!select(f))
      continue;
    if (!f.evidence()) {
      ++c.n_excluded;
      continue;
    }
    ++c.n;
    if (good_or_better(f))
      ++c.n_hold;
    else
      add_example(c, row_name(f));
    const auto twin = index.find(twin_of(f));
    if (twin == index.end() || !twin->second->evidence())
      continue;
    ++c.n2;
    if (clearly_larger(*twin->second->errors[2], *f.errors[2]))
      ++c.n2_hold;
  }
  c.verdict = both_parts(verdict_of(c.n_hold, c.n), verdict_of(c.n2_hold, c.n2, kRefined));
  return c;
}

/// Trend 1: AL (and PM) ss Q4 is good or excellent except for S(1/3), S(1/7); ns is worse.
ClaimEvidence trend_penalty(const std::vector<RowFacts>& rows) {
  return trend_claim(
      rows, "trend_penalty",
      [](const RowFacts& f) {
        return f.option.algorithm == Algorithm::AL && f.option.contact == ContactKind::ss &&
               f.element == Element::Q4 && !small_radius(f.problem);
      },
      [](const RowFacts& f) {
        return TwinKey{f.problem, f.quantity, f.element, Algorithm::AL, ContactKind::ns};
      });
}

/// Trend 2: LMP, PLM with Q4 good or excellent except with mismatched nodes; Q8 worse.
ClaimEvidence trend_multiplier(const std::vector<RowFacts>& rows) {
  return trend_claim(
      rows, "trend_multiplier",
      [](const RowFacts& f) {
        return f.option.algorithm == Algorithm::LMP && f.element == Element::Q4 && !mismatched(f);
      },
      [](const RowFacts& f) {
        return TwinKey{f.problem, f.quantity, Element::Q8, f.option.algorithm, f.option.contact};
      });
}

/// Trend 3: MPC is uniformly unsatisfactory; the patch tests apart (n2). A row that fails its
/// interface checks, did not converge or is the luck of one mesh is not a satisfactory result
/// whatever its grade: it counts for the claim (n_excluded of n_hold), never as g or better.
ClaimEvidence mpc_unsatisfactory(const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "mpc_unsatisfactory"};
  for (const auto& f : rows) {
    if (f.option.algorithm != Algorithm::MPC)
      continue;
    if (!f.evidence() && !patch_test(f)) {
      ++c.n;
      ++c.n_hold;
      ++c.n_excluded;
      continue;
    }
    if (patch_test(f)) {
      if (!f.evidence())
        continue;
      ++c.n2;
      c.n2_hold += good_or_better(f) ? 0 : 1;
      continue;
    }
    ++c.n;
    if (f.grade == Grade::u || f.grade == Grade::s)
      ++c.n_hold;
    else
      add_example(c, row_name(f));
  }
  c.verdict = verdict_of(c.n_hold, c.n);
  return c;
}

/// The median of `v` (0 when empty).
double median_of(std::vector<double> v) {
  if (v.empty())
    return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// IMC fastest: per model (problem, F, element, discretization), is MPC's case time below the
/// fastest other option's by more than the run's timing noise? The noise is what two options
/// that solve the same equations (LMP and PLM, frictionless) differ by in one model: the median
/// of |t_LMP / t_PLM - 1| over the models (figure2, in %; 0 when no model has both). n_hold:
/// faster beyond it; n2_hold: slower beyond it; n2: within it, a tie. figure: the median of
/// t_MPC / t_fastest other.
ClaimEvidence mpc_fastest(const ResultsIndex& index) {
  ClaimEvidence c{.key = "mpc_fastest"};
  using Model = std::tuple<ProblemId, Element, ContactKind>;
  std::map<Model, std::map<Algorithm, double>> times;
  for (const auto& r : index.results().cases) {
    if (r.spec.mesh != schema::MeshLevel::F || !r.is_baseline() ||
        r.status != schema::CaseStatus::converged)
      continue;
    times[{r.spec.problem, r.spec.element, r.spec.contact}][r.spec.algorithm] = r.wall_seconds;
  }
  std::vector<double> same_work;
  for (const auto& [model, t] : times) {
    const auto lmp = t.find(Algorithm::LMP), plm = t.find(Algorithm::PLM);
    if (lmp != t.end() && plm != t.end() && plm->second > 0)
      same_work.push_back(std::abs(lmp->second / plm->second - 1.0));
  }
  const double noise = median_of(same_work);
  c.figure2 = 100.0 * noise;
  std::vector<double> ratios;
  for (const auto& [model, by_algorithm] : times) {
    const auto mpc = by_algorithm.find(Algorithm::MPC);
    if (mpc == by_algorithm.end() || by_algorithm.size() < 2)
      continue;
    double fastest_other = INFINITY;
    for (const auto& [a, t] : by_algorithm)
      fastest_other = a == Algorithm::MPC ? fastest_other : std::min(fastest_other, t);
    if (!(fastest_other > 0))
      continue;
    const double ratio = mpc->second / fastest_other;
    ++c.n;
    ratios.push_back(ratio);
    if (ratio * (1.0 + noise) < 1.0)
      ++c.n_hold;
    else if (ratio > 1.0 + noise)
      ++c.n2_hold;
    else
      ++c.n2;
  }
  if (!ratios.empty())
    c.figure = median_of(ratios);
  c.verdict = verdict_of(c.n_hold, c.n, kRefined);
  if (c.verdict == ClaimVerdict::refined)
    c.verdict = ClaimVerdict::not_reproduced;
  return c;
}

/// Little difference between Q4 and Q8 where the algorithm works well: same grade.
ClaimEvidence element_order(const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "element_order"};
  const auto index = by_key(rows);
  for (const auto& f : rows) {
    if (f.element != Element::Q4)
      continue;
    const auto q8 =
        index.find({f.problem, f.quantity, Element::Q8, f.option.algorithm, f.option.contact});
    if (q8 == index.end())
      continue;
    if (!f.evidence() || !q8->second->evidence()) {
      ++c.n_excluded;
      continue;
    }
    if (!good_or_better(f) && !good_or_better(*q8->second))
      continue;  // the algorithm does not work well here
    ++c.n;
    if (f.grade == q8->second->grade)
      ++c.n_hold;
    else
      add_example(c, fmt::format("{} vs Q8 {}", row_name(f),
                                 format_error_resolved(*q8->second->errors[2])));
    c.n2 += clearly_larger(*q8->second->errors[2], *f.errors[2]) ? 1 : 0;
  }
  c.verdict = verdict_of(c.n_hold, c.n, kRefined);
  return c;
}

/// Rows s or better without c on F: does a converged VF case bring them closer
/// (grading::refinement_step)? Closer rows are n_hold, settled ones n2 (a plateau or a round-off
/// level error). Rows that are not credible or luck on F are not evidence: left out with those
/// whose VF case did not converge.
ClaimEvidence refinement(const ResultsIndex& index, const std::vector<RowFacts>& rows, bool mpc) {
  ClaimEvidence c{.key = mpc ? "mpc_refinement" : "refinement"};
  for (const auto& f : rows) {
    if ((f.option.algorithm == Algorithm::MPC) != mpc || !f.grade)
      continue;
    if (!mpc && (f.study_c || *f.grade == Grade::u))
      continue;
    const auto& vf = f.row->refinement;
    if (!vf)
      continue;
    const schema::CaseResult* vf_case = index.case_of(*f.row, schema::MeshLevel::VF);
    if (!vf_case || vf_case->status != schema::CaseStatus::converged || !vf->error || !f.credible ||
        f.luck) {
      ++c.n_excluded;
      continue;
    }
    ++c.n;
    const auto step = grading::refinement_step(
        *f.errors[2], *vf->error, index.read_resolution_percent(*f.row, schema::MeshLevel::F));
    if (step == grading::RefinementStep::closer)
      ++c.n_hold;
    else if (step == grading::RefinementStep::settled)
      ++c.n2;
    else
      add_example(c, fmt::format("{} → VF {}", row_name(f), format_error_resolved(*vf->error)));
  }
  // Results that settle have converged (claim 9); only a real improvement shows that MPC's
  // performance could improve (claim 10).
  c.verdict =
      mpc ? verdict_of(c.n_hold, c.n - c.n2, kRefined) : verdict_of(c.n_hold + c.n2, c.n, kRefined);
  return c;
}

/// Eq. 47 holds for all contact elements and options; the strict verdict beside it.
ClaimEvidence divergence(const std::vector<DivergenceFacts>& singular) {
  ClaimEvidence c{.key = "divergence"};
  for (const auto& d : singular) {
    ++c.n;
    c.n_hold += d.eq47 ? 1 : 0;
    c.n2_hold += d.strict ? 1 : 0;
    if (!d.eq47)
      add_example(c, fmt::format("{} {} {}", schema::label(d.problem), schema::to_string(d.element),
                                 d.option.label()));
  }
  c.n2 = c.n;
  c.verdict = verdict_of(c.n_hold, c.n);
  return c;
}

/// Closing: AL, PM ss good for most problems; LMP, PLM fine wherever nodes can be aligned.
ClaimEvidence closing(const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "closing"};
  for (const auto& f : rows) {
    const bool penalty_ss = family_of(f.option.algorithm) == OptionFamily::penalty &&
                            f.option.contact == ContactKind::ss;
    const bool multiplier_aligned =
        family_of(f.option.algorithm) == OptionFamily::multiplier && !mismatched(f);
    if (!penalty_ss && !multiplier_aligned)
      continue;
    if (!f.evidence()) {
      ++c.n_excluded;
      continue;
    }
    if (penalty_ss) {
      ++c.n;
      c.n_hold += good_or_better(f) ? 1 : 0;
    } else {
      ++c.n2;
      c.n2_hold += good_or_better(f) ? 1 : 0;
      if (!good_or_better(f))
        add_example(c, row_name(f));
    }
  }
  c.verdict = both_parts(verdict_of(c.n_hold, c.n, kRefined), verdict_of(c.n2_hold, c.n2));
  return c;
}

}  // namespace

std::string to_string(ClaimVerdict v) {
  switch (v) {
    case ClaimVerdict::reproduced:
      return "reproduced";
    case ClaimVerdict::refined:
      return "refined";
    case ClaimVerdict::not_reproduced:
      return "not reproduced";
    case ClaimVerdict::not_testable:
      return "not testable here";
  }
  return {};
}

std::vector<ClaimEvidence> study_claims(const ResultsIndex& index,
                                        const std::vector<RowFacts>& all_rows,
                                        const std::vector<DivergenceFacts>& singular) {
  // The study's claims are about its own battery: problems beyond it (equal moduli, friction,
  // conformal fits) neither support nor refute them.
  std::vector<RowFacts> rows;
  for (const auto& f : all_rows) {
    const schema::ProblemRecord* p = index.problem(f.problem);
    if (p != nullptr && !p->study_tables.empty())
      rows.push_back(f);
  }
  return {same_results(rows, Algorithm::AL, Algorithm::PM, "al_equals_pm"),
          same_results(rows, Algorithm::LMP, Algorithm::PLM, "lmp_equals_plm"),
          ss_equals_ns(rows),
          trend_penalty(rows),
          trend_multiplier(rows),
          mpc_unsatisfactory(rows),
          mpc_fastest(index),
          element_order(rows),
          refinement(index, rows, false),
          refinement(index, rows, true),
          divergence(singular),
          closing(rows)};
}

}  // namespace cs::reports
