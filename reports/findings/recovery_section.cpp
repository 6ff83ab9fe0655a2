#include "reports/findings/recovery_section.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/tables/grade_tables.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// A baseline row and its extrapolated twin, graded on the same mesh.
using schema::RowVerdict;

struct RecoveryPair {
  const RowVerdict* spr = nullptr;
  const RowVerdict* extrapolated = nullptr;
  schema::MeshLevel mesh = kFinestMesh;  ///< the mesh both are graded on
  std::optional<double> pressure_error;  ///< % error of the contact pressure there
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

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// An unsigned percentage: "0.40 %".
std::string magnitude(double percent) {
  return fmt::format("{:.2f} %", percent);
}

std::string converging_text(const std::optional<bool>& c) {
  if (!c)
    return kMissing;
  return *c ? "c" : "—";
}

/// "+0.45 % (e)" on the fine mesh; "+0.45 % (e, on M)" where the row is graded on another.
std::string error_cell(const RowVerdict& row, schema::MeshLevel mesh) {
  const std::string where =
      mesh == kFinestMesh ? std::string() : fmt::format(", on {}", schema::to_string(mesh));
  return fmt::format("{} ({}{})", format_percent(*row.errors[mesh_index(mesh)]),
                     schema::to_string(*row.grade), where);
}

/// One line per element: how many rows, the median |error| both ways, grades better/worse.
std::string summary_lines(const std::vector<RecoveryComparison>& comparisons) {
  std::string out;
  for (const auto& c : comparisons) {
    out += fmt::format(
        "- {}: {} option set(s) graded both ways; median |error| {} with patch recovery, {} "
        "extrapolated; the grade is better with patch recovery in {}, worse in {}, the same in "
        "{}.",
        schema::to_string(c.element), c.compared, magnitude(c.median_spr),
        magnitude(c.median_extrapolated), c.better, c.worse, c.compared - c.better - c.worse);
    if (c.differing_with_pressure > 0) {
      out += fmt::format(
          " Where the grades differ, the patch-recovered value is the closer to the contact "
          "pressure in {} of {}.",
          c.spr_closer_to_pressure, c.differing_with_pressure);
    }
    out += "\n";
  }
  return out;
}

/// The singular rows: Eq. 47 verdicts both ways.
std::string divergence_line(const ResultsIndex& index) {
  int both = 0, same = 0;
  for (const RowVerdict* row : index.baseline_rows()) {
    const RowVerdict* twin = index.extrapolated_twin(*row);
    if (twin == nullptr || !row->diverging || !twin->diverging)
      continue;
    ++both;
    same += *row->diverging == *twin->diverging ? 1 : 0;
  }
  if (both == 0)
    return {};
  return fmt::format(
      "- Flat punch (Eq. 47): the divergence verdict is the same both ways in {} of {} option "
      "set(s).\n",
      same, both);
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
      spr.push_back(std::abs(e_spr));
      ext.push_back(std::abs(e_ext));
      const int d = grade_rank(*p.spr->grade) - grade_rank(*p.extrapolated->grade);
      c.better += d < 0 ? 1 : 0;
      c.worse += d > 0 ? 1 : 0;
      if (d != 0 && p.pressure_error) {
        ++c.differing_with_pressure;
        const bool closer =
            std::abs(e_spr - *p.pressure_error) < std::abs(e_ext - *p.pressure_error);
        c.spr_closer_to_pressure += closer ? 1 : 0;
      }
    }
    if (spr.empty())
      continue;
    c.compared = static_cast<int>(spr.size());
    c.median_spr = median(spr);
    c.median_extrapolated = median(ext);
    out.push_back(c);
  }
  return out;
}

std::string recovery_section(const ResultsIndex& index) {
  if (!index.has_extrapolated_twins())
    return {};
  const auto pairs = graded_pairs(index);
  std::string out =
      "## Nodal stress recovery: patch recovery beside extrapolation\n\n"
      "Every graded value above is a nodal stress recovered by superconvergent patch recovery "
      "(our default). This run also recovered each analysis's stresses the way commercial codes "
      "print them, and the study graded them: extrapolated from the Gauss points and averaged. "
      "Both come from the same displacement solution; the contact pressure of that solution, "
      "shown beside, tells which recovery is right where they disagree.\n\n";
  out += summary_lines(compare_recoveries(index)) + divergence_line(index) + "\n";

  MarkdownTable table({"Problem", "Element", "Option", "Patch recovery", "Extrapolated",
                       "Contact pressure", "Converging (patch / extrapolated)"});
  int differing = 0;
  for (const auto& p : pairs) {
    if (*p.spr->grade == *p.extrapolated->grade)
      continue;
    ++differing;
    const schema::ProblemRecord* info = index.problem(p.spr->spec.problem);
    std::string name(schema::label(p.spr->spec.problem));
    if (info != nullptr && info->quantities.size() > 1)
      name += fmt::format(" {}", schema::label(p.spr->quantity));
    const Option option{p.spr->spec.algorithm, p.spr->spec.contact};
    table.add_row(
        {name, std::string(schema::to_string(p.spr->spec.element)), option.label(),
         error_cell(*p.spr, p.mesh), error_cell(*p.extrapolated, p.mesh),
         p.pressure_error ? format_percent(*p.pressure_error) : std::string(kMissing),
         converging_text(p.spr->converging) + " / " + converging_text(p.extrapolated->converging)});
  }
  if (differing == 0)
    return out + "The two recoveries give the same grade for every option set.\n\n";
  out += fmt::format(
      "The {} option set(s) whose grade differs, with the error on the graded mesh (F unless "
      "the cell names another) and that mesh's contact-pressure error:\n\n",
      differing);
  return out + table.render() + "\n";
}

}  // namespace cs::reports
