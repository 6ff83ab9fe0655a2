#include "reports/facts/claims.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <set>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gsl/gsl_statistics_double.h>

#include "grading/convergence.hpp"
#include "reports/bench/bench_results.hpp"
#include "reports/facts/refinement_claim.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::Element;
using schema::Grade;
using schema::ProblemId;

/// The fraction of the rows examined for which a part of a claim must hold to be reproduced as
/// stated; below it but at or above kRefined (the exceptions a minority, named), the part holds
/// with exceptions (refined); below kRefined it is not reproduced.
constexpr double kReproduced = 1.0;
constexpr double kRefined = 0.75;

/// The verdict of one part of a claim that holds for n_hold of n rows (see kRefined).
ClaimVerdict verdict_of(int n_hold, int n, double reproduced = kReproduced) {
  if (n == 0)
    return ClaimVerdict::not_testable;
  const double share = static_cast<double>(n_hold) / n;
  if (share >= reproduced)
    return ClaimVerdict::reproduced;
  return share >= kRefined ? ClaimVerdict::refined : ClaimVerdict::not_reproduced;
}

/// The verdict of a claim of several parts: the worst of its parts' (reproduced, then refined,
/// then not reproduced), so a part that holds only in a minority makes the claim not
/// reproduced whatever the others show. A part with no data (not testable) leaves the others'
/// verdict, and the claim says so (part_not_testable); a claim with no testable part is not
/// testable.
void set_verdict_of_parts(ClaimEvidence& c, std::initializer_list<ClaimVerdict> parts) {
  ClaimVerdict worst = ClaimVerdict::not_testable;
  for (const ClaimVerdict v : parts) {
    if (v != ClaimVerdict::not_testable && (worst == ClaimVerdict::not_testable || v > worst))
      worst = v;
  }
  c.verdict = worst;
  c.part_not_testable = worst != ClaimVerdict::not_testable &&
                        std::ranges::find(parts, ClaimVerdict::not_testable) != parts.end();
}

/// A stated exception ("except for ...") checked on its own rows: the claim is refined when the
/// exception does not show in all of them (they are g or better after all), not testable
/// without such rows.
ClaimVerdict exception_verdict(int n_holds, int n) {
  if (n == 0)
    return ClaimVerdict::not_testable;
  return n_holds == n ? ClaimVerdict::reproduced : ClaimVerdict::refined;
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
  return fmt::format("{} {} {} {} {}", schema::label(f.problem), schema::to_string(f.quantity),
                     schema::to_string(f.element), f.option.label(),
                     format_error_resolved(*f.errors[2]));
}

/// A row's errors over M, F and VF, the window the refinement rule judges: "H<sub>p</sub>
/// sigma_h Q8 AL ss: M −0.23 % → F −0.30 % → VF −0.30 %".
std::string refinement_example(const RowFacts& f) {
  return fmt::format("{} {} {} {}: M {} → F {} → VF {}", schema::label(f.problem),
                     schema::to_string(f.quantity), schema::to_string(f.element), f.option.label(),
                     format_error_resolved(*f.errors[1]), format_error_resolved(*f.errors[2]),
                     format_error_resolved(*f.row->refinement->error));
}

/// Appends `text` to a list of examples, four at most; counts the others in `more`.
void add_example(std::string& examples, int& more, const std::string& text) {
  if (std::count(examples.begin(), examples.end(), ';') >= 3) {
    ++more;
    return;
  }
  examples += (examples.empty() ? "" : "; ") + text;
}

void add_example(ClaimEvidence& c, const std::string& text) {
  add_example(c.examples, c.examples_more, text);
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

/// An F error the study's printed digits cannot tell from 0 (a patch test at round-off).
bool at_resolution(double e) {
  return std::abs(e) <= grading::kErrorResolutionPercent;
}

/// ss and ns give essentially the same results for LMP, PLM and MPC: the same grade on F, in two
/// parts, LMP and PLM (n_hold of n, largest |e_ss - e_ns| figure) and IMC (n2_hold of n2,
/// figure2); IMC pairs exact on both to the printed digits (the patch tests, where any tie is
/// exact) show nothing and are left out (n2_exact). The verdict is the worse part's.
ClaimEvidence ss_equals_ns(const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "ss_equals_ns"};
  const auto index = by_key(rows);
  double largest_lm = 0.0, largest_mpc = 0.0;
  std::set<Algorithm> run;  // of the first part's algorithms
  for (const auto& f : rows) {
    if (f.option.contact != ContactKind::ss ||
        family_of(f.option.algorithm) == OptionFamily::penalty)
      continue;
    const auto twin =
        index.find({f.problem, f.quantity, f.element, f.option.algorithm, ContactKind::ns});
    if (twin == index.end())
      continue;
    c.part2_run = c.part2_run || f.option.algorithm == Algorithm::MPC;
    if (!f.accuracy_evidence() || !twin->second->accuracy_evidence()) {
      ++c.n_excluded;
      continue;
    }
    const double e_ns = *twin->second->errors[2];
    const bool same = f.grade == twin->second->grade;
    const std::string example =
        fmt::format("{} vs ns {}", row_name(f), format_error_resolved(e_ns));
    if (f.option.algorithm != Algorithm::MPC) {  // LMP, PLM: the first part
      run.insert(f.option.algorithm);
      ++c.n;
      largest_lm = std::max(largest_lm, std::abs(*f.errors[2] - e_ns));
      c.n_hold += same ? 1 : 0;
      if (!same)
        add_example(c, example);
    } else if (at_resolution(*f.errors[2]) && at_resolution(e_ns)) {
      ++c.n2_exact;  // a patch test at round-off: any tie is exact, nothing to compare
    } else {         // IMC: the second part
      ++c.n2;
      largest_mpc = std::max(largest_mpc, std::abs(*f.errors[2] - e_ns));
      c.n2_hold += same ? 1 : 0;
      if (!same)
        add_example(c.examples2, c.examples2_more, example);
    }
  }
  c.members = join_words(names_of(run), ", ");
  c.figure = largest_lm;
  c.figure2 = largest_mpc;
  c.verdict1 = verdict_of(c.n_hold, c.n);
  c.verdict2 = verdict_of(c.n2_hold, c.n2);
  set_verdict_of_parts(c, {c.verdict1, c.verdict2});
  return c;
}

/// Whether row a's |F error| exceeds row b's by more than the noise of the two: the study's
/// printed resolution (0.01 points; two patch-test errors of 3.3e-12 % and 3.4e-12 % are ordered
/// either way by round-off) or what one refinement changes in either, whichever is larger, as
/// the verdict page ties options (H_a sigma_c -0.789 % vs -0.775 %, moving 2.7 points from M to
/// F, is a tie).
bool clearly_larger(const RowFacts& a, const RowFacts& b) {
  return std::abs(*a.errors[2]) >
         std::abs(*b.errors[2]) + grading::pair_noise_points(a.m_to_f_change(), b.m_to_f_change(),
                                                             a.read_resolution_on_f,
                                                             b.read_resolution_on_f);
}

/// A Table 2 trend of three parts: the selected evidence rows are g or better on F (n_hold of
/// n); each one's twin (`twin_of` gives its key) has the clearly larger |F error| (n2_hold of
/// n2, reproduced at kRefined: "almost uniformly"; pairs exact on both to the printed digits
/// show no difference either way and are left out, n2_exact); and the rows of the stated exception
/// (`exception`) are below g (n_exception_holds of n_exception). The verdict is the worst of the
/// three (set_verdict_of_parts); each part names the rows that break it.
template <class Select, class Twin, class Exception>
ClaimEvidence trend_claim(const std::vector<RowFacts>& rows, const char* key, Select select,
                          Twin twin_of, const char* twin_name, Exception exception) {
  ClaimEvidence c{.key = key};
  const auto index = by_key(rows);
  for (const auto& f : rows) {
    const std::optional<bool> good = f.at_least(Grade::g);
    if (exception(f) && good) {
      ++c.n_exception;
      if (*good)
        add_example(c.exception_examples, c.exception_examples_more, row_name(f));
      else
        ++c.n_exception_holds;
    }
    if (!select(f))
      continue;
    if (!good) {
      ++c.n_excluded;
      continue;
    }
    ++c.n;
    if (*good)
      ++c.n_hold;
    else
      add_example(c, row_name(f));
    const auto twin = index.find(twin_of(f));
    if (!f.accuracy_evidence() || twin == index.end() || !twin->second->accuracy_evidence())
      continue;
    const double e_twin = *twin->second->errors[2];
    if (at_resolution(*f.errors[2]) && at_resolution(e_twin)) {
      ++c.n2_exact;  // both exact to the printed digits: no difference to see
      continue;
    }
    ++c.n2;
    if (clearly_larger(*twin->second, f))
      ++c.n2_hold;
    else
      add_example(
          c.examples2, c.examples2_more,
          fmt::format("{} vs {} {}", row_name(f), twin_name, format_error_resolved(e_twin)));
  }
  c.verdict1 = verdict_of(c.n_hold, c.n);
  c.verdict2 = verdict_of(c.n2_hold, c.n2, kRefined);
  set_verdict_of_parts(
      c, {c.verdict1, c.verdict2, exception_verdict(c.n_exception_holds, c.n_exception)});
  return c;
}

/// Trend 1: AL (and PM) ss Q4 is good or excellent except for S(1/3), S(1/7); ns is worse.
ClaimEvidence trend_penalty(const std::vector<RowFacts>& rows) {
  const auto al_ss_q4 = [](const RowFacts& f) {
    return f.option.algorithm == Algorithm::AL && f.option.contact == ContactKind::ss &&
           f.element == Element::Q4;
  };
  return trend_claim(
      rows, "trend_penalty",
      [&](const RowFacts& f) { return al_ss_q4(f) && !small_radius(f.problem); },
      [](const RowFacts& f) {
        return TwinKey{f.problem, f.quantity, f.element, Algorithm::AL, ContactKind::ns};
      },
      "ns", [&](const RowFacts& f) { return al_ss_q4(f) && small_radius(f.problem); });
}

/// Trend 2: LMP, PLM with Q4 good or excellent except with mismatched nodes; Q8 worse.
ClaimEvidence trend_multiplier(const std::vector<RowFacts>& rows) {
  const auto lmp_q4 = [](const RowFacts& f) {
    return f.option.algorithm == Algorithm::LMP && f.element == Element::Q4;
  };
  return trend_claim(
      rows, "trend_multiplier", [&](const RowFacts& f) { return lmp_q4(f) && !mismatched(f); },
      [](const RowFacts& f) {
        return TwinKey{f.problem, f.quantity, Element::Q8, f.option.algorithm, f.option.contact};
      },
      "Q8", [&](const RowFacts& f) { return lmp_q4(f) && mismatched(f); });
}

/// Trend 3: MPC is uniformly unsatisfactory, judged in two parts by the rule for parts
/// (set_verdict_of_parts). Outside the patch tests (verdict1), of n MPC rows, n_hold are
/// unsatisfactory: an evidence row graded s or u on F, or (n_unsound of them) a row whose F
/// case fails an interface check or did not converge. Here, and only here, such a row counts:
/// a solution that violates the contact conditions, or that the solver did not finish, is
/// unsatisfactory whatever its error. A row whose grade is the luck of one mesh, or a read
/// within its resolution, says nothing of MPC's accuracy and is left out (n_excluded). On the
/// patch tests (verdict2; a uniform pressure is exact for any tie), n2 rows by the same rule,
/// n2_hold of them unsatisfactory. "Uniformly" is over the whole battery: the patch tests count.
ClaimEvidence mpc_unsatisfactory(const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "mpc_unsatisfactory"};
  for (const auto& f : rows) {
    if (f.option.algorithm != Algorithm::MPC)
      continue;
    const bool unsound = !f.fine_converged || !f.credible;
    const std::optional<bool> good = f.at_least(Grade::g);
    if (!unsound && !good) {
      ++c.n_excluded;
      continue;
    }
    const bool unsatisfactory = unsound || !*good;
    if (patch_test(f)) {  // the second part, by the same rule
      ++c.n2;
      c.n2_hold += unsatisfactory ? 1 : 0;
      continue;
    }
    ++c.n;
    c.n_unsound += unsound ? 1 : 0;
    c.n_hold += unsatisfactory ? 1 : 0;
    if (!unsatisfactory)
      add_example(c, row_name(f));
  }
  c.verdict1 = verdict_of(c.n_hold, c.n);
  c.verdict2 = verdict_of(c.n2_hold, c.n2);
  set_verdict_of_parts(c, {c.verdict1, c.verdict2});
  return c;
}

/// The median of `v` (0 when empty).
double median_of(std::vector<double> v) {
  if (v.empty())
    return 0.0;
  return gsl_stats_median(v.data(), 1, v.size());
}

/// IMC fastest, judged on the benchmarks, which time each option's contact analysis alone, per
/// fine-mesh model (problem, element, discretization), on two measures: the whole analysis and
/// its contact phase, the active-set iterations (counter iterations_s), where the options
/// differ; the assembly, ordering, factorization and recovery are the same work for each. Two
/// values differ beyond the noise when their gap exceeds both the measure's same-work spread
/// (figure2, figure3, in %: the median of |m_AL / m_PM - 1| over the models where AL took no
/// augmentation and PM's iterations, i.e. made PM's computation) times the larger value, and
/// the sum of their standard deviations over their repetitions (for a value measured once, the
/// same-work spread times it). In a model MPC holds when it is
/// below every other option beyond the noise, is slower when another option is below it beyond
/// the noise, and ties otherwise: n_hold, n2_hold and n2 for the whole analysis (figure: the
/// median of t_MPC / t_fastest other), n3_hold of n3 for the contact phase (range_low ..
/// range_high: the fastest other option's phase over MPC's). The whole analysis decides
/// (verdict1); where MPC is not the fastest there in most models, the claim is refined when its
/// contact phase is the shortest in most (verdict2) and its whole analysis is not slower in
/// most. When AL, timed after PM, is the faster in too many same-work pairs (order_bias_z), the
/// times rank the order of the run and the claim is not testable from them.
/// The sign test's threshold for claim 7: z > 3 leaves chance below 0.3 % (two-sided).
constexpr double kOrderBiasZ = 3.0;

/// The benchmarks of one fine-mesh model that finished and converged, by option.
using BenchTimes = std::map<BenchMethod, const BenchRow*>;

std::map<std::tuple<BenchModel, ContactKind>, BenchTimes> fine_mesh_times(
    const BenchResults& bench) {
  std::map<std::tuple<BenchModel, ContactKind>, BenchTimes> out;
  for (const BenchRow* r : bench.of(BenchFamily::Contact)) {
    if (r->model.mesh == schema::MeshLevel::F && r->converged() && r->time_ms > 0.0)
      out[{r->model, r->contact}][r->algorithm] = r;
  }
  return out;
}

/// One timed measure of a benchmark: its time (ms), or the counter `counter` (a phase, s).
struct BenchMeasure {
  std::string counter;  ///< empty: the whole analysis's time
  std::optional<double> value(const BenchRow& r) const {
    return counter.empty() ? r.time_ms : r.counter(counter);
  }
  /// The standard deviation over the repetitions; none for a case timed once.
  std::optional<double> spread(const BenchRow& r) const {
    if (counter.empty())
      return r.time_stddev_ms;
    const auto it = r.counter_stddev.find(counter);
    return it == r.counter_stddev.end() ? std::nullopt : std::optional(it->second);
  }
};

/// PM and AL of a model made the same computation: AL took no augmentation and PM's iterations
/// (AL's first pass is PM's solve).
bool same_work(const BenchTimes& t) {
  const auto pm = t.find(BenchMethod::PM), al = t.find(BenchMethod::AL);
  if (pm == t.end() || al == t.end())
    return false;
  const auto iterations = pm->second->counter("active_set_iterations");
  return iterations && al->second->counter("augmentations") == 0.0 &&
         al->second->counter("active_set_iterations") == iterations;
}

/// The median of |m_AL / m_PM - 1| over the models where PM and AL made the same computation.
double same_work_noise(const std::map<std::tuple<BenchModel, ContactKind>, BenchTimes>& times,
                       const BenchMeasure& m) {
  std::vector<double> spread;
  for (const auto& [model, t] : times) {
    if (!same_work(t))
      continue;
    const auto pm = m.value(*t.at(BenchMethod::PM)), al = m.value(*t.at(BenchMethod::AL));
    if (pm > 0.0 && al)
      spread.push_back(std::abs(*al / *pm - 1.0));
  }
  return median_of(spread);
}

/// The smallest value of an option other than MPC (infinity when none has one).
double fastest_other(const BenchTimes& t, const BenchMeasure& m) {
  double fastest = INFINITY;
  for (const auto& [method, row] : t) {
    if (const auto v = m.value(*row); method != BenchMethod::MPC && v)
      fastest = std::min(fastest, *v);
  }
  return fastest;
}

enum class Race { faster, tie, slower };

/// MPC against every other option of one model on `m` (see mpc_fastest).
Race mpc_race(const BenchTimes& t, const BenchMeasure& m, double noise) {
  const BenchRow& mpc = *t.at(BenchMethod::MPC);
  const double a = *m.value(mpc);
  bool below_all = true, above_one = false;
  for (const auto& [method, row] : t) {
    const auto b = m.value(*row);
    if (method == BenchMethod::MPC || !b)
      continue;
    const double gap = *b - a;
    // A time measured once has an unknown spread, not none: the same-work noise stands for it.
    const double spreads = m.spread(mpc).value_or(noise * a) + m.spread(*row).value_or(noise * *b);
    const double tolerance = std::max(noise * std::max(a, *b), spreads);
    below_all = below_all && gap > tolerance;
    above_one = above_one || -gap > tolerance;
  }
  return below_all ? Race::faster : above_one ? Race::slower : Race::tie;
}

ClaimEvidence mpc_fastest(const BenchResults* bench) {
  ClaimEvidence c{.key = "mpc_fastest"};
  if (bench == nullptr)
    return c;
  const auto times = fine_mesh_times(*bench);
  const BenchMeasure whole{}, phase{"iterations_s"};
  for (const auto& [model, t] : times) {
    if (!same_work(t))
      continue;
    ++c.n_order_pairs;
    c.n_later_faster += *t.at(BenchMethod::AL)->time_ms < *t.at(BenchMethod::PM)->time_ms;
  }
  if (c.n_order_pairs > 0) {
    c.order_bias_z = std::abs(2.0 * c.n_later_faster - c.n_order_pairs) /
                     std::sqrt(static_cast<double>(c.n_order_pairs));
  }
  const double noise = same_work_noise(times, whole), phase_noise = same_work_noise(times, phase);
  c.figure2 = 100.0 * noise;
  c.figure3 = 100.0 * phase_noise;
  std::vector<double> ratios, phase_ratios;
  for (const auto& [model, t] : times) {
    if (!t.contains(BenchMethod::MPC) || !std::isfinite(fastest_other(t, whole)))
      continue;
    ++c.n;
    ratios.push_back(*t.at(BenchMethod::MPC)->time_ms / fastest_other(t, whole));
    const Race race = mpc_race(t, whole, noise);
    c.n_hold += race == Race::faster;
    c.n2_hold += race == Race::slower;
    c.n2 += race == Race::tie;
    const auto mpc_phase = phase.value(*t.at(BenchMethod::MPC));
    if (mpc_phase > 0.0 && std::isfinite(fastest_other(t, phase))) {
      ++c.n3;
      phase_ratios.push_back(fastest_other(t, phase) / *mpc_phase);
      c.n3_hold += mpc_race(t, phase, phase_noise) == Race::faster;
    }
  }
  if (!ratios.empty())
    c.figure = median_of(ratios);
  if (!phase_ratios.empty()) {
    c.range_low = *std::ranges::min_element(phase_ratios);
    c.range_high = *std::ranges::max_element(phase_ratios);
  }
  c.verdict1 = verdict_of(c.n_hold, c.n, kRefined);
  c.verdict2 = verdict_of(c.n3_hold, c.n3, kRefined);
  if (c.verdict1 <= ClaimVerdict::refined)
    c.verdict = c.verdict1;
  else if (c.verdict2 <= ClaimVerdict::refined && c.n - c.n2_hold >= kRefined * c.n)
    c.verdict = ClaimVerdict::refined;  // the fastest contact phase; the shared work dominates
  else
    c.verdict = c.verdict1;
  if (c.order_bias_z > kOrderBiasZ)
    c.verdict = ClaimVerdict::not_testable;  // the times rank the run's order
  if (c.n_order_pairs == 0)
    c.verdict = ClaimVerdict::not_testable;  // no same-work pair: the noise is unknown
  return c;
}

/// Little difference between Q4 and Q8 where the algorithm works well: the Q4/Q8 pairs of
/// evidence rows where at least one is g or better (n) share their grade (n_hold); of the same
/// pairs (n2), Q8 has the clearly larger |F error| in n2_hold.
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
    if (!f.accuracy_evidence() || !q8->second->accuracy_evidence()) {
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
    ++c.n2;
    c.n2_hold += clearly_larger(*q8->second, f) ? 1 : 0;
  }
  c.verdict = verdict_of(c.n_hold, c.n, kRefined);
  return c;
}

/// The rows `keep` accepts, tallied by vf_judgement, with the failing ones as examples. A row
/// that is not evidence on F counts as such (left out) whether or not it has a VF case, so that
/// no_vf holds only rows a VF case would judge.
template <typename Keep>
VfTally refinement_tally(ClaimEvidence& c, const ResultsIndex& index,
                         const std::vector<RowFacts>& rows, Keep&& keep) {
  VfTally t;
  for (const auto& f : rows) {
    if (!keep(f))
      continue;
    VfJudgement j =
        vf_judgement(*f.row, index.state(*f.row, schema::MeshLevel::VF),
                     index.read_resolution_percent(*f.row, schema::MeshLevel::M), f.evidence());
    if (j == VfJudgement::no_vf && !f.evidence())
      j = VfJudgement::not_evidence;
    if (j == VfJudgement::fails)
      add_example(c, refinement_example(f));  // plateaus are a class the text describes
    ++t.by[static_cast<std::size_t>(j)];
  }
  return t;
}

/// Claim 9: the baseline rows the study's claim applies to (refinement_claim_applies), by the
/// rule of the estimates appendix: n judged, n_hold of them hold (converge over M-F-VF, or
/// settle at the study's resolution), n_plateau settle at a larger error (a bias: fails the
/// claim); n_excluded left open (not evidence on F, with or without a VF case, or VF not
/// converged); n2, evidence on F, have no VF case, so are not judged. Reproduced when most
/// judged rows hold (kRefined).
ClaimEvidence refinement(const ResultsIndex& index, const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "refinement"};
  const VfTally t = refinement_tally(
      c, index, rows, [](const RowFacts& f) { return refinement_claim_applies(*f.row); });
  c.n_hold = t[VfJudgement::converges] + t[VfJudgement::at_resolution];
  c.n = t.trends() + t[VfJudgement::at_resolution];
  c.n_plateau = t[VfJudgement::plateau];
  c.n_excluded = t.open();
  c.n2 = t[VfJudgement::no_vf];  // evidence on F, not judged: the claim's scope here
  c.verdict = verdict_of(c.n_hold, c.n, kRefined);
  return c;
}

/// Claim 10: MPC's baseline rows with a VF case, by the same rule, whatever their grade: n
/// judged, n_hold of them converge, n_plateau settle at a nonzero error; rows at the study's
/// resolution already (n_round_off: nothing to improve) and n_excluded open ones are left out.
/// Reproduced when most judged rows converge (kRefined).
ClaimEvidence mpc_refinement(const ResultsIndex& index, const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "mpc_refinement"};
  const VfTally t = refinement_tally(
      c, index, rows, [](const RowFacts& f) { return f.option.algorithm == Algorithm::MPC; });
  c.n_hold = t[VfJudgement::converges];
  c.n = t.trends();
  c.n_plateau = t[VfJudgement::plateau];
  c.n_round_off = t[VfJudgement::at_resolution];
  c.n_excluded = t.open();
  c.verdict = verdict_of(c.n_hold, c.n, kRefined);
  return c;
}

/// Eq. 47 holds for all contact elements and options; the strict verdict beside it.
ClaimEvidence divergence(const std::vector<DivergenceFacts>& singular) {
  ClaimEvidence c{.key = "divergence"};
  std::map<Option, std::pair<int, int>> by_option;  // rows failing Eq. 47, rows
  std::set<Algorithm> run;
  for (const auto& d : singular) {
    if (!d.evidence()) {  // F not converged or not credible (an MPC edge in tension)
      ++c.n_excluded;
      continue;
    }
    ++c.n;
    run.insert(d.option.algorithm);
    c.n_hold += d.eq47 ? 1 : 0;
    c.n2_hold += d.strict ? 1 : 0;
    auto& [fails, of] = by_option[d.option];
    fails += d.eq47 ? 0 : 1;
    ++of;
  }
  for (const auto& [option, counts] : by_option) {  // every exception, by option
    if (counts.first > 0)
      c.examples += fmt::format("{}{} on {} of {} rows", c.examples.empty() ? "" : "; ",
                                option.label(), counts.first, counts.second);
  }
  for (const auto a : schema::values<Algorithm>()) {
    if (!run.contains(a))
      c.not_run += (c.not_run.empty() ? "" : ", ") + std::string(schema::to_string(a));
  }
  c.n2 = c.n;
  c.verdict = verdict_of(c.n_hold, c.n);
  if (c.verdict == ClaimVerdict::reproduced && !c.not_run.empty() && c.n > 0)
    c.verdict = ClaimVerdict::refined;  // "all options": only those run
  return c;
}

/// Closing: AL, PM ss good for most problems; LMP, PLM fine wherever nodes can be aligned.
/// members: "LMP/PLM", the algorithms in the vocabulary's order.
ClaimEvidence closing(const std::vector<RowFacts>& rows) {
  ClaimEvidence c{.key = "closing"};
  std::set<Algorithm> run, run2;  // the algorithms of each part with evidence rows
  for (const auto& f : rows) {
    const bool penalty_ss = family_of(f.option.algorithm) == OptionFamily::penalty &&
                            f.option.contact == ContactKind::ss;
    const bool multiplier_aligned =
        family_of(f.option.algorithm) == OptionFamily::multiplier && !mismatched(f);
    if (!penalty_ss && !multiplier_aligned)
      continue;
    const std::optional<bool> good = f.at_least(Grade::g);
    if (!good) {
      ++c.n_excluded;
      continue;
    }
    (penalty_ss ? run : run2).insert(f.option.algorithm);
    if (penalty_ss) {
      ++c.n;
      c.n_hold += *good ? 1 : 0;
    } else {
      ++c.n2;
      c.n2_hold += *good ? 1 : 0;
      if (!*good)
        add_example(c, row_name(f));
    }
  }
  c.members = fmt::format("{}", fmt::join(names_of(run), "/"));
  c.members2 = fmt::format("{}", fmt::join(names_of(run2), "/"));
  c.verdict1 = verdict_of(c.n_hold, c.n, kRefined);
  c.verdict2 = verdict_of(c.n2_hold, c.n2);
  set_verdict_of_parts(c, {c.verdict1, c.verdict2});
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
                                        const std::vector<DivergenceFacts>& singular,
                                        const BenchResults* bench) {
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
          mpc_fastest(bench),
          element_order(rows),
          refinement(index, rows),
          mpc_refinement(index, rows),
          divergence(singular),
          closing(rows)};
}

}  // namespace cs::reports
