#pragma once
// The study's claims and our evidence for each: every claim the paper makes (its abstract, the
// three Table 2 trends, AL = PM, LMP = PLM, ss = ns for the multiplier options, IMC fastest, low
// vs high order, convergence under refinement, divergence for all options, the closing remarks),
// each with the numbers that decide it and a verdict. Only rows that are evidence
// (RowFacts::evidence; for accuracy, RowFacts::accuracy_evidence) count, except that "IMC
// uniformly unsatisfactory" counts a row that fails an interface check or did not converge as
// unsatisfactory; the rule that turns numbers into a verdict is written once per claim, in
// claims.cpp, and a claim of parts takes the worst of its parts' verdicts. The words are in
// templates/claims_ledger.mustache.

#include <optional>
#include <string>
#include <vector>

#include "reports/facts/row_facts.hpp"

namespace cs::reports {

/// Ordered from best to worst, not testable last.
enum class ClaimVerdict { reproduced, refined, not_reproduced, not_testable };
std::string to_string(ClaimVerdict v);

/// Counts behind a claim; which fields a claim uses is its own (see claims.cpp).
struct ClaimEvidence {
  std::string key{};  ///< the template section, e.g. "al_equals_pm"
  ClaimVerdict verdict = ClaimVerdict::not_testable;
  int n = 0;           ///< the rows, pairs or models examined
  int n_hold = 0;      ///< of them, those for which the claim holds
  int n_excluded = 0;  ///< rows left out: not credible, luck of one mesh, or not converged
  std::optional<double> figure{};   ///< a claim's deciding figure (a ratio, a difference)
  std::optional<double> figure2{};  ///< a second figure where the claim has two parts
  int n2 = 0, n2_hold = 0;          ///< a second part's counts
  int n2_exact = 0;                 ///< second-part pairs exact on both: left out
  std::string examples{};           ///< the rows or models that break the claim, a few
  std::string examples2{};          ///< those that break its second part, a few
  /// How many more break it than `examples`, `examples2`, `exception_examples` name.
  int examples_more = 0, examples2_more = 0, exception_examples_more = 0;
  /// A claim of parts: each part's own verdict; the claim's is the worst of them.
  ClaimVerdict verdict1 = ClaimVerdict::not_testable, verdict2 = ClaimVerdict::not_testable;
  /// A part (or a stated exception) had no evidence: the claim's verdict is the other parts'.
  bool part_not_testable = false;
  /// A stated exception ("except for ..."): its evidence rows, those where it shows (below g),
  /// and a few where it does not.
  int n_exception = 0, n_exception_holds = 0;
  /// Refinement claims (9, 10): rows that settle at a nonzero error (a bias), and rows at the
  /// study's resolution already (nothing to improve).
  int n_plateau = 0, n_round_off = 0;
  /// Claim 6: rows counted as unsatisfactory because their F case fails an interface check or
  /// did not converge (see mpc_unsatisfactory).
  int n_unsound = 0;
  std::string exception_examples{};
  /// Claim 7's contact phase: the models compared, those where MPC's is the shortest beyond the
  /// noise, the phase's same-work noise (%), and the range of the fastest other option's phase
  /// over MPC's.
  int n3 = 0, n3_hold = 0;
  std::optional<double> figure3{}, range_low{}, range_high{};
  /// Claim 7: benchmarked models where AL made PM's computation (no augmentation, PM's
  /// iterations; AL is timed after PM), those where AL is the faster, and the sign test's
  /// z = |2 n_later_faster - n_order_pairs| / sqrt(n_order_pairs); above kOrderBiasZ the times
  /// rank the run's order, not the algorithms, and the claim is not testable from them.
  int n_order_pairs = 0, n_later_faster = 0;
  /// Claim 11 ("all options"): the study's algorithms with no row in the results.
  std::string not_run{};
  /// Claim 3: the algorithms of its first part that were run ("LMP", "LMP, PLM"), and whether
  /// any MPC pair (its second part) was, evidence or not; claim 12: its first part's ("AL/PM").
  std::string members{};
  /// Claim 12: the algorithms of its second part with evidence rows ("LMP/PLM", "LMP"); its
  /// first part's are in `members` ("AL/PM").
  std::string members2{};
  bool part2_run = false;
  double order_bias_z = 0.0;
};

struct BenchResults;

/// Every claim of the study, in the ledger's order. Claim 7 (IMC fastest) is judged on the
/// benchmarks, which time each option alone (not testable without them): the case times of a
/// run share one factorization per model and take a repeated solve's result
/// (suites/problem_executor.hpp), so they do not rank the algorithms.
std::vector<ClaimEvidence> study_claims(const ResultsIndex& index,
                                        const std::vector<RowFacts>& rows,
                                        const std::vector<DivergenceFacts>& singular,
                                        const BenchResults* bench = nullptr);

}  // namespace cs::reports
