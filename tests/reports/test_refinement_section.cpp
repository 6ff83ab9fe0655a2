// The "Error estimates and refinement" section's facts: which rows the study's "further
// refinement would lead to converging results" applies to and whether it holds (only a VF case
// that converged counts), the GCI band test, round-off rows left out, and estimates.csv.

#include <algorithm>
#include <array>
#include <numeric>
#include <sstream>

#include <gtest/gtest.h>

#include "grading/accuracy.hpp"
#include "grading/richardson.hpp"
#include "reports/facts/claims.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/findings/refinement_section.hpp"
#include "reports/pages/claims_ledger.hpp"

namespace cs::reports {
namespace {

using schema::RowVerdict;

/// A row with errors C, M, F (percent), the study's c as given, and a VF error if any.
RowVerdict row(std::array<double, 3> errors, bool converging, std::optional<double> vf_error) {
  RowVerdict r;
  for (std::size_t m = 0; m < 3; ++m)
    r.errors[m] = errors[m];
  r.converging = converging;
  if (vf_error) {
    r.refinement.emplace();
    r.refinement->error = vf_error;
  }
  return r;
}

// Requirement: the claim applies only to rows graded s or better on F without the study's c;
// it holds when the trend over M-F-VF converges, fails when it does not, and stays open when
// the VF case is missing or did not converge.
TEST(RefinementSection, StudyClaimCountsOnlyConvergedVfCases) {
  const auto s_row = [](std::optional<double> vf) { return row({8.0, 7.0, 6.0}, false, vf); };
  EXPECT_TRUE(refinement_claim_applies(s_row(3.0)));
  EXPECT_EQ(vf_judgement(s_row(3.0), MeshState::converged, 0.0), VfJudgement::converges);
  EXPECT_EQ(vf_judgement(s_row(9.0), MeshState::converged, 0.0), VfJudgement::fails);
  EXPECT_EQ(vf_judgement(s_row(3.0), MeshState::not_converged, 0.0), VfJudgement::vf_not_converged);
  EXPECT_EQ(vf_judgement(s_row(3.0), MeshState::failed, 0.0), VfJudgement::vf_not_converged);
  EXPECT_EQ(vf_judgement(s_row(std::nullopt), MeshState::missing, 0.0), VfJudgement::no_vf);
  EXPECT_EQ(vf_judgement(s_row(3.0), MeshState::converged, 0.0, false), VfJudgement::not_evidence);
  EXPECT_FALSE(refinement_claim_applies(row({8.0, 7.0, 6.0}, true, 3.0)));      // already c
  EXPECT_FALSE(refinement_claim_applies(row({14.0, 13.0, 12.0}, false, 3.0)));  // u on F
}

constexpr double kUnitExact = 1.0;

/// A baseline row of H_p sigma_c with values on C, M, F (and VF when given, with its status).
void add_row(schema::ResultsDocument& doc, schema::Algorithm algorithm, schema::ContactKind contact,
             std::array<double, 3> values, std::optional<double> vf = std::nullopt,
             schema::CaseStatus vf_status = schema::CaseStatus::converged) {
  RowVerdict r;
  r.spec.problem = schema::ProblemId::H_p;
  r.spec.algorithm = algorithm;
  r.spec.contact = contact;
  r.quantity = schema::Quantity::sigma_c;
  r.id = schema::case_key(r.spec) + "/sigma_c";
  const auto add_case = [&](schema::MeshLevel mesh, double value, schema::CaseStatus status) {
    schema::CaseResult c;
    c.spec = r.spec;
    c.spec.mesh = mesh;
    c.status = status;
    schema::QuantityResult q;
    q.quantity = schema::Quantity::sigma_c;
    q.value = value;
    q.exact = kUnitExact;
    q.error_percent = grading::error_percent(value, kUnitExact);
    c.quantities.push_back(q);
    doc.cases.push_back(c);
  };
  for (std::size_t m = 0; m < 3; ++m) {
    r.values[m] = values[m];
    r.errors[m] = grading::error_percent(values[m], kUnitExact);
    add_case(static_cast<schema::MeshLevel>(m), values[m], schema::CaseStatus::converged);
  }
  r.converging = false;
  r.estimate = schema::ErrorEstimate{};
  r.estimate->note = "oscillatory";
  if (vf) {
    r.refinement.emplace();
    r.refinement->value = *vf;
    r.refinement->error = grading::error_percent(*vf, kUnitExact);
    add_case(schema::MeshLevel::VF, *vf, vf_status);
  }
  doc.rows.push_back(r);
}

schema::ResultsDocument vf_document() {
  schema::ResultsDocument doc;
  schema::ProblemRecord p;
  p.id = schema::ProblemId::H_p;
  p.quantities = {{schema::Quantity::sigma_c, "peak", "peak", "1", "main"}};
  doc.problems.push_back(p);
  using A = schema::Algorithm;
  using K = schema::ContactKind;
  // s on F, not c: VF converged and closer (holds); VF converged and worse (fails); VF not
  // converged at +85 % (open, not counted, marked).
  add_row(doc, A::AL, K::ss, {1.08, 1.07, 1.06}, 1.03);
  add_row(doc, A::LMP, K::ss, {1.08, 1.07, 1.06}, 1.09);
  add_row(doc, A::MPC, K::ss, {1.08, 1.07, 1.06}, 1.85, schema::CaseStatus::not_converged);
  // Exact to round-off on every mesh (a patch test): left out of the estimates.
  add_row(doc, A::PM, K::ns, {1.0, 1.0, 1.0});
  return doc;
}

// Requirement: "further refinement would converge" counts only rows whose VF case converged
// (1 holds, 1 fails, 1 open of 3 that apply); an MPC row whose VF case did not converge is left
// out of the MPC refinement too; a round-off row is left out of the estimates.
TEST(RefinementSection, FactsCountOnlyConvergedVfCases) {
  const schema::ResultsDocument doc = vf_document();
  const ResultsIndex index(doc);
  const RefinementFacts f = refinement_facts(index);
  EXPECT_EQ(f.claim.by, (std::array{1, 0, 0, 1, 0, 1, 0}));  // holds, fails, VF not converged
  EXPECT_EQ(f.mpc.trends(), 0);
  EXPECT_EQ(f.mpc[VfJudgement::vf_not_converged], 1);
  EXPECT_EQ(f.round_off, 1);
  ASSERT_EQ(f.problems.size(), 1u);
  EXPECT_EQ(f.problems[0].rows, 3);
  EXPECT_EQ(f.problems[0].asymptotic, 0);
  ASSERT_EQ(f.vf_rows.size(), 3u);
  EXPECT_EQ(f.vf_rows[2].vf, MeshState::not_converged);
}

// Requirement: the not-converged VF value is never shown unmarked, on the page or in the CSV;
// the CSV has one line per row with C, M and F values, round-off rows included and marked.
TEST(RefinementSection, MarksVfValuesOfCasesThatDidNotConverge) {
  const schema::ResultsDocument doc = vf_document();
  const ResultsIndex index(doc);
  const std::string md = refinement_section(index);
  EXPECT_NE(md.find("| +85.0 % (not converged) |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| +85.0 % |"), std::string::npos) << md;
  // Rows are named with the quantity's label, as the prose names it, not its id.
  EXPECT_NE(md.find("H<sub>p</sub> σ̄<sub>c</sub> Q4"), std::string::npos) << md;
  EXPECT_EQ(md.find("H<sub>p</sub> sigma_c"), std::string::npos) << md;
  const std::string csv = estimates_csv(index);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // header and 4 rows
  EXPECT_NE(csv.find(",1.85,85,not_converged,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("H_p/Q4/PM/ns/sigma_c,1,1,1,0,1,"), std::string::npos) << csv;
}

// Requirement: estimates.csv quotes a field that holds a comma (a note "pre-asymptotic (p1 =
// 5.47, p2 = 3.88 ...)"), so every line has the header's fields.
TEST(RefinementSection, EstimatesCsvQuotesItsFields) {
  schema::ResultsDocument doc = vf_document();
  doc.rows.front().estimate = schema::ErrorEstimate{false, {}, {}, {}, "one, two"};
  const ResultsIndex index(doc);
  const std::string csv = estimates_csv(index);
  EXPECT_NE(csv.find(",\"one, two\","), std::string::npos) << csv;
  std::istringstream lines(csv);
  std::string header;
  std::getline(lines, header);
  const auto fields = [](const std::string& line) {  // commas outside quotes, plus one
    bool quoted = false;
    int n = 1;
    for (const char c : line) {
      quoted = c == '"' ? !quoted : quoted;
      n += c == ',' && !quoted ? 1 : 0;
    }
    return n;
  };
  for (std::string line; std::getline(lines, line);)
    EXPECT_EQ(fields(line), fields(header)) << line;
}

// Requirement: a results file without VF cases says so in one line; one without C, M, F rows
// has no section and no CSV.
TEST(RefinementSection, OneLineWithoutVfAndNothingWithoutRows) {
  schema::ResultsDocument doc = vf_document();
  std::erase_if(doc.cases, [](const auto& c) { return c.spec.mesh == schema::MeshLevel::VF; });
  for (auto& r : doc.rows)
    r.refinement.reset();
  const ResultsIndex index(doc);
  EXPECT_NE(refinement_section(index).find("No VF mesh in these results"), std::string::npos);
  const schema::ResultsDocument empty;
  const ResultsIndex none(empty);
  EXPECT_EQ(refinement_section(none), "");
  EXPECT_EQ(estimates_csv(none), "");
}

}  // namespace
}  // namespace cs::reports

namespace cs::reports {
namespace {

// Requirement: an order of the errors is printed only where the values converge to the exact
// value. Values 1.04, 1.02, 1.015 converge at order 2 to 1.0133: 1.33 % above the exact 1, the
// exact value outside their GCI band and further from the limit than F is: the row keeps that
// limit and no order. Values 1.04, 1.01, 1.0025 converge to the exact value: order 2.
TEST(RefinementSection, AnOrderOfTheErrorsOnlyWhereTheValuesConvergeToTheExactValue) {
  schema::ResultsDocument doc = vf_document();
  doc.rows.clear();
  doc.cases.clear();
  using A = schema::Algorithm;
  using K = schema::ContactKind;
  add_row(doc, A::AL, K::ss, {1.04, 1.02, 1.015});
  doc.rows.back().estimate = grading::error_estimate(1.04, 1.02, 1.015);
  add_row(doc, A::LMP, K::ss, {1.04, 1.01, 1.0025});
  doc.rows.back().estimate = grading::error_estimate(1.04, 1.01, 1.0025);
  const ResultsIndex index(doc);
  const RowFacts biased = facts_of_row(index, doc.rows[0]);
  EXPECT_FALSE(biased.order.has_value());
  ASSERT_TRUE(biased.biased_limit.has_value());
  EXPECT_NEAR(biased.biased_limit->error_percent, 100.0 * (1.015 - 0.005 / 3 - 1.0), 1e-9);
  EXPECT_NEAR(biased.biased_limit->order, 2.0, 1e-9);
  const RowFacts exact = facts_of_row(index, doc.rows[1]);
  EXPECT_FALSE(exact.biased_limit.has_value());
  ASSERT_TRUE(exact.order.has_value()) << exact.order_note;
  EXPECT_NEAR(*exact.order, 2.0, 1e-9);
  // A row whose F case did not converge says nothing of how the option converges: no limit.
  for (auto& c : doc.cases) {
    if (c.spec.algorithm == A::AL && c.spec.mesh == schema::MeshLevel::F)
      c.status = schema::CaseStatus::not_converged;
  }
  const ResultsIndex unconverged(doc);
  EXPECT_FALSE(facts_of_row(unconverged, doc.rows[0]).biased_limit.has_value());
}

// Requirement: the claims ledger (claims 9 and 10) and the estimates appendix judge "further
// refinement would converge" by one rule, the trend over M-F-VF: a row whose error is the same
// +0.71 % on every mesh is a plateau (a bias), not convergence, and fails the claim in both;
// an MPC row exact to round-off has nothing to improve and is left out of claim 10; a row that
// is not evidence on F counts in neither place.
TEST(RefinementSection, LedgerAndAppendixJudgeRefinementByOneRule) {
  schema::ResultsDocument doc = vf_document();
  doc.rows.clear();
  doc.cases.clear();
  doc.problems[0].study_tables = "7";
  using A = schema::Algorithm;
  using K = schema::ContactKind;
  add_row(doc, A::AL, K::ss, {1.08, 1.07, 1.06}, 1.03);          // converges: holds
  add_row(doc, A::LMP, K::ss, {1.08, 1.07, 1.06}, 1.09);         // not converging: fails
  add_row(doc, A::PM, K::ss, {1.0071, 1.0071, 1.0071}, 1.0071);  // a plateau: fails
  add_row(doc, A::MPC, K::ss, {1.08, 1.07, 1.06}, 1.03);         // converges
  add_row(doc, A::MPC, K::ns, {1.0, 1.0, 1.0}, 1.0);             // round-off
  doc.rows.back().converging = true;
  // Converging on VF, but its F case did not converge: not evidence, judged nowhere.
  add_row(doc, A::MPC, K::mortar, {1.08, 1.07, 1.06}, 1.03);
  // No VF case: in the claim's scope, but not judged; the ledger says so.
  add_row(doc, A::AL, K::ns, {1.08, 1.07, 1.06});
  // No VF case and not evidence on F (its F case did not converge): left out, not counted
  // among the rows a VF case would judge.
  add_row(doc, A::PLM, K::mortar, {1.08, 1.07, 1.06});
  for (auto& c : doc.cases) {
    if (c.spec.contact == K::mortar && c.spec.mesh == schema::MeshLevel::F)
      c.status = schema::CaseStatus::not_converged;
  }
  const ResultsIndex index(doc);
  const RefinementFacts f = refinement_facts(index);
  const int holds = f.claim[VfJudgement::converges] + f.claim[VfJudgement::at_resolution];
  EXPECT_EQ(holds, 2);
  EXPECT_EQ(f.claim[VfJudgement::plateau], 1);
  EXPECT_EQ(f.claim[VfJudgement::fails], 1);
  EXPECT_EQ(f.claim[VfJudgement::not_evidence], 1);
  EXPECT_EQ(std::accumulate(f.claim.by.begin(), f.claim.by.end(), 0), 5);  // 5 with a VF case
  EXPECT_EQ(f.mpc[VfJudgement::not_evidence], 1);
  EXPECT_EQ(f.mpc.trends(), 1);
  EXPECT_EQ(f.mpc[VfJudgement::converges], 1);
  EXPECT_EQ(f.mpc[VfJudgement::at_resolution], 1);
  const auto claims = study_claims(index, row_facts(index), {});
  const auto claim = [&](const std::string& key) {
    return *std::find_if(claims.begin(), claims.end(),
                         [&](const ClaimEvidence& c) { return c.key == key; });
  };
  const ClaimEvidence nine = claim("refinement");
  EXPECT_EQ(nine.n, 4);
  EXPECT_EQ(nine.n_hold, 2);
  EXPECT_EQ(nine.n_plateau, 1);
  EXPECT_EQ(nine.n_excluded, 2);                          // MPC and PLM mortar: F not converged
  EXPECT_EQ(nine.n2, 1);                                  // no VF case, evidence on F
  EXPECT_EQ(nine.verdict, ClaimVerdict::not_reproduced);  // 2 of 4
  const ClaimEvidence ten = claim("mpc_refinement");
  EXPECT_EQ(ten.n, 1);
  EXPECT_EQ(ten.n_hold, 1);
  EXPECT_EQ(ten.n_round_off, 1);
  EXPECT_EQ(ten.n_excluded, 1);
  EXPECT_EQ(ten.verdict, ClaimVerdict::reproduced);
  const std::string md = claims_ledger(claims);
  EXPECT_NE(md.find("further refinement converges in 2"), std::string::npos) << md;
  EXPECT_NE(md.find("1 settle at a larger error"), std::string::npos) << md;
  EXPECT_NE(md.find("1 more rows the claim applies to, evidence on F, have no VF case and are not "
                    "judged"),
            std::string::npos)
      << md;
  // The appendix says where its plateaus are, so that one bias can be told from another.
  const std::string appendix = refinement_section(index);
  EXPECT_NE(appendix.find("(by problem, quantity and element: H<sub>p</sub> σ̄<sub>c</sub> Q4 (1))"),
            std::string::npos)
      << appendix;
  // The examples of rows that do not converge name only those: the plateau is not among them.
  EXPECT_NE(nine.examples.find("LMP"), std::string::npos) << nine.examples;
  EXPECT_EQ(nine.examples.find(" PM "), std::string::npos) << nine.examples;
  // Each example shows the window judged, M, F and VF.
  EXPECT_NE(nine.examples.find(": M +7.00 % → F +6.00 % → VF +9.00 %"), std::string::npos)
      << nine.examples;
  // estimates.csv flags each row as evidence on F or not (its last field): the mortar rows,
  // whose F case did not converge, are not; AL ss is.
  const std::string csv = estimates_csv(index);
  const auto last_field = [&](const std::string& id) {
    const auto at = csv.find("\n" + id + ",");
    return at == std::string::npos ? std::string("none")
                                   : csv.substr(csv.find('\n', at + 1) - 2, 2);
  };
  EXPECT_EQ(last_field("H_p/Q4/MPC/mortar/sigma_c"), ",0") << csv;
  EXPECT_EQ(last_field("H_p/Q4/AL/ss/sigma_c"), ",1") << csv;
}

// Requirement: with no MPC row left to judge (here one at round-off), the appendix draws no
// verdict on the study's "could be improved" either way.
TEST(RefinementSection, NoVerdictFromNoMpcRowJudged) {
  schema::ResultsDocument doc = vf_document();
  doc.rows.clear();
  doc.cases.clear();
  add_row(doc, schema::Algorithm::MPC, schema::ContactKind::ns, {1.0, 1.0, 1.0}, 1.0);
  doc.rows.back().converging = true;
  const ResultsIndex index(doc);
  ASSERT_EQ(refinement_facts(index).mpc.trends(), 0);
  const std::string md = refinement_section(index);
  EXPECT_NE(md.find("is not testable here: no row is left to judge"), std::string::npos) << md;
  EXPECT_EQ(md.find("for most of the rows judged"), std::string::npos) << md;
}

}  // namespace
}  // namespace cs::reports
