#include "apps/solver_option_mappings.hpp"

#include "adapters/calculix/calculix_options.hpp"
#include "schema/case_axes.hpp"

namespace cs::apps {

std::vector<reports::SolverOptionMapping> solver_option_mappings() {
  std::vector<reports::SolverOptionMapping> out;
  const std::string calculix(schema::to_string(schema::SolverKind::calculix));
  for (const auto& m : adapters::calculix::calculix_option_mapping())
    out.push_back({calculix, m.study_option, m.calculix, m.fidelity, m.note});
  return out;
}

}  // namespace cs::apps
