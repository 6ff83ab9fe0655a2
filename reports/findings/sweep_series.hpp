#pragma once
// The swept cases of a results document (`run --sweep KEY=...`), as series: the cases that
// differ only in the value of one swept parameter, ordered by that value. A parameter is swept
// when the run says so (run.sweep) or when its cases carry it as an override with two or more
// values. Used by the report's sweep section and its figures.

#include <optional>
#include <string>
#include <vector>

#include "schema/results_file.hpp"

namespace cs::reports {

/// One swept case: the swept value and the case.
struct SweepPoint {
  double value = 0.0;
  const schema::CaseResult* result = nullptr;
};

/// The cases of one option set that differ only in the swept key, by ascending value.
struct SweepSeries {
  std::string key;
  schema::CaseSpec base;  ///< the common spec, the swept key removed from its overrides
  std::vector<SweepPoint> points;

  /// "AL ss" plus any other variant ("AL ss, rigid, E_ratio=1e+09"), for legends and tables.
  std::string option_label() const;
  /// The error (%) of a quantity at a point, if finite.
  static std::optional<double> error(const SweepPoint& point, schema::Quantity quantity);
  /// True when the point's case converged.
  static bool converged(const SweepPoint& point);
};

/// The swept keys: those of run.sweep in their order, then any other key with two or more
/// override values among the cases, alphabetically.
std::vector<std::string> swept_keys(const schema::ResultsDocument& doc);

/// The series of one key, in document order of their first case; cases without the key are
/// left out, and a series of a single point is kept (it is still a swept case).
std::vector<SweepSeries> sweep_series(const schema::ResultsDocument& doc, const std::string& key);

/// True when no series of the same problem and element has a finer mesh: the mesh the study
/// grades, and the one the section's tables, figures and windows show.
bool on_finest_mesh(const SweepSeries& series, const std::vector<SweepSeries>& all);

/// The values of a key over its series, ascending and distinct.
std::vector<double> swept_values(const std::vector<SweepSeries>& series);

/// A swept value as the report prints it: "0.001", "1e+04" -> "1e4" style via {:g}.
std::string format_swept_value(double value);

/// One panel of a sweep figure: the series of one problem, quantity, mesh and element.
struct SweepPanel {
  schema::ProblemId problem = schema::ProblemId::P_p;
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::MeshLevel mesh = schema::MeshLevel::F;
  schema::Element element = schema::Element::Q4;
  std::vector<const SweepSeries*> series;
};

/// The panels of a key's series, in document order: the finest mesh swept of each problem and
/// element, every stress quantity (not the contact half-width, graded apart).
std::vector<SweepPanel> sweep_panels(const std::vector<SweepSeries>& series);

}  // namespace cs::reports
