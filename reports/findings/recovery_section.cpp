#include "reports/findings/recovery_section.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <gsl/gsl_statistics_double.h>

#include "grading/accuracy.hpp"
#include "grading/convergence.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::RowVerdict;
using Fields = kainjow::mustache::object;

/// A baseline row and its extrapolated twin, graded on the same mesh.
struct RecoveryPair {
  const RowVerdict* spr = nullptr;
  const RowVerdict* extrapolated = nullptr;
  schema::MeshLevel mesh = kFinestMesh;  ///< the mesh both are graded on
  std::optional<double> pressure_error;  ///< % error of the contact pressure there (shown)
};

std::optional<double> pressure_error(const ResultsIndex& index, const RowVerdict& row,
                                     schema::MeshLevel mesh) {
  const schema::QuantityResult* q = index.quantity_of(row, mesh);
  if (q == nullptr || !q->contact_pressure || !std::isfinite(q->exact) || q->exact == 0.0)
    return std::nullopt;
  return grading::error_percent(*q->contact_pressure, q->exact);
}

std::vector<RecoveryPair> graded_pairs(const ResultsIndex& index) {
  std::vector<RecoveryPair> out;
  for (const RowVerdict* row : index.baseline_rows()) {
    const RowVerdict* twin = index.extrapolated_twin(*row);
    if (twin == nullptr || !row->grade || !twin->grade || !row->graded_mesh ||
        row->graded_mesh != twin->graded_mesh) {
      continue;
    }
    const schema::MeshLevel mesh = *row->graded_mesh;
    if (!row->errors[mesh_index(mesh)] || !twin->errors[mesh_index(mesh)])
      continue;
    out.push_back({row, twin, mesh, pressure_error(index, *row, mesh)});
  }
  return out;
}

/// "+0.45 % (e)" on the fine mesh; "+0.45 % (e, on M)" where the row is graded on another.
std::string error_cell(const RowVerdict& row, schema::MeshLevel mesh) {
  const std::string where =
      mesh == kFinestMesh ? std::string() : fmt::format(", on {}", schema::to_string(mesh));
  return fmt::format("{} ({}{})", format_error_resolved(*row.errors[mesh_index(mesh)]),
                     schema::to_string(*row.grade), where);
}

std::string converging_text(const std::optional<bool>& c) {
  return c ? (*c ? "c" : "—") : kMissing;
}

TemplateData comparison_data(const RecoveryComparison& c) {
  const auto n = [](int v) { return std::to_string(v); };
  return Fields{{"element", name_of(c.element)},
                {"compared", n(c.compared)},
                {"unaffected", n(c.unaffected)},
                {"not_evidence", n(c.not_evidence)},
                {"any", c.compared > 0},
                {"median_spr", fmt::format("{:.2f}", c.median_spr)},
                {"median_extrapolated", fmt::format("{:.2f}", c.median_extrapolated)},
                {"closer", n(c.closer)},
                {"farther", n(c.farther)},
                {"ties", n(c.compared - c.closer - c.farther)},
                {"better", n(c.better)},
                {"worse", n(c.worse)},
                {"same", n(c.compared - c.better - c.worse)}};
}

std::string pairs_table(const ResultsIndex& index, const std::vector<RecoveryPair>& pairs) {
  const auto cells = [&](const RecoveryPair& p) -> std::vector<std::string> {
    const schema::ProblemRecord* info = index.problem(p.spr->spec.problem);
    std::string name(schema::label(p.spr->spec.problem));
    if (info != nullptr && info->quantities.size() > 1)
      name += fmt::format(" {}", schema::label(p.spr->quantity));
    return {
        name,
        name_of(p.spr->spec.element),
        Option{p.spr->spec.algorithm, p.spr->spec.contact}.label(),
        error_cell(*p.spr, p.mesh) + evidence_marks(facts_of_row(index, *p.spr)),
        error_cell(*p.extrapolated, p.mesh) + evidence_marks(facts_of_row(index, *p.extrapolated)),
        format_error_resolved(p.pressure_error),
        converging_text(p.spr->converging) + " / " + converging_text(p.extrapolated->converging)};
  };
  constexpr Align l = Align::left, c = Align::center, r = Align::right;
  return table_of({"Problem", "Element", "Option", "Patch recovery", "Extrapolated",
                   "Contact pressure", "Converging (patch / extrapolated)"},
                  pairs, cells, {l, c, l, r, r, r, c})
      .render();
}

}  // namespace

std::vector<RecoveryComparison> compare_recoveries(const ResultsIndex& index) {
  const auto pairs = graded_pairs(index);
  std::vector<RecoveryComparison> out;
  for (const auto element : schema::values<schema::Element>()) {
    RecoveryComparison c;
    c.element = element;
    std::vector<double> spr, ext;
    for (const auto& p : pairs) {
      if (p.spr->spec.element != element)
        continue;
      const std::size_t m = mesh_index(p.mesh);
      const double e_spr = *p.spr->errors[m], e_ext = *p.extrapolated->errors[m];
      if (std::abs(e_spr - e_ext) <= schema::kErrorNoiseFloorPercent) {  // round-off apart
        ++c.unaffected;
        continue;
      }
      if (!facts_of_row(index, *p.spr).evidence()) {
        ++c.not_evidence;
        continue;
      }
      spr.push_back(std::abs(e_spr));
      ext.push_back(std::abs(e_ext));
      const schema::Grade g_spr = *p.spr->grade, g_ext = *p.extrapolated->grade;
      c.better += g_spr < g_ext ? 1 : 0;  // schema::Grade is ordered best first
      c.worse += g_spr > g_ext ? 1 : 0;
      const double gain = std::abs(e_ext) - std::abs(e_spr);
      c.closer += gain > grading::kErrorResolutionPercent ? 1 : 0;
      c.farther += gain < -grading::kErrorResolutionPercent ? 1 : 0;
    }
    c.compared = static_cast<int>(spr.size());
    if (c.compared + c.unaffected + c.not_evidence == 0)
      continue;
    if (c.compared > 0) {
      c.median_spr = gsl_stats_median(spr.data(), 1, spr.size());
      c.median_extrapolated = gsl_stats_median(ext.data(), 1, ext.size());
    }
    out.push_back(c);
  }
  return out;
}

std::string recovery_section(const ResultsIndex& index) {
  TemplateData d;
  d.set("has_twins", index.has_extrapolated_twins());
  d.set("elements", template_list(compare_recoveries(index), comparison_data));
  // The flat punch: Eq. 47 both ways, on rows that are evidence (a row whose F case fails an
  // interface check or did not converge has no verdict to compare; the twins share its solve).
  int both = 0, same = 0, left_out = 0;
  for (const RowVerdict* row : index.baseline_rows()) {
    const RowVerdict* twin = index.extrapolated_twin(*row);
    if (twin == nullptr || !row->diverging || !twin->diverging)
      continue;
    const RowFacts f = facts_of_row(index, *row);
    if (!f.credible || !f.fine_converged) {
      ++left_out;
      continue;
    }
    ++both;
    same += *row->diverging == *twin->diverging ? 1 : 0;
  }
  d.set("has_divergence", both + left_out > 0);
  d.set("divergence_same", fmt::format("{} of {}", same, both));
  d.set("divergence_left_out", count_or_false(left_out));
  std::vector<RecoveryPair> differing = graded_pairs(index);
  std::erase_if(differing,
                [](const RecoveryPair& p) { return *p.spr->grade == *p.extrapolated->grade; });
  d.set("n_differing", count_or_false(differing.size()));
  d.set("marks_legend", evidence_marks_legend());
  d.set("differing", pairs_table(index, differing));
  return render_template(templates::recovery_section, d);
}

}  // namespace cs::reports
