#include "reports/facts/refinement_claim.hpp"

#include "grading/accuracy.hpp"
#include "reports/facts/row_facts.hpp"

namespace cs::reports {

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

bool refinement_claim_applies(const schema::RowVerdict& row) {
  return row.errors[2] && row.converging && !*row.converging &&
         !schema::is_worse(grading::grade_of_error(*row.errors[2]), schema::Grade::s);
}

int VfTally::trends() const {
  return (*this)[VfJudgement::converges] + (*this)[VfJudgement::plateau] +
         (*this)[VfJudgement::fails];
}

int VfTally::open() const {
  return (*this)[VfJudgement::not_evidence] + (*this)[VfJudgement::vf_not_converged];
}

VfTally tally_vf(const ResultsIndex& index, const std::vector<const schema::RowVerdict*>& rows) {
  VfTally t;
  for (const schema::RowVerdict* row : rows)
    ++t.by[static_cast<std::size_t>(vf_judgement(index, *row))];
  return t;
}

}  // namespace cs::reports
