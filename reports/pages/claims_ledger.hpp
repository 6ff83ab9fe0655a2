#pragma once
// The study's claims ledger: each claim in the study's words with its place in the paper, our
// evidence with numbers, and a verdict (reproduced, refined, not reproduced, not testable here).
// Numbers: facts/claims.hpp; prose: templates/claims_ledger.mustache.

#include <string>
#include <vector>

#include "reports/facts/claims.hpp"

namespace cs::reports {

std::string claims_ledger(const std::vector<ClaimEvidence>& claims);

}  // namespace cs::reports
