#include "reports/facts/refinement_claim.hpp"

#include "grading/accuracy.hpp"
#include "reports/facts/row_facts.hpp"

namespace cs::reports {
namespace {

/// Whether the study's claim applies: s or better on F, without the study's c.
bool claim_applies(const schema::RowVerdict& row) {
  return row.errors[2] && row.converging && !*row.converging &&
         !schema::is_worse(grading::grade_of_error(*row.errors[2]), schema::Grade::s);
}

/// The claim where it applies: VF converging or settled at the study's resolution holds it.
RefinementClaim claim_of(VfJudgement j) {
  switch (j) {
    case VfJudgement::converges:
    case VfJudgement::at_resolution:
      return RefinementClaim::holds;
    case VfJudgement::plateau:
      return RefinementClaim::plateau;
    case VfJudgement::fails:
      return RefinementClaim::fails;
    case VfJudgement::not_evidence:
      return RefinementClaim::not_evidence;
    case VfJudgement::vf_not_converged:
      return RefinementClaim::vf_not_converged;
    case VfJudgement::no_vf:
      break;
  }
  return RefinementClaim::no_vf;
}

}  // namespace

VfJudgement vf_judgement(const schema::RowVerdict& row, MeshState vf, double resolution_on_m,
                         bool evidence) {
  if (!row.refinement || vf == MeshState::missing)
    return VfJudgement::no_vf;
  if (vf != MeshState::converged || !row.refinement->error || !row.errors[1] || !row.errors[2])
    return VfJudgement::vf_not_converged;
  if (!evidence)
    return VfJudgement::not_evidence;
  switch (grading::further_refinement(*row.errors[1], *row.errors[2], *row.refinement->error,
                                      resolution_on_m)) {
    case grading::FurtherRefinement::converges:
      return VfJudgement::converges;
    case grading::FurtherRefinement::at_resolution:
      return VfJudgement::at_resolution;
    case grading::FurtherRefinement::plateau:
      return VfJudgement::plateau;
    case grading::FurtherRefinement::fails:
      break;
  }
  return VfJudgement::fails;
}

VfJudgement vf_judgement(const ResultsIndex& index, const schema::RowVerdict& row) {
  return vf_judgement(row, index.state(row, schema::MeshLevel::VF),
                      index.read_resolution_percent(row, schema::MeshLevel::M),
                      facts_of_row(index, row).evidence());
}

RefinementClaim refinement_claim(const schema::RowVerdict& row, MeshState vf,
                                 double resolution_on_m, bool evidence) {
  return claim_applies(row) ? claim_of(vf_judgement(row, vf, resolution_on_m, evidence))
                            : RefinementClaim::not_applicable;
}

RefinementClaim refinement_claim(const ResultsIndex& index, const schema::RowVerdict& row) {
  return claim_applies(row) ? claim_of(vf_judgement(index, row)) : RefinementClaim::not_applicable;
}

}  // namespace cs::reports
