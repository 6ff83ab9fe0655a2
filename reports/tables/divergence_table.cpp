#include "reports/tables/divergence_table.hpp"

#include <cmath>
#include <map>

#include <fmt/format.h>

#include "grading/divergence.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using Values = std::array<std::optional<double>, 3>;

/// "0.46", "−0.05" (the minus sign as in the other tables).
std::string format_exponent(double alpha) {
  return with_minus_sign(fmt::format("{:.2f}", std::abs(alpha) < 0.005 ? 0.0 : alpha));
}

/// The values, the Eq. 47 cell, the exponent cell and the strict cell of one sequence.
std::array<std::string, 4> sequence_cells(const Values& v,
                                          const std::optional<schema::DivergenceVerdict>& d) {
  const std::string values =
      !v[0] && !v[1] && !v[2]
          ? std::string(kMissing)
          : join_meshes({format_value(v[0]), format_value(v[1]), format_value(v[2])});
  if (!d)
    return {values, kMissing, kMissing, kMissing};
  return {values, d->eq47 ? "diverges" : "**does not diverge**",
          d->exponent ? format_exponent(*d->exponent) : std::string(kMissing),
          d->diverges ? "diverges" : "**does not diverge**: " + strict_failure_reason(v, *d)};
}

}  // namespace

std::string strict_failure_reason(const Values& v, const schema::DivergenceVerdict& d) {
  if (d.diverges)
    return {};
  if (!d.exponent) {
    const bool tensile = (v[0] && *v[0] <= 0) || (v[1] && *v[1] <= 0) || (v[2] && *v[2] <= 0);
    return tensile ? "tensile or changing sign" : "changing sign";
  }
  if (!d.monotone) {
    const bool shrinking = std::abs(*v[2]) < std::abs(*v[1]) && std::abs(*v[1]) < std::abs(*v[0]);
    // -sigma_z/p below 0 on every mesh: the "compressive" edge stress is a tension.
    const bool tensile = *v[0] < 0 && *v[1] < 0 && *v[2] < 0;
    return std::string(tensile ? "tensile, " : "") + (shrinking ? "shrinking" : "not monotone");
  }
  return fmt::format("grows at α {} per halving of h, outside [{}, {}]",
                     format_exponent(*d.exponent), grading::kDivergenceExponentMin,
                     grading::kDivergenceExponentMax);
}

DivergenceTableFacts build_divergence_table(const ResultsIndex& index,
                                            const schema::StudyReference& study) {
  const std::string cmf = join_meshes({"C", "M", "F"});
  DivergenceTableFacts out{
      .table = MarkdownTable({"Problem", "Element", "Option", "C", "M", "F", "Eq. 47 (ours)",
                              "α (ours)", "strict (ours)", "ANSYS " + cmf, "Eq. 47 (ANSYS)",
                              "α (ANSYS)", "strict (ANSYS)"})};
  std::map<const schema::RowVerdict*, DivergenceFacts> facts;
  for (const auto& d : divergence_facts(index))
    facts[d.row] = d;
  for (const Slot& s : slots_of(index)) {
    if (!index.singular(s.problem))
      continue;
    for (const auto& option : index.options_present(s.problem, s.quantity, s.element)) {
      const schema::RowVerdict* row = index.row(s.problem, s.quantity, s.element, option);
      const auto it = facts.find(row);
      const DivergenceFacts* f = it != facts.end() ? &it->second : nullptr;
      std::optional<schema::DivergenceVerdict> ours;
      if (f != nullptr) {
        ours = {f->eq47, row->divergence && row->divergence->monotone, f->exponent, f->strict};
        (f->eq47 ? out.eq47 : out.eq47_fails)++;
        (f->strict ? out.strict : out.strict_fails)++;
        out.eq47_only += f->eq47 && !f->strict;
        out.fine_not_converged += f->fine_converged ? 0 : 1;
        out.not_credible += f->credible ? 0 : 1;
        out.not_credible_eq47 += !f->credible && f->eq47 ? 1 : 0;
      } else {
        ++out.undecided;
      }
      Values theirs;
      for (const auto mesh : kMeshes) {
        const auto match = study.find_value(s.problem, s.quantity, s.element, option.algorithm,
                                            option.contact, mesh);
        if (match.value != nullptr)
          theirs[mesh_index(mesh)] = match.value->value;
      }
      std::optional<schema::DivergenceVerdict> study_verdict;
      if (theirs[0] && theirs[1] && theirs[2])
        study_verdict = grading::divergence_verdict(*theirs[0], *theirs[1], *theirs[2]);
      out.study_strict_fails += study_verdict && !study_verdict->diverges;
      auto a = sequence_cells(row->values, ours);
      const auto b = sequence_cells(theirs, study_verdict);
      if (f != nullptr && !f->credible) {
        a[1] += " ✗";  // an F case fails an interface check: the verdict is no evidence
        a[3] += " ✗";
      }
      const bool fine_ok = index.state(*row, kFinestMesh) != MeshState::not_converged;
      out.table.add_row({std::string(schema::label(s.problem)), name_of(s.element), option.label(),
                         format_value(row->values[0]), format_value(row->values[1]),
                         format_value(row->values[2]) + (fine_ok ? "" : "!"), a[1], a[2], a[3],
                         b[0], b[1], b[2], b[3]});
    }
  }
  return out;
}

std::string divergence_section(const ResultsIndex& index, const schema::StudyReference& study) {
  const DivergenceTableFacts t = build_divergence_table(index, study);
  if (t.table.n_rows() == 0)
    return {};
  TemplateData d("table", t.table.render());
  d.set("min", fmt::format("{}", grading::kDivergenceExponentMin));
  d.set("max", fmt::format("{}", grading::kDivergenceExponentMax));
  for (const auto& [key, n] : {std::pair{"eq47", t.eq47},
                               {"eq47_fails", t.eq47_fails},
                               {"undecided", t.undecided},
                               {"strict", t.strict},
                               {"strict_fails", t.strict_fails},
                               {"eq47_only", t.eq47_only},
                               {"study_strict_fails", t.study_strict_fails}})
    d.set(key, std::to_string(n));
  d.set("fine_not_converged", count_or_false(t.fine_not_converged));
  d.set("not_credible", count_or_false(t.not_credible));
  d.set("not_credible_eq47", std::to_string(t.not_credible_eq47));
  return tidy_markdown(render_template(templates::divergence_table, d));
}

}  // namespace cs::reports
