// The verdict page and the claims ledger on a real run (data/battery_results.json: patch tests,
// Hertz, a Steuermann punch and the flat punch, Q4 and Q8, every algorithm, ss and ns, C, M, F).
// Every number they quote is recomputed here from the results' raw records through the grading
// layer, independently of reports/facts/.

#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "grading/convergence.hpp"
#include "grading/credibility.hpp"
#include "grading/divergence.hpp"
#include "report_test_support.hpp"
#include "reports/bench/bench_results.hpp"
#include "reports/facts/claims.hpp"
#include "reports/facts/situation_verdict.hpp"
#include "reports/pages/claims_ledger.hpp"
#include "reports/pages/verdict_page.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::MeshLevel;

struct Battery {
  Battery()
      : doc(schema::read_results_file(testing::source_dir() / "tests" / "reports" / "data" /
                                      "battery_results.json")),
        index(doc),
        rows(row_facts(index)),
        singular(divergence_facts(index)) {}
  schema::ResultsDocument doc;
  ResultsIndex index;
  std::vector<RowFacts> rows;
  std::vector<DivergenceFacts> singular;
};

/// For verdicts without a flat punch.
const std::vector<DivergenceFacts> kNoSingularRows;

const Battery& battery() {
  static const Battery b;
  return b;
}

const schema::CaseResult* case_of(const schema::RowVerdict& row, MeshLevel mesh) {
  schema::CaseSpec spec = row.spec;
  spec.mesh = mesh;
  const std::string id = schema::case_id(spec);
  for (const auto& c : battery().doc.cases) {
    if (c.spec.problem == spec.problem && schema::case_id(c.spec) == id)
      return &c;
  }
  return nullptr;
}

/// Is a raw row evidence? Recomputed: F converged, credible by the interface checks, not luck.
bool evidence(const schema::RowVerdict& r) {
  const schema::CaseResult* fine = case_of(r, MeshLevel::F);
  if (!fine || fine->status != schema::CaseStatus::converged || !r.errors[2])
    return false;
  if (fine->interface && !grading::credibility(*fine->interface).credible)
    return false;
  return !(r.errors[0] && r.errors[1] &&
           grading::luck_of_one_mesh(*r.errors[0], *r.errors[1], *r.errors[2]));
}

/// The claim `key` of `claims` (a test that asks for one not there fails).
const ClaimEvidence& claim_in(const std::vector<ClaimEvidence>& claims, const std::string& key) {
  for (const auto& c : claims) {
    if (c.key == key)
      return c;
  }
  throw std::logic_error("no claim " + key);
}

/// The claim `key` of the battery fixture.
const ClaimEvidence& claim(const std::string& key) {
  static const std::vector<ClaimEvidence> claims =
      study_claims(battery().index, battery().rows, battery().singular);
  return claim_in(claims, key);
}

/// Fixture rows for a claim: each owns its raw row (kept alive here) and is evidence unless
/// the test says otherwise.
struct FixtureRows {
  std::deque<schema::RowVerdict> raw;
  std::vector<RowFacts> rows;

  /// A row of `problem` with the F error `e_f` (C and M the same unless given).
  RowFacts& add(schema::ProblemId problem, schema::Quantity quantity, schema::Element element,
                Algorithm algorithm, schema::ContactKind contact, double e_f,
                std::optional<std::array<double, 2>> coarse = std::nullopt) {
    schema::RowVerdict& r = raw.emplace_back();
    r.spec.problem = problem;
    r.spec.element = element;
    r.spec.algorithm = algorithm;
    r.spec.contact = contact;
    r.quantity = quantity;
    r.errors = {coarse ? (*coarse)[0] : e_f, coarse ? (*coarse)[1] : e_f, e_f};
    RowFacts f;
    f.row = &r;
    f.problem = problem;
    if (const schema::ProblemRecord* p = battery().index.problem(problem))
      f.situation = p->situation;
    f.quantity = quantity;
    f.element = element;
    f.option = {algorithm, contact};
    f.errors = r.errors;
    f.grade = grading::grade_of_error(e_f);
    f.fine_converged = true;
    rows.push_back(f);
    return rows.back();
  }

  /// The claim `key` over these rows (on the battery's problems).
  ClaimEvidence claim(const std::string& key) const {
    for (const auto& c : study_claims(battery().index, rows, {})) {
      if (c.key == key)
        return c;
    }
    throw std::logic_error("no claim " + key);
  }
};

using schema::ContactKind;
using schema::Element;
using schema::ProblemId;
using schema::Quantity;

// Requirement: "low vs high order" counts, of the Q4/Q8 pairs where the algorithm works well,
// those where Q8 has the larger |F error| by more than the noise (the study's resolution, or
// what one refinement changes in either row: a known count), and prints it with its population.
TEST(ClaimsLedger, ElementOrderCountsThePairsWhereQ8IsWorse) {
  FixtureRows fx;
  const auto pair = [&](ContactKind contact, Algorithm a, double q4, double q8) {
    fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, a, contact, q4);
    fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q8, a, contact, q8);
  };
  pair(ContactKind::ss, Algorithm::LMP, 0.1, 0.8);     // Q8 worse, same grade
  pair(ContactKind::ns, Algorithm::LMP, 3e-12, 0.71);  // Q8 worse: round-off vs a bias
  pair(ContactKind::ss, Algorithm::AL, 0.5, 0.505);    // a tie within 0.01 points
  pair(ContactKind::ns, Algorithm::AL, 2.0, 0.3);      // Q8 better, another grade
  // Q8 0.3 points worse, but one refinement moves it 0.5 points: a tie
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::PLM, ContactKind::ss, 0.2);
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q8, Algorithm::PLM, ContactKind::ss, 0.5,
         std::array{1.2, 1.0});
  const ClaimEvidence c = fx.claim("element_order");
  EXPECT_EQ(c.n, 5);
  EXPECT_EQ(c.n_hold, 4);
  EXPECT_EQ(c.n2, 5);
  EXPECT_EQ(c.n2_hold, 2);
  const std::string md = claims_ledger({c});
  EXPECT_NE(md.find("what one refinement changes in either row), in 2 of these 5"),
            std::string::npos)
      << md;
}

// Requirement: a claim of parts takes the worst of its parts' verdicts: a first trend whose rows
// are all g or better but whose "ns is worse" holds in a minority of pairs is not reproduced,
// and names the pairs that break it; pairs exact on both show nothing and are left out.
TEST(ClaimsLedger, APartThatHoldsInAMinorityMakesTheClaimNotReproduced) {
  FixtureRows fx;
  const auto pair = [&](Quantity q, double ss, double ns) {
    fx.add(ProblemId::H_p, q, Element::Q4, Algorithm::AL, ContactKind::ss, ss);
    fx.add(ProblemId::H_p, q, Element::Q4, Algorithm::AL, ContactKind::ns, ns);
  };
  pair(Quantity::sigma_c, 0.2, 1.5);      // ns worse
  pair(Quantity::sigma_z_max, 0.3, 0.3);  // the same
  pair(Quantity::tau_max, 0.5, 0.2);      // ns better
  pair(Quantity::p_mean, 2e-12, 3e-12);   // exact on both: left out
  const ClaimEvidence c = fx.claim("trend_penalty");
  EXPECT_EQ(c.n, 4);
  EXPECT_EQ(c.n_hold, 4);
  EXPECT_EQ(c.verdict1, ClaimVerdict::reproduced);
  EXPECT_EQ(c.n2, 3);
  EXPECT_EQ(c.n2_hold, 1);
  EXPECT_EQ(c.n2_exact, 1);
  EXPECT_EQ(c.verdict2, ClaimVerdict::not_reproduced);
  EXPECT_EQ(c.verdict, ClaimVerdict::not_reproduced);
  const std::string md = claims_ledger({c});
  EXPECT_NE(md.find("not in H<sub>p</sub> sigma_z_max Q4 AL ss +0.30 % vs ns +0.30 %"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("(this part: not reproduced)"), std::string::npos) << md;
}

// Requirement: a stated exception is checked on its own rows: LMP Q4 with mismatched nodes
// graded e does not show the study's exception, so the second trend is refined at best and the
// page names those rows.
TEST(ClaimsLedger, AStatedExceptionThatDoesNotShowRefinesTheClaim) {
  FixtureRows fx;
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::LMP, ContactKind::ss, 0.2);
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q8, Algorithm::LMP, ContactKind::ss, 0.9);
  fx.add(ProblemId::Pprime_p, Quantity::sigma_c, Element::Q4, Algorithm::LMP, ContactKind::ss, 0.1);
  const ClaimEvidence c = fx.claim("trend_multiplier");
  EXPECT_EQ(c.n, 1);
  EXPECT_EQ(c.n2_hold, 1);
  EXPECT_EQ(c.n_exception, 1);
  EXPECT_EQ(c.n_exception_holds, 0);
  EXPECT_EQ(c.verdict, ClaimVerdict::refined);
  EXPECT_NE(claims_ledger({c}).find("The stated exception shows in 0 of 1"), std::string::npos);
}

// Requirement: the ledger holds at least 8 claims, divergence and "IMC fastest" among them, each
// with a verdict.
TEST(ClaimsLedger, HoldsTheStudysClaimsWithVerdicts) {
  const auto claims = study_claims(battery().index, battery().rows, battery().singular);
  EXPECT_GE(claims.size(), 8u);
  const std::string md = claims_ledger(claims);
  for (const char* key : {"divergence", "mpc_fastest", "al_equals_pm", "element_order"})
    EXPECT_NO_THROW(claim(key)) << key;
  for (const auto& c : claims)
    EXPECT_NE(md.find(to_string(c.verdict)), std::string::npos) << c.key;
}

// Requirement: the divergence claim counts Eq. 47 and the strict verdict over every complete
// flat-punch row, recomputed from the raw values.
TEST(ClaimsLedger, DivergenceCountsEq47OverEveryFlatPunchRow) {
  int n = 0, eq47 = 0, strict = 0, excluded = 0;
  for (const auto& r : battery().doc.rows) {
    if (r.spec.problem != schema::ProblemId::F_p || !r.is_baseline() || !r.values[0] ||
        !r.values[1] || !r.values[2])
      continue;
    // Only rows that are evidence: the F case converged and passes the interface checks.
    const schema::CaseResult* fine = battery().index.case_of(r, schema::MeshLevel::F);
    if (fine == nullptr || fine->status != schema::CaseStatus::converged ||
        (fine->interface && !grading::credibility(*fine->interface).credible)) {
      ++excluded;
      continue;
    }
    ++n;
    eq47 += grading::eq47_diverging(*r.values[0], *r.values[1], *r.values[2]) ? 1 : 0;
    strict += grading::divergence_verdict(*r.values[0], *r.values[1], *r.values[2]).diverges;
  }
  const ClaimEvidence& c = claim("divergence");
  EXPECT_GT(n, 0);
  EXPECT_EQ(c.n, n);
  EXPECT_EQ(c.n_excluded, excluded);
  EXPECT_EQ(c.n_hold, eq47);
  EXPECT_EQ(c.n2_hold, strict);
  // "For all options": reproduced only when every algorithm has a row that is evidence.
  EXPECT_EQ(c.verdict, eq47 < 0.75 * n                  ? ClaimVerdict::not_reproduced
                       : eq47 == n && c.not_run.empty() ? ClaimVerdict::reproduced
                                                        : ClaimVerdict::refined);
  const std::string md = claims_ledger({c});
  EXPECT_NE(md.find(std::to_string(eq47) + " of " + std::to_string(n) + " flat-punch rows"),
            std::string::npos);
}

// Requirement: AL = PM counts the AL/PM pairs whose values agree to the printed digits.
TEST(ClaimsLedger, AlEqualsPmComparesEveryPair) {
  std::map<std::string, const schema::RowVerdict*> pm;
  for (const auto& r : battery().doc.rows) {
    if (r.is_baseline() && r.spec.algorithm == Algorithm::PM)
      pm[r.id.substr(0, r.id.find("/PM/")) + r.id.substr(r.id.find("/PM/") + 3)] = &r;
  }
  int n = 0, same = 0;
  for (const auto& r : battery().doc.rows) {
    if (!r.is_baseline() || r.spec.algorithm != Algorithm::AL || !r.errors[2] ||
        battery().index.singular(r.spec.problem))
      continue;
    const auto it = pm.find(r.id.substr(0, r.id.find("/AL/")) + r.id.substr(r.id.find("/AL/") + 3));
    if (it == pm.end())
      continue;
    ++n;
    bool equal = true;
    for (int m = 0; m < 3; ++m)
      equal = equal && r.values[m].has_value() == it->second->values[m].has_value() &&
              (!r.values[m] || std::abs(*r.values[m] - *it->second->values[m]) < 5e-5);
    same += equal ? 1 : 0;
  }
  EXPECT_GT(n, 0);
  EXPECT_EQ(claim("al_equals_pm").n, n);
  EXPECT_EQ(claim("al_equals_pm").n_hold, same);
}

// Requirement: "IMC uniformly unsatisfactory" never counts a row that fails an interface check
// or did not converge as g or better: outside the patch tests such a row is an unsatisfactory
// result and counts for the claim (n_unsound), whatever its grade; a row whose grade is the
// luck of one mesh says nothing either way and is left out.
TEST(ClaimsLedger, MpcClaimNeverCountsAFailedRowAsGood) {
  int n = 0, bad = 0, unsound = 0, left_out = 0;
  for (const auto& r : battery().doc.rows) {
    if (!r.is_baseline() || r.spec.algorithm != Algorithm::MPC || !r.errors[2] ||
        battery().index.singular(r.spec.problem))
      continue;
    const bool patch =
        r.spec.problem == schema::ProblemId::P_p || r.spec.problem == schema::ProblemId::Pprime_p;
    if (patch)
      continue;
    const schema::CaseResult* fine = case_of(r, MeshLevel::F);
    if (!fine || fine->status != schema::CaseStatus::converged ||
        (fine->interface && !grading::credibility(*fine->interface).credible)) {
      ++n;
      ++unsound;
      ++bad;
      continue;
    }
    const double resolution = battery().index.read_resolution_percent(r, MeshLevel::F);
    if (!evidence(r) || (resolution > 0 && std::abs(*r.errors[2]) <= resolution * (1 + 1e-9))) {
      ++left_out;
      continue;
    }
    ++n;
    const auto g = grading::grade_of_error(*r.errors[2]);
    bad += g == schema::Grade::s || g == schema::Grade::u;
  }
  const ClaimEvidence& c = claim("mpc_unsatisfactory");
  EXPECT_GT(unsound, 0) << "the fixture has MPC rows that fail a check or did not converge";
  EXPECT_EQ(c.n_unsound, unsound);
  EXPECT_EQ(c.n_excluded, left_out);
  EXPECT_EQ(c.n, n);
  EXPECT_EQ(c.n_hold, bad);
}

// Requirement: claim 6 counts an MPC row that fails an interface check as unsatisfactory and
// says so; an MPC row whose e is the luck of one mesh is left out, not counted for or against.
TEST(ClaimsLedger, MpcClaimSaysWhyRowsThatFailAChecksCount) {
  FixtureRows fx;
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::MPC, ContactKind::ss, 0.5)
      .credible = false;
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::MPC, ContactKind::ns, 0.5,
         std::array<double, 2>{300.0, 150.0})
      .luck = true;
  fx.add(ProblemId::H_p, Quantity::sigma_h, Element::Q4, Algorithm::MPC, ContactKind::ss, 12.0);
  const ClaimEvidence c = fx.claim("mpc_unsatisfactory");
  EXPECT_EQ(c.n, 2);
  EXPECT_EQ(c.n_hold, 2);
  EXPECT_EQ(c.n_unsound, 1);
  EXPECT_EQ(c.n_excluded, 1);
  const std::string md = claims_ledger({c});
  EXPECT_NE(md.find("1 evidence rows graded s or u on F, and 1 rows whose fine-mesh case fails "
                    "an interface check"),
            std::string::npos)
      << md;
  // Without a patch test the claim holds on the rows it has, and says which part it lacks.
  EXPECT_EQ(c.verdict, ClaimVerdict::reproduced);
  EXPECT_TRUE(c.part_not_testable);
  EXPECT_NE(md.find("No MPC patch-test row is evidence"), std::string::npos) << md;
  // An MPC patch test graded e: "uniformly" speaks of the whole set of experiments, so the
  // patch-test part (0 of 1) makes the claim not reproduced, by the rule for parts.
  fx.add(ProblemId::P_p, Quantity::sigma_z_max, Element::Q4, Algorithm::MPC, ContactKind::ss,
         1e-11);
  const ClaimEvidence with_patch = fx.claim("mpc_unsatisfactory");
  EXPECT_EQ(with_patch.n2, 1);
  EXPECT_EQ(with_patch.n2_hold, 0);
  EXPECT_EQ(with_patch.verdict1, ClaimVerdict::reproduced);
  EXPECT_EQ(with_patch.verdict2, ClaimVerdict::not_reproduced);
  EXPECT_EQ(with_patch.verdict, ClaimVerdict::not_reproduced);
  const std::string md2 = claims_ledger({with_patch});
  EXPECT_NE(md2.find("| IMC uniformly unsatisfactory (Results, third trend; Abstract) | not "
                     "reproduced |"),
            std::string::npos)
      << md2;
  EXPECT_NE(md2.find("0 of 1 MPC rows are unsatisfactory by the same rule (this part: not "
                     "reproduced)"),
            std::string::npos)
      << md2;
  // A patch test that fails an interface check counts against MPC there too, as outside.
  fx.add(ProblemId::P_p, Quantity::sigma_z_max, Element::Q4, Algorithm::MPC, ContactKind::ns, 1e-11)
      .credible = false;
  const ClaimEvidence unsound_patch = fx.claim("mpc_unsatisfactory");
  EXPECT_EQ(unsound_patch.n2, 2);
  EXPECT_EQ(unsound_patch.n2_hold, 1);
  EXPECT_EQ(unsound_patch.n_excluded, 1);
}

// Requirement: a value read between two nodes whose F error is within half a node spacing (the
// contact half-width at +-6.25 % on H_a Q4) is not evidence about accuracy in any claim: not a
// failing exception of a trend, not a grade difference between Q4 and Q8, not an ss/ns gap.
TEST(ClaimsLedger, AReadWithinItsResolutionIsNotEvidenceOfInaccuracy) {
  FixtureRows fx;
  const auto half_width = [&](Element el, ContactKind k, double e, double resolution) {
    fx.add(ProblemId::H_p, Quantity::contact_half_width, el, Algorithm::LMP, k, e)
        .read_resolution_on_f = resolution;
  };
  half_width(Element::Q4, ContactKind::ss, -6.25, 6.25);  // half a node off on F
  half_width(Element::Q4, ContactKind::ns, +6.25, 6.25);
  half_width(Element::Q8, ContactKind::ss, -3.125, 3.125);
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::LMP, ContactKind::ss, 0.2);
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::LMP, ContactKind::ns, 0.2);
  const ClaimEvidence trend = fx.claim("trend_multiplier");
  EXPECT_EQ(trend.n, 2);
  EXPECT_EQ(trend.n_hold, 2);
  EXPECT_EQ(trend.n_excluded, 2);
  EXPECT_EQ(fx.claim("element_order").n, 0);
  const ClaimEvidence ss_ns = fx.claim("ss_equals_ns");
  EXPECT_EQ(ss_ns.n, 1);
  ASSERT_TRUE(ss_ns.figure);
  EXPECT_LT(*ss_ns.figure, 0.01);  // not 12.5 points from -6.25 vs +6.25
}

// Requirement: a claim of "g or better" counts a read between nodes where every reading of it
// says the same (one rule with the verdict page): +12 +- 4 % is below g at its best reading and
// refutes the claim; +2 +- 1 % is g at every reading and supports it; +6.25 +- 6.25 % may be
// anything from e to u and is left out. Claim 6 counts the first as unsatisfactory.
TEST(ClaimsLedger, AReadCountsForAGradeWhereEveryReadingAgrees) {
  FixtureRows fx;
  const auto read = [&](ContactKind k, Algorithm a, double e, double resolution) {
    fx.add(ProblemId::H_p, Quantity::contact_half_width, Element::Q4, a, k, e)
        .read_resolution_on_f = resolution;
  };
  read(ContactKind::ss, Algorithm::LMP, 12.0, 4.0);
  read(ContactKind::ns, Algorithm::LMP, 2.0, 1.0);
  read(ContactKind::mortar, Algorithm::LMP, 6.25, 6.25);
  read(ContactKind::ss, Algorithm::MPC, 12.0, 4.0);
  read(ContactKind::ns, Algorithm::MPC, 6.25, 6.25);
  const ClaimEvidence trend = fx.claim("trend_multiplier");
  EXPECT_EQ(trend.n, 2);
  EXPECT_EQ(trend.n_hold, 1);
  EXPECT_EQ(trend.n_excluded, 1);
  const ClaimEvidence mpc = fx.claim("mpc_unsatisfactory");
  EXPECT_EQ(mpc.n, 1);
  EXPECT_EQ(mpc.n_hold, 1);
  EXPECT_EQ(mpc.n_excluded, 1);
}

// Requirement: claim 3 judges LMP/PLM and IMC apart, the verdict the worse part's; IMC pairs
// exact on both (a patch test, where any tie is exact) show nothing and are left out, so IMC
// is not testable from them, and an IMC pair that differs in grade makes the claim fail.
TEST(ClaimsLedger, SsEqualsNsJudgesImcApartFromItsPatchTests) {
  using schema::ContactKind;
  using schema::Element;
  using schema::ProblemId;
  using schema::Quantity;
  FixtureRows fx;
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::LMP, ContactKind::ss, 0.2);
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::LMP, ContactKind::ns, 0.3);
  fx.add(ProblemId::P_p, Quantity::sigma_z_max, Element::Q4, Algorithm::MPC, ContactKind::ss,
         3e-12);
  fx.add(ProblemId::P_p, Quantity::sigma_z_max, Element::Q4, Algorithm::MPC, ContactKind::ns,
         2e-12);
  ClaimEvidence c = fx.claim("ss_equals_ns");
  EXPECT_EQ(c.n, 1);
  EXPECT_EQ(c.n2, 0);
  EXPECT_EQ(c.n2_exact, 1);
  EXPECT_EQ(c.verdict2, ClaimVerdict::not_testable);
  EXPECT_EQ(c.verdict, ClaimVerdict::reproduced);
  EXPECT_TRUE(c.part_not_testable);  // and the ledger says so
  const std::string md = claims_ledger({c});
  EXPECT_NE(md.find("IMC: no pair that is evidence away from round-off"), std::string::npos) << md;
  EXPECT_NE(md.find("| reproduced (a part not testable) |"), std::string::npos) << md;
  // An IMC pair away from round-off with other grades (e +0.5 % vs g +3 %): not reproduced.
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q8, Algorithm::MPC, ContactKind::ss, 0.5);
  fx.add(ProblemId::H_p, Quantity::sigma_c, Element::Q8, Algorithm::MPC, ContactKind::ns, 3.0);
  c = fx.claim("ss_equals_ns");
  EXPECT_EQ(c.n2, 1);
  EXPECT_EQ(c.n2_hold, 0);
  EXPECT_EQ(c.verdict, ClaimVerdict::not_reproduced);
  EXPECT_FALSE(c.part_not_testable);
}

// Requirement: claim 11 names every exception by option, and "for all options" checked on
// results that lack some of the study's algorithms is at best refined, saying which.
TEST(ClaimsLedger, DivergenceNamesEveryExceptionAndTheOptionsNotRun) {
  std::vector<DivergenceFacts> singular;
  for (const Algorithm a : {Algorithm::AL, Algorithm::PM, Algorithm::LMP}) {
    DivergenceFacts d;
    d.option = {a, schema::ContactKind::ss};
    d.eq47 = d.strict = d.fine_converged = true;
    singular.push_back(d);
  }
  // An MPC row that pulls (not credible) is no evidence: MPC counts as not judged.
  DivergenceFacts pulls;
  pulls.option = {Algorithm::MPC, schema::ContactKind::ss};
  pulls.eq47 = pulls.fine_converged = true;
  pulls.credible = false;
  singular.push_back(pulls);
  const auto claims = study_claims(battery().index, {}, singular);
  const ClaimEvidence& c = claim_in(claims, "divergence");
  EXPECT_EQ(c.n_hold, 3);
  EXPECT_EQ(c.n_excluded, 1);
  EXPECT_EQ(c.not_run, "PLM, MPC");
  EXPECT_EQ(c.verdict, ClaimVerdict::refined);
  // The battery's flat punch: every failing option named with its count; the options named
  // not judged are those with no row that is evidence.
  const ClaimEvidence& all = claim("divergence");
  std::set<Algorithm> judged;
  for (const auto& d : divergence_facts(battery().index)) {
    if (d.evidence())
      judged.insert(d.option.algorithm);
  }
  EXPECT_EQ(all.not_run.empty(), judged.size() == schema::values<Algorithm>().size())
      << all.not_run;
  int named = 0;
  for (std::size_t at = all.examples.find(" rows"); at != std::string::npos;
       at = all.examples.find(" rows", at + 1))
    ++named;
  std::set<Option> failing;
  for (const auto& d : divergence_facts(battery().index)) {
    if (d.evidence() && !d.eq47)
      failing.insert(d.option);
  }
  EXPECT_EQ(named, static_cast<int>(failing.size())) << all.examples;
  EXPECT_EQ(all.examples.find("AL "), std::string::npos) << all.examples;
}

/// A Contact benchmark of `problem` at mesh `mesh`: its time and the solver's counts.
BenchRow bench_row(ProblemId problem, MeshLevel mesh, Element element, ContactKind contact,
                   BenchMethod method, double ms, int iterations, int augmentations = 0) {
  BenchRow r;
  r.model = {problem, mesh, element};
  r.contact = contact;
  r.algorithm = method;
  r.time_ms = ms;
  r.counters = {{"active_set_iterations", iterations}, {"augmentations", augmentations}};
  return r;
}

// Requirement: the whole analysis decides claim 7; where it ties, the claim is refined when
// MPC's contact phase (the active-set iterations, where the options differ) is the shortest
// beyond that phase's noise, and the ledger says so. A gap beyond the same-work noise is still a
// tie when it lies within the two times' standard deviations over their repetitions, or within
// the same-work noise of each where a time was measured once.
TEST(ClaimsLedger, MpcFastestIsRefinedWhenOnlyItsContactPhaseIsFaster) {
  using enum BenchMethod;
  BenchResults bench;
  for (const Element e : {Element::Q4, Element::Q8}) {
    for (const ContactKind k : {ContactKind::ns, ContactKind::ss}) {
      for (const auto& [method, ms, phase_s] :
           {std::tuple{PM, 100.0, 0.010}, std::tuple{AL, 100.5, 0.0101},
            std::tuple{LM, 101.0, 0.012}, std::tuple{MPC, 100.2, 0.001}}) {
        bench.rows.push_back(bench_row(ProblemId::H_p, MeshLevel::F, e, k, method, ms, 5));
        bench.rows.back().counters["iterations_s"] = phase_s;
      }
    }
  }
  const auto claims = study_claims(battery().index, battery().rows, battery().singular, &bench);
  const ClaimEvidence& c = claim_in(claims, "mpc_fastest");
  EXPECT_EQ(c.n, 4);
  EXPECT_EQ(c.n2, 4);  // within 0.5 %, the PM/AL spread
  EXPECT_EQ(c.n3, 4);
  EXPECT_EQ(c.n3_hold, 4);  // a tenth of PM's phase, beyond its 1 % noise
  ASSERT_TRUE(c.figure3 && c.range_low && c.range_high);
  EXPECT_NEAR(*c.figure3, 1.0, 1e-9);
  EXPECT_NEAR(*c.range_low, 10.0, 1e-9);
  EXPECT_EQ(c.verdict, ClaimVerdict::refined);
  EXPECT_NE(claims_ledger(claims).find("fastest at its own work"), std::string::npos);
  // MPC 2 % faster on one model: beyond the 0.5 % noise, but not beyond its and PM's spreads.
  bench.rows[3].time_ms = 98.0;
  const auto faster = study_claims(battery().index, battery().rows, battery().singular, &bench);
  EXPECT_EQ(claim_in(faster, "mpc_fastest").n_hold, 1);
  bench.rows[3].time_stddev_ms = 1.5;
  bench.rows[0].time_stddev_ms = 1.0;
  const auto spread = study_claims(battery().index, battery().rows, battery().singular, &bench);
  EXPECT_EQ(claim_in(spread, "mpc_fastest").n_hold, 0);
  // MPC 0.8 % faster, every time measured once: beyond the 0.5 % noise, but a single run's
  // spread is unknown, not zero, and counts as that noise: a tie. Measured spreads of 0.1 ms on
  // MPC and PM make the same gap a win.
  bench.rows[3].time_ms = 99.2;
  bench.rows[3].time_stddev_ms.reset();
  bench.rows[0].time_stddev_ms.reset();
  const auto once = study_claims(battery().index, battery().rows, battery().singular, &bench);
  EXPECT_EQ(claim_in(once, "mpc_fastest").n_hold, 0);
  bench.rows[3].time_stddev_ms = 0.1;
  bench.rows[0].time_stddev_ms = 0.1;
  const auto repeated = study_claims(battery().index, battery().rows, battery().singular, &bench);
  EXPECT_EQ(claim_in(repeated, "mpc_fastest").n_hold, 1);
}

// Requirement: without a model where AL makes PM's computation, the timing noise is unknown, so
// "IMC fastest" is not testable from the times, and the ledger says why (it had judged single
// runs against a noise of zero).
TEST(ClaimsLedger, MpcFastestIsNotTestableWithoutTheTimingNoise) {
  using enum BenchMethod;
  BenchResults bench;
  bench.rows.push_back(
      bench_row(ProblemId::H_p, MeshLevel::F, Element::Q4, ContactKind::ss, PM, 100.0, 5));
  bench.rows.push_back(
      bench_row(ProblemId::H_p, MeshLevel::F, Element::Q4, ContactKind::ss, MPC, 90.0, 1));
  const auto claims = study_claims(battery().index, battery().rows, battery().singular, &bench);
  const ClaimEvidence& c = claim_in(claims, "mpc_fastest");
  EXPECT_EQ(c.n, 1);
  EXPECT_EQ(c.verdict, ClaimVerdict::not_testable);
  EXPECT_NE(claims_ledger(claims).find("so the timing noise that two times must differ by is "
                                       "unknown"),
            std::string::npos);
}

// Requirement: "IMC fastest" is measured on the benchmarks, which time each option alone: per
// fine-mesh model, MPC's time against the fastest other option's, beyond the timing noise (the
// median relative difference of PM and AL where AL makes PM's computation: no augmentation,
// PM's iterations); within it is a tie. Coarser meshes, failed benchmarks and AL that augmented
// stay out of their parts. Without benchmarks the claim is not testable.
TEST(ClaimsLedger, MpcFastestIsMeasuredOnTheBenchmarksBeyondTheTimingNoise) {
  using enum BenchMethod;
  const auto F = MeshLevel::F;
  BenchResults bench;
  for (const auto& [contact, mpc, al] :
       {std::tuple{ContactKind::ss, 90.0, 101.0}, std::tuple{ContactKind::ns, 99.5, 99.0}}) {
    bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q4, contact, PM, 100.0, 5));
    bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q4, contact, AL, al, 5));
    bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q4, contact, LM, 103.0, 4));
    bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q4, contact, MPC, mpc, 1));
  }
  // slower beyond the noise; AL augmented, so its pair is not the same work
  bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q8, ContactKind::ss, PM, 200.0, 4));
  bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q8, ContactKind::ss, AL, 150.0, 4, 1));
  bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q8, ContactKind::ss, MPC, 230.0, 1));
  // MPC failed: no comparison, but a same-work pair (3 %)
  bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q8, ContactKind::ns, PM, 100.0, 3));
  bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q8, ContactKind::ns, AL, 103.0, 3));
  bench.rows.push_back(bench_row(ProblemId::H_p, F, Element::Q8, ContactKind::ns, MPC, 1.0, 1));
  bench.rows.back().label = "not converged: iteration cap";
  // not a fine mesh
  bench.rows.push_back(
      bench_row(ProblemId::H_p, MeshLevel::M, Element::Q4, ContactKind::ss, PM, 9.0, 5));
  bench.rows.push_back(
      bench_row(ProblemId::H_p, MeshLevel::M, Element::Q4, ContactKind::ss, MPC, 1.0, 1));
  const auto claims = study_claims(battery().index, battery().rows, battery().singular, &bench);
  const ClaimEvidence& c = claim_in(claims, "mpc_fastest");
  EXPECT_EQ(c.n, 3);
  EXPECT_EQ(c.n_hold, 1);   // Q4 ss: 0.90 x 1.01 < 1
  EXPECT_EQ(c.n2, 1);       // Q4 ns: 99.5 / 99 within 1 %
  EXPECT_EQ(c.n2_hold, 1);  // Q8 ss: 230 / 150 beyond it
  ASSERT_TRUE(c.figure2 && c.figure);
  EXPECT_NEAR(*c.figure2, 1.0, 1e-9);  // the median of 1 %, 1 %, 3 %
  EXPECT_NEAR(*c.figure, 99.5 / 99.0, 1e-12);
  EXPECT_EQ(c.n_order_pairs, 3);
  EXPECT_EQ(c.n_later_faster, 1);
  EXPECT_EQ(c.verdict, ClaimVerdict::not_reproduced);
  const auto without = study_claims(battery().index, battery().rows, battery().singular);
  const ClaimEvidence& none = claim_in(without, "mpc_fastest");
  EXPECT_EQ(none.verdict, ClaimVerdict::not_testable);
  const std::string md = claims_ledger({none});
  EXPECT_NE(md.find("no benchmark times MPC"), std::string::npos) << md;
}

// Requirement: times that rank the run's order rather than the algorithms make claim 7 not
// testable: AL makes PM's computation after it, so a sign test over the models where AL is
// systematically the faster (z > 3) shows an order bias the noise estimate misses.
TEST(ClaimsLedger, MpcFastestIsNotTestableWhenTheRunOrderBiasesTheTimes) {
  using enum BenchMethod;
  BenchResults bench;
  for (const ProblemId p : {ProblemId::H_p, ProblemId::S_1_7, ProblemId::Pprime_p}) {
    for (const Element e : {Element::Q4, Element::Q8}) {
      for (const ContactKind k : {ContactKind::ns, ContactKind::ss}) {
        bench.rows.push_back(bench_row(p, MeshLevel::F, e, k, PM, 100.0, 5));
        bench.rows.push_back(bench_row(p, MeshLevel::F, e, k, AL, 90.0, 5));
        bench.rows.push_back(bench_row(p, MeshLevel::F, e, k, MPC, 50.0, 1));
      }
    }
  }
  const auto claims = study_claims(battery().index, battery().rows, battery().singular, &bench);
  const ClaimEvidence& c = claim_in(claims, "mpc_fastest");
  EXPECT_EQ(c.n_order_pairs, 12);
  EXPECT_EQ(c.n_later_faster, 12);
  EXPECT_GT(c.order_bias_z, 3.0);  // sqrt(12)
  EXPECT_EQ(c.verdict, ClaimVerdict::not_testable);
  const std::string md = claims_ledger(claims);
  EXPECT_NE(md.find("rank the order of the run"), std::string::npos) << md;
  // Every other model's AL the slower: no bias, and the count decides.
  for (std::size_t i = 1; i < bench.rows.size(); i += 6)
    bench.rows[i].time_ms = 110.0;
  const auto unbiased = study_claims(battery().index, battery().rows, battery().singular, &bench);
  const ClaimEvidence& counted = claim_in(unbiased, "mpc_fastest");
  EXPECT_EQ(counted.n_later_faster, 6);
  EXPECT_EQ(counted.verdict, ClaimVerdict::reproduced);  // MPC at half the time everywhere
}

// Requirement: each verdict cell is the worst signed F error over its rows, graded by Eq. 46,
// and is marked when a row is not evidence; the page prints it with its sign.
TEST(VerdictPage, CellsAreTheWorstSignedFineErrorGradedByEq46) {
  const auto situations = situation_verdicts(battery().index, battery().rows, battery().singular);
  ASSERT_FALSE(situations.empty());
  int cells = 0;
  for (const auto& s : situations) {
    for (const auto& c : s.cells) {
      if (c.rows.empty())
        continue;
      ++cells;
      double worst = 0.0;
      int not_credible = 0;
      for (const RowFacts* f : c.rows) {
        const double e = *f->row->errors[2];
        worst = std::abs(e) > std::abs(worst) ? e : worst;
        const schema::CaseResult* fine = case_of(*f->row, MeshLevel::F);
        not_credible += fine && fine->interface && !grading::credibility(*fine->interface).credible;
        EXPECT_TRUE(std::count(s.problems.begin(), s.problems.end(), f->problem));
        EXPECT_EQ(family_of(f->option.algorithm), c.family);
      }
      EXPECT_EQ(*c.worst_error, worst);
      EXPECT_EQ(*c.worst_grade, grading::grade_of_error(worst));
      EXPECT_EQ(c.n_not_credible, not_credible);
      const std::string cell = verdict_cell(c);
      EXPECT_EQ(cell.find(not_credible > 0 ? "✗" : "~") != std::string::npos, not_credible > 0);
      EXPECT_NE(cell.find(worst < 0 ? "−" : "+"), std::string::npos) << cell;
    }
  }
  EXPECT_GT(cells, 10);
}

// Requirement: the best options of a situation are evidence cells of one grade, not ranked; an
// option whose rows fail an interface check is never among them.
TEST(VerdictPage, TiesAreEvidenceOfTheBestGrade) {
  for (const auto& s : situation_verdicts(battery().index, battery().rows, battery().singular)) {
    for (const OptionCell* c : s.best) {
      if (s.singular)
        continue;
      EXPECT_TRUE(c->evidence) << s.title;
      EXPECT_EQ(c->worst_grade, s.best_grade) << s.title;
      EXPECT_EQ(c->n_not_credible, 0);
    }
  }
}

// Requirement: the first screen of the study's battery is at most 60 lines.
/// A rounded-punch row on F: e, converged, failing the named interface checks.
RowFacts rounded_punch_row(Algorithm algorithm, std::vector<std::string> checks) {
  RowFacts f;
  f.problem = schema::ProblemId::S_1;
  f.quantity = schema::Quantity::sigma_c;
  f.option = {algorithm, schema::ContactKind::ss};
  f.errors = {2.0, 1.0, 0.5};
  f.grade = schema::Grade::e;
  f.fine_converged = true;
  for (auto& check : checks)
    f.failures.push_back({std::move(check), 3.0});
  f.credible = f.failures.empty();
  return f;
}

// Requirement: the best options are tied when their worst |errors| lie within the noise, whatever
// their signs: -0.59 % and +0.55 % are 0.04 points apart in accuracy, not 1.14.
TEST(VerdictPage, TiesCompareTheMagnitudesOfTheErrors) {
  RowFacts below = rounded_punch_row(Algorithm::AL, {});
  below.errors = {-0.9, -0.7, -0.59};
  RowFacts above = rounded_punch_row(Algorithm::LMP, {});
  above.errors = {0.9, 0.7, 0.55};                 // M -> F moves 0.15 and 0.11 points: the noise
  const std::vector<RowFacts> rows{below, above};  // the cells point into them
  const auto situations = situation_verdicts(battery().index, rows, kNoSingularRows);
  ASSERT_EQ(situations.size(), 1U);
  const SituationVerdict& s = situations[0];
  ASSERT_EQ(s.best.size(), 2U);
  EXPECT_NEAR(s.best_abs_spread, 0.04, 1e-12);
  EXPECT_NEAR(s.best_noise, 0.15, 1e-12);
  const std::string md = verdict_page(battery().index, situations);
  EXPECT_NE(md.find("tied (their worst |errors| 0.04 points apart"), std::string::npos) << md;
}

// Requirement: options of the best grade that are not tied are not offered as "any of": those
// with the smallest F errors (within the largest M -> F change of the grade's cells of it) are
// named apart from the others of the grade, whose larger errors are given. A cell that moves
// more than the smallest one is not left out on the smallest one's change alone.
TEST(VerdictPage, UntiedOptionsOfAGradeAreNotAnyOf) {
  RowFacts lmp = rounded_punch_row(Algorithm::LMP, {});
  lmp.errors = {0.5, 0.1, 0.01};  // the most accurate; one refinement moves it 0.09 points
  RowFacts al = rounded_punch_row(Algorithm::AL, {});
  al.errors = {0.3, 0.1, 0.05};  // 0.04 points behind: within 0.09
  RowFacts mpc = rounded_punch_row(Algorithm::MPC, {});
  mpc.errors = {0.9, 0.85, 0.8};  // 0.79 points behind
  const std::vector<RowFacts> rows{lmp, al, mpc};
  const auto situations = situation_verdicts(battery().index, rows, kNoSingularRows);
  ASSERT_EQ(situations.size(), 1U);
  const SituationVerdict& s = situations[0];
  ASSERT_EQ(s.best.size(), 3U);
  ASSERT_EQ(s.leaders.size(), 2U);
  EXPECT_EQ(std::ranges::count_if(
                s.leaders, [](const OptionCell* c) { return c->family == OptionFamily::mpc; }),
            0);
  const std::string md = verdict_page(battery().index, situations);
  EXPECT_EQ(md.find("any of"), std::string::npos) << md;
  EXPECT_NE(md.find("all e, not tied: their worst |errors| lie 0.79 points apart, more than one "
                    "refinement moves them (0.09 points)."),
            std::string::npos)
      << md;
  EXPECT_NE(
      md.find("(worst |error| at most 0.05 %, within 0.09 points of the smallest: what one "
              "refinement changes in it, at least the study's 0.01-point resolution). Larger: MPC "
              "ss Q4 (worst error +0.8 %)."),
      std::string::npos)
      << md;
  // AL 0.14 points behind, moving 0.15 itself: the bound is the most accurate cell's own
  // change (0.09), not AL's, so an option settled near exact is not joined by one that moves.
  al.errors = {0.5, 0.3, 0.15};
  const std::vector<RowFacts> moved{lmp, al, mpc};
  const auto again = situation_verdicts(battery().index, moved, kNoSingularRows);
  ASSERT_EQ(again[0].leaders.size(), 1U);
  EXPECT_EQ(again[0].leaders[0]->family, OptionFamily::multiplier);
  EXPECT_NEAR(again[0].leaders_noise, 0.09, 1e-12);
}

// Requirement: no cut between the leaders and the others falls within the study's 0.01-point
// resolution (the interference fit: ss Q8 +0.0392 % leads by the most accurate cell's change,
// 0.0217 + 0.0179; ns Q8 +0.0443 %, 0.005 points from it and printed alike, leads too); a cell
// beyond that, -0.111 %, does not.
TEST(VerdictPage, NoLeaderIsCutWithinTheStudysResolution) {
  const auto cell = [](Algorithm a, schema::ContactKind k, double m, double f) {
    RowFacts r = rounded_punch_row(a, {});
    r.option.contact = k;
    r.errors = {m, m, f};
    return r;
  };
  using K = schema::ContactKind;
  const std::vector<RowFacts> rows{
      cell(Algorithm::AL, K::ss, 0.0396, 0.0217), cell(Algorithm::LMP, K::ss, 0.0416, 0.0392),
      cell(Algorithm::LMP, K::ns, 0.0568, 0.0443), cell(Algorithm::AL, K::ns, -0.138, -0.111)};
  const auto situations = situation_verdicts(battery().index, rows, kNoSingularRows);
  ASSERT_EQ(situations.size(), 1U);
  const SituationVerdict& s = situations[0];
  ASSERT_EQ(s.best.size(), 4U);
  EXPECT_NEAR(s.leaders_noise, 0.0179, 1e-12);
  ASSERT_EQ(s.leaders.size(), 3U);
  EXPECT_TRUE(s.leaders_extended);
  EXPECT_NEAR(s.leaders_max_abs, 0.0443, 1e-12);
  EXPECT_EQ(std::ranges::count_if(s.leaders,
                                  [](const OptionCell* c) {
                                    return c->contact == K::ns &&
                                           c->family == OptionFamily::penalty;
                                  }),
            0);
  EXPECT_NE(verdict_page(battery().index, situations).find("or within 0.01 points of another"),
            std::string::npos);
}

// Requirement: a tie whose tolerance (what one refinement changes) is wider than the grade's
// band says that the meshes resolve neither a ranking nor the grade; a narrower one does not.
TEST(VerdictPage, ATieWiderThanItsGradeSaysSo) {
  const auto advice_of = [](double m_error) {
    RowFacts a = rounded_punch_row(Algorithm::AL, {});
    a.errors = {3.0, m_error, 0.5};
    RowFacts b = rounded_punch_row(Algorithm::LMP, {});
    b.errors = {3.0, 0.9, 0.6};
    const std::vector<RowFacts> rows{a, b};
    return verdict_page(battery().index,
                        situation_verdicts(battery().index, rows, kNoSingularRows));
  };
  const std::string wide = advice_of(2.5);  // M -> F: 2 points, twice e's band
  EXPECT_NE(wide.find("within 2 points: the larger of what one refinement changes in them and "
                      "the 0.01-point resolution of the study's values), wider than grade e's "
                      "band (1 point)"),
            std::string::npos)
      << wide;
  const std::string narrow = advice_of(0.8);  // M -> F: 0.3 points
  EXPECT_NE(narrow.find("tied"), std::string::npos) << narrow;
  EXPECT_EQ(narrow.find("wider than grade"), std::string::npos) << narrow;
}

// Requirement: a read between nodes whose F error, give or take its resolution, may lie in more
// than one grade (within half a node of zero, or across a grade's bound: +10.49 +- 4.42 % may
// be s or u) is not graded as it reads; but the cell's grade is never better than the read's
// best reading (|e| - r): +10.49 +- 4.42 % makes a cell of e stresses s, printed with its
// resolution, while a read within half a node of zero leaves the cell alone. One whose whole
// interval stays in one grade counts as a row.
TEST(VerdictPage, AReadWhoseResolutionLeavesItsGradeOpenCountsAtItsBestReading) {
  RowFacts point = rounded_punch_row(Algorithm::LMP, {});
  point.errors = {1.0, 0.6, 0.4};
  struct Case {
    double f_error, resolution;
    std::size_t rows;
    double worst;
    schema::Grade grade;
    double printed_resolution;
  };
  for (const Case& k : {Case{2.0, 2.5, 1, 0.4, schema::Grade::e, 0.0},
                        Case{10.49, 4.42, 1, 10.49, schema::Grade::s, 4.42},
                        Case{20.0, 4.42, 2, 20.0, schema::Grade::u, 0.0}}) {
    RowFacts read = rounded_punch_row(Algorithm::LMP, {});
    read.errors = {8.0, 4.0, k.f_error};
    read.read_resolution_on_f = k.resolution;
    const std::vector<RowFacts> rows{read, point};
    const auto situations = situation_verdicts(battery().index, rows, kNoSingularRows);
    ASSERT_EQ(situations.size(), 1U);
    ASSERT_EQ(situations[0].cells.size(), 1U);
    const OptionCell& c = situations[0].cells[0];
    EXPECT_EQ(c.rows.size(), k.rows) << k.f_error;
    EXPECT_DOUBLE_EQ(*c.worst_error, k.worst) << k.f_error;
    EXPECT_EQ(c.worst_grade, k.grade) << k.f_error;
    EXPECT_DOUBLE_EQ(c.worst_resolution, k.printed_resolution) << k.f_error;
    EXPECT_EQ(verdict_cell(c).find(" ± ") != std::string::npos, k.printed_resolution > 0)
        << verdict_cell(c);
    EXPECT_EQ(read.accuracy_evidence(), k.rows == 2 && read.evidence()) << k.f_error;
  }
  // An option whose only row is an open read has nothing graded: no cell, no situation.
  RowFacts alone = rounded_punch_row(Algorithm::LMP, {});
  alone.errors = {8.0, 4.0, 10.49};
  alone.read_resolution_on_f = 4.42;
  const std::vector<RowFacts> only{alone};
  EXPECT_TRUE(situation_verdicts(battery().index, only, kNoSingularRows).empty());
}

// Requirement: an option whose F case failed has no F value, but its cell says so, with no
// grade, and the option is listed to avoid with the failure's reason (it once showed "—", as
// if it had not been run).
TEST(VerdictPage, ACellWhoseFineCaseFailedSaysSo) {
  const testing::Loaded data(testing::sample_json());        // H_p F Q8 PM ss failed
  const std::vector<RowFacts> rows = row_facts(data.index);  // the cells point into them
  const std::vector<DivergenceFacts> singular = divergence_facts(data.index);
  const auto situations = situation_verdicts(data.index, rows, singular);
  const auto hertz = std::find_if(situations.begin(), situations.end(),
                                  [](const auto& s) { return s.key == "smooth_curved"; });
  ASSERT_NE(hertz, situations.end());
  const OptionCell* pm_q8 = nullptr;
  for (const auto& c : hertz->cells) {
    if (c.element == schema::Element::Q8 && c.contact == schema::ContactKind::ss &&
        c.members.contains(Algorithm::PM))
      pm_q8 = &c;
  }
  ASSERT_NE(pm_q8, nullptr);
  EXPECT_GE(pm_q8->n_failed, 1);
  EXPECT_FALSE(pm_q8->worst_grade.has_value());
  EXPECT_FALSE(pm_q8->evidence);
  EXPECT_TRUE(std::count(hertz->avoid.begin(), hertz->avoid.end(), pm_q8));
  EXPECT_NE(verdict_cell(*pm_q8).find("F failed on"), std::string::npos) << verdict_cell(*pm_q8);
  const std::string md = verdict_page(data.index, situations);
  EXPECT_NE(md.find("singular stiffness matrix (rigid body mode)"), std::string::npos) << md;
  // AL's Q8 rows have C and M cases but no F case (not run): the cell covers part of the
  // situation and says so.
  EXPECT_GE(pm_q8->n_missing, 1);
  EXPECT_NE(verdict_cell(*pm_q8).find("no F on"), std::string::npos) << verdict_cell(*pm_q8);
}

/// The verdict page of a results document (its facts built as report.md builds them).
std::string verdict_page_of(const nlohmann::json& doc) {
  const testing::Loaded data(doc);
  const std::vector<RowFacts> rows = row_facts(data.index);  // the cells point into them
  const std::vector<DivergenceFacts> singular = divergence_facts(data.index);
  return verdict_page(data.index, situation_verdicts(data.index, rows, singular));
}

// Requirement: on the flat punch, an option whose F case failed is not judged by Eq. 47: the
// advice lists it to avoid for that reason, apart from the options that fail Eq. 47.
TEST(VerdictPage, AFlatPunchOptionWhoseFineCaseFailedIsNotJudged) {
  auto doc = testing::sample_json();
  for (auto& c : doc["cases"]) {
    if (c["id"] == "F_p/F/Q4/AL/ss") {
      c["status"] = "failed";
      c["reason"] = "the solver stopped";
      for (auto& [name, q] : c["quantities"].items())
        q["value"] = nullptr;
    }
  }
  for (auto& r : doc["rows"]) {
    if (r["id"] == "F_p/Q4/AL/ss/sigma_c_star") {
      r["values"].erase("F");
      r["diverging"] = nullptr;
    }
  }
  const std::string md = verdict_page_of(doc);
  EXPECT_NE(md.find("Avoid AL ss Q4: an F case failed, so it gives no edge stress to judge"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("Avoid AL ss Q4: Eq. 47 fails"), std::string::npos) << md;
  EXPECT_NE(md.find("Avoid MPC ss Q4: Eq. 47 fails"), std::string::npos) << md;
}

// Requirement: a flat-punch option whose F case pulls (tensile pressure) is no evidence even
// where Eq. 47 holds: its cell is marked ✗, it is to be avoided for that reason (not as an
// Eq. 47 failure nor as a failed case), never the best, and the failure line quotes the measure.
TEST(VerdictPage, AFlatPunchOptionThatPullsIsNoEvidence) {
  auto doc = testing::sample_json();
  for (auto& c : doc["cases"]) {
    if (c["id"] == "F_p/F/Q4/AL/ss")
      c["interface"]["max_tensile_over_p"] = 5.0;
  }
  const std::string md = verdict_page_of(doc);
  EXPECT_NE(md.find("Avoid AL ss Q4: an F case fails an interface check (the failures below), so "
                    "its divergence is no evidence."),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("tensile pressure up to 5"), std::string::npos) << md;
  EXPECT_NE(md.find(" ✗ |"), std::string::npos) << md;
}

// Requirement: a check that every option fails alike (e.g. pressure a few elements beyond the
// exact patch edge for every option and target) makes no option evidence, but is no reason to
// avoid one: only an option that fails a check some other option passes, or grades u, is to be
// avoided; the page says the failure is shared.
TEST(VerdictPage, ACheckEveryOptionFailsIsSharedNotAReasonToAvoidOne) {
  const std::string outside = "pressure outside the patch";
  const std::vector<RowFacts> rows = {
      rounded_punch_row(Algorithm::LMP, {outside}),
      rounded_punch_row(Algorithm::AL, {outside, "tensile pressure"}),
      rounded_punch_row(Algorithm::MPC, {outside})};
  const auto situations = situation_verdicts(battery().index, rows, kNoSingularRows);
  ASSERT_EQ(situations.size(), 1U);
  const SituationVerdict& s = situations[0];
  EXPECT_EQ(s.common_failures, std::vector<std::string>{outside});
  EXPECT_TRUE(s.best.empty());  // no cell is evidence
  ASSERT_EQ(s.avoid.size(), 1U);
  EXPECT_EQ(s.avoid[0]->family, OptionFamily::penalty);  // AL: it also pulls
  const std::string md = verdict_page(battery().index, situations);
  EXPECT_NE(md.find("every option fails the pressure outside the patch check alike"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("every option alike: pressure outside the patch up to 3"), std::string::npos)
      << md;
  // Without the shared failure, the same three options are all to be avoided.
  const std::vector<RowFacts> apart = {rounded_punch_row(Algorithm::LMP, {outside}),
                                       rounded_punch_row(Algorithm::AL, {"tensile pressure"}),
                                       rounded_punch_row(Algorithm::MPC, {outside})};
  const auto s2 = situation_verdicts(battery().index, apart, kNoSingularRows);
  ASSERT_EQ(s2.size(), 1U);
  EXPECT_TRUE(s2[0].common_failures.empty());
  EXPECT_EQ(s2[0].avoid.size(), 3U);
  // One family alone cannot show that a failure is not its own.
  const std::vector<RowFacts> one_family = {rounded_punch_row(Algorithm::LMP, {outside}),
                                            rounded_punch_row(Algorithm::PLM, {outside})};
  const auto s3 = situation_verdicts(battery().index, one_family, kNoSingularRows);
  ASSERT_EQ(s3.size(), 1U);
  EXPECT_TRUE(s3[0].common_failures.empty());
  EXPECT_EQ(s3[0].avoid.size(), 1U);
}

// Requirement: a row names two algorithms only where they give the same results: where AL and
// PM differ in a situation (as with friction), the situation's cells are split by algorithm,
// the matrix cell gives each one's error, and the advice names the one to avoid alone.
TEST(VerdictPage, AFamilyWhoseMembersDifferIsSplitInThatSituation) {
  schema::ResultsDocument doc = battery().doc;
  schema::RowVerdict* pm = nullptr;
  for (auto& r : doc.rows) {
    if (r.id == "H_p/Q4/PM/ss/sigma_c")
      pm = &r;
  }
  ASSERT_NE(pm, nullptr);
  ASSERT_TRUE(pm->values[2] && pm->errors[2]);
  const double exact = *pm->values[2] / (1.0 + *pm->errors[2] / 100.0);
  pm->values[2] = 1.2 * exact;  // PM alone: +20 %, graded u
  pm->errors[2] = 20.0;
  const ResultsIndex index(doc);
  const std::vector<RowFacts> rows = row_facts(index);  // the cells point into them
  const std::vector<DivergenceFacts> singular = divergence_facts(index);
  const auto situations = situation_verdicts(index, rows, singular);
  const auto hertz =
      std::find_if(situations.begin(), situations.end(),
                   [](const SituationVerdict& s) { return s.key == "smooth_curved"; });
  ASSERT_NE(hertz, situations.end());
  std::map<Algorithm, const OptionCell*> ss_q4;
  for (const auto& c : hertz->cells) {
    if (c.code.empty() && c.family == OptionFamily::penalty &&
        c.contact == schema::ContactKind::ss && c.element == schema::Element::Q4) {
      ASSERT_TRUE(c.algorithm.has_value());
      ss_q4[*c.algorithm] = &c;
    }
  }
  ASSERT_EQ(ss_q4.size(), 2U);
  EXPECT_EQ(*ss_q4.at(Algorithm::PM)->worst_grade, schema::Grade::u);
  EXPECT_NE(*ss_q4.at(Algorithm::AL)->worst_grade, schema::Grade::u);
  EXPECT_EQ(option_label(*ss_q4.at(Algorithm::PM)), "PM ss");
  EXPECT_TRUE(std::count(hertz->avoid.begin(), hertz->avoid.end(), ss_q4.at(Algorithm::PM)));
  EXPECT_FALSE(std::count(hertz->avoid.begin(), hertz->avoid.end(), ss_q4.at(Algorithm::AL)));
  // The patch tests, where the two still coincide, keep one cell for both.
  for (const auto& s : situations) {
    for (const auto& c : s.cells) {
      if (s.key != "smooth_curved") {
        EXPECT_FALSE(c.algorithm.has_value()) << s.key << " " << option_label(c);
      }
    }
  }
  const std::string md = verdict_page(index, situations);
  EXPECT_NE(md.find("| AL, PM ss |"), std::string::npos) << md;
  EXPECT_NE(md.find(" · PM u +20.0 %"), std::string::npos) << md;
  EXPECT_NE(md.find("Avoid PM ss Q4"), std::string::npos) << md;
}

TEST(VerdictPage, FitsOnTheFirstScreen) {
  const auto situations = situation_verdicts(battery().index, battery().rows, battery().singular);
  const std::string md = verdict_page(battery().index, situations);
  EXPECT_LE(std::count(md.begin(), md.end(), '\n'), 60);
}

}  // namespace
}  // namespace cs::reports

namespace cs::reports {
namespace {

/// The battery's claims without its PLM and MPC rows.
std::vector<ClaimEvidence> claims_without_plm_and_mpc() {
  std::vector<RowFacts> rows = battery().rows;
  std::erase_if(rows, [](const RowFacts& f) {
    return f.option.algorithm == Algorithm::PLM || f.option.algorithm == Algorithm::MPC;
  });
  return study_claims(battery().index, rows, {});
}

// Requirement: the closing remarks (claim 12) name the algorithms of each part that have rows,
// and say what the rows are ("g or better on F"); claim 6 without any MPC row says so.
TEST(ClaimsLedger, ClosingRemarksNameTheAlgorithmsRun) {
  const auto claims = claims_without_plm_and_mpc();
  const ClaimEvidence& closing = claim_in(claims, "closing");
  EXPECT_EQ(closing.members, "AL/PM");
  EXPECT_EQ(closing.members2, "LMP");
  const std::string md = claims_ledger({closing, claim_in(claims, "mpc_unsatisfactory")});
  EXPECT_NE(md.find(" LMP rows with aligned nodes are g or better on F"), std::string::npos) << md;
  EXPECT_EQ(md.find("LMP/PLM rows"), std::string::npos) << md;
  EXPECT_NE(md.find("No MPC row is in these results."), std::string::npos) << md;
  EXPECT_EQ(md.find("On the patch tests"), std::string::npos) << md;
}

// Requirement: claim 3 names the algorithms it ran: without PLM and MPC rows its first part is
// "LMP" and its IMC part "not run", never "LMP, PLM" or a pair that is no evidence.
TEST(ClaimsLedger, SsEqualsNsNamesTheAlgorithmsRun) {
  const auto claims = claims_without_plm_and_mpc();
  const ClaimEvidence& c = claim_in(claims, "ss_equals_ns");
  EXPECT_EQ(c.members, "LMP");
  EXPECT_FALSE(c.part2_run);
  const std::string md = claims_ledger({c});
  EXPECT_NE(md.find("LMP: "), std::string::npos) << md;
  EXPECT_EQ(md.find("LMP, PLM: "), std::string::npos) << md;
  EXPECT_NE(md.find("IMC: not run (this part: not testable here)"), std::string::npos) << md;
}

}  // namespace
}  // namespace cs::reports

namespace cs::reports {
namespace {

// Requirement: an option not run on every problem of a situation that another option was run
// on covers part of it: its cell says which problem it lacks and has no grade, so it is never
// among the best (LMP run on P_p and P_a, AL on P_p alone).
TEST(VerdictPage, ACellNotRunOnEveryProblemOfItsSituationHasNoGrade) {
  auto doc = testing::sample_json();
  nlohmann::json p_a = doc["problems"][0];
  ASSERT_EQ(p_a["id"], "P_p");
  p_a["id"] = "P_a";
  p_a["axisymmetric"] = true;
  doc["problems"].push_back(p_a);
  testing::copy_problem(doc, "P_p", "P_a", [](const std::string& id) {
    return id.find("/LMP/") != std::string::npos;
  });
  const testing::Loaded data(doc);
  const std::vector<RowFacts> rows = row_facts(data.index);  // the cells point into them
  const std::vector<DivergenceFacts> singular = divergence_facts(data.index);
  const auto situations = situation_verdicts(data.index, rows, singular);
  const auto flat = std::ranges::find_if(situations, [](const SituationVerdict& s) {
    return std::ranges::find(s.problems, schema::ProblemId::P_a) != s.problems.end();
  });
  ASSERT_NE(flat, situations.end());
  int penalty = 0;
  for (const OptionCell& c : flat->cells) {
    if (c.family == OptionFamily::penalty) {
      ++penalty;
      EXPECT_EQ(c.not_run_on, std::vector<schema::ProblemId>{schema::ProblemId::P_a});
      EXPECT_FALSE(c.worst_grade.has_value());
      EXPECT_EQ(std::ranges::count(flat->best, &c), 0);
      EXPECT_NE(verdict_cell(c).find("not run on P<sub>a</sub>"), std::string::npos)
          << verdict_cell(c);
    } else {
      EXPECT_TRUE(c.not_run_on.empty());
    }
  }
  EXPECT_GT(penalty, 0);
}

// Requirement: a row naming two algorithms ("AL, PM ss") names, in a cell, the one that alone
// was run on that situation ("PM e …"): the battery without AL on the Steuermann punch.
TEST(VerdictPage, ACellOfOneMemberOfItsRowNamesIt) {
  std::ifstream in(testing::source_dir() / "tests" / "reports" / "data" / "battery_results.json");
  auto doc = nlohmann::json::parse(in);
  for (const std::string key : {"cases", "rows"}) {
    auto& entries = doc[key];
    entries.erase(std::remove_if(entries.begin(), entries.end(),
                                 [](const nlohmann::json& e) {
                                   const std::string id = e["id"];
                                   return id.starts_with("S_1/") &&
                                          id.find("/AL/") != std::string::npos;
                                 }),
                  entries.end());
  }
  const testing::Loaded data(doc);
  const std::vector<RowFacts> rows = row_facts(data.index);  // the cells point into them
  const std::vector<DivergenceFacts> singular = divergence_facts(data.index);
  const auto situations = situation_verdicts(data.index, rows, singular);
  const std::string md = verdict_page(data.index, situations);
  const auto column = [&](const std::string& title) {
    const auto header = md.find("| Option |");
    const std::string line = md.substr(header, md.find('\n', header) - header);
    int n = 0;
    for (std::size_t at = 0; at < line.find(title); at = line.find('|', at + 1))
      ++n;
    return n;
  };
  const int steuermann = column("Punch with rounded edges"), hertz = column("Hertz");
  const auto cell = [&](const std::string& row, int col) {
    const auto at = md.find("| " + row + " |");
    EXPECT_NE(at, std::string::npos) << row;
    std::string line = md.substr(at, md.find('\n', at) - at);
    std::size_t from = 0;
    for (int i = 0; i < col; ++i)
      from = line.find('|', from) + 1;
    return line.substr(from, line.find('|', from) - from);
  };
  EXPECT_TRUE(cell("AL, PM ss", steuermann).starts_with(" PM ")) << cell("AL, PM ss", steuermann);
  EXPECT_FALSE(cell("AL, PM ss", hertz).starts_with(" PM ")) << cell("AL, PM ss", hertz);
  EXPECT_FALSE(cell("LMP, PLM ss", steuermann).starts_with(" LMP ")) << md;
}

// Requirement: where one member of a family was run on part of a situation (AL on H_p, PM on
// H_p and H_a), the cell is split by algorithm: AL's half is "not run on H_a" with no grade,
// and no cell shows PM's H_a error under AL's name.
TEST(VerdictPage, AMemberRunOnPartOfASituationIsSplitOut) {
  std::ifstream in(testing::source_dir() / "tests" / "reports" / "data" / "battery_results.json");
  auto doc = nlohmann::json::parse(in);
  for (auto record : doc["problems"]) {
    if (record["id"] == "H_p") {
      record["id"] = "H_a";
      record["axisymmetric"] = true;
      doc["problems"].push_back(record);
      break;
    }
  }
  testing::copy_problem(doc, "H_p", "H_a",
                        [](const std::string& id) { return id.find("/PM/") != std::string::npos; });
  const testing::Loaded data(doc);
  const std::vector<RowFacts> rows = row_facts(data.index);
  const std::vector<DivergenceFacts> singular = divergence_facts(data.index);
  const auto situations = situation_verdicts(data.index, rows, singular);
  const auto hertz = std::ranges::find_if(situations, [](const SituationVerdict& s) {
    return std::ranges::find(s.problems, schema::ProblemId::H_a) != s.problems.end();
  });
  ASSERT_NE(hertz, situations.end());
  int al = 0, pm = 0;
  for (const OptionCell& c : hertz->cells) {
    if (c.family != OptionFamily::penalty)
      continue;
    ASSERT_TRUE(c.algorithm.has_value()) << option_label(c);
    if (*c.algorithm == Algorithm::AL) {
      ++al;
      EXPECT_EQ(c.not_run_on, std::vector<schema::ProblemId>{schema::ProblemId::H_a});
      EXPECT_FALSE(c.worst_grade.has_value());
    } else {
      ++pm;
      EXPECT_TRUE(c.not_run_on.empty());
      EXPECT_TRUE(c.problems.contains(schema::ProblemId::H_a));
    }
  }
  EXPECT_GT(al, 0);
  EXPECT_EQ(al, pm);
}

}  // namespace
}  // namespace cs::reports
