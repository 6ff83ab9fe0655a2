#include "schema/case_spec.hpp"

#include <fmt/format.h>

namespace cs::schema {
namespace {

std::string options_suffix(const CaseSpec& spec) {
  std::string id;
  if (spec.target == TargetKind::Rigid)
    id += "/rigid";
  if (spec.recovery != Recovery::spr)
    id += fmt::format("/{}", to_string(spec.recovery));
  for (const auto& [name, value] : spec.overrides)
    id += fmt::format("/{}={}", name, value);
  if (spec.solver != SolverKind::builtin)
    id += "/@" + solver_label(spec);
  return id;
}

}  // namespace

std::string solver_label(const CaseSpec& spec) {
  if (spec.solver == SolverKind::imported)
    return spec.solver_name;
  return std::string(to_string(spec.solver));
}

bool is_baseline(const CaseSpec& spec) {
  return spec.solver == SolverKind::builtin && spec.target == TargetKind::Discretized &&
         spec.recovery == Recovery::spr && spec.overrides.empty();
}

std::string case_id(const CaseSpec& spec) {
  return fmt::format("{}/{}/{}/{}/{}", to_string(spec.problem), to_string(spec.mesh),
                     to_string(spec.element), to_string(spec.algorithm), to_string(spec.contact)) +
         options_suffix(spec);
}

std::string case_key(const CaseSpec& spec) {
  return fmt::format("{}/{}/{}/{}", to_string(spec.problem), to_string(spec.element),
                     to_string(spec.algorithm), to_string(spec.contact)) +
         options_suffix(spec);
}

}  // namespace cs::schema
