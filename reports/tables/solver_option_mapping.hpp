#pragma once
// How the study's contact options map to another solver's own, as the report states it. The
// report reads results only, so the mapping is handed in by the command line (apps/), which
// takes it from the registered codes' manifests (apps/solver_option_mappings.hpp).

#include <string>
#include <vector>

namespace cs::reports {

/// One row: a study option and what the solver runs for it.
struct SolverOptionMapping {
  std::string solver;        ///< the solver's label in results.json, e.g. "calculix"
  std::string study_option;  ///< "ns", "ss", "mortar", "PM", "AL", "LMP", "PLM", "MPC"
  std::string target;    ///< what the solver is given, e.g. "*CONTACT PAIR, TYPE=NODE TO SURFACE"
  std::string fidelity;  ///< "same", "approximated" or "not supported"
  std::string note;      ///< why, in one line
};

/// The mapping of the solvers in `solvers` as a Markdown table with a lead-in sentence (empty
/// when none of them has a mapping).
std::string option_mapping_markdown(const std::vector<SolverOptionMapping>& mappings,
                                    const std::vector<std::string>& solvers);

}  // namespace cs::reports
