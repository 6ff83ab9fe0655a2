#pragma once
// What one analysis produced: its status, the graded quantities, the surface profile and the
// cost. A case that fails is still a CaseResult (status + reason), never an exception escaping
// the runner. Whichever solver ran it, the record is the same.

#include <optional>
#include <string>
#include <vector>

#include "schema/case_spec.hpp"
#include "schema/grade.hpp"
#include "schema/interface_checks.hpp"
#include "schema/quantity.hpp"

namespace cs::schema {

/// One graded quantity, normalized by p and positive in compression (e.g. -sigma_z/p).
struct QuantityResult {
  Quantity quantity = Quantity::sigma_c;
  double value = 0.0;          ///< from the nodal stresses (NaN: not available)
  double exact = 0.0;          ///< the physically consistent exact value (inf: singular)
  double error_percent = 0.0;  ///< signed; NaN for singular quantities (no finite exact value)
  Grade grade = Grade::u;      ///< Eq. 46 on |error_percent|; u for singular quantities
  /// The same quantity from the contact solution's pressure (multipliers or penalty forces).
  std::optional<double> contact_pressure;
  /// The study's printed exact value where it differs from ours (Steuermann; see docs).
  std::optional<double> study_exact;

  bool singular() const;
};

/// The contact surface of the indented body, sorted by x: for the figures of the report.
struct SurfaceProfile {
  std::vector<double> x_over_a;         ///< position / contact half-width (b for S)
  std::vector<double> sigma_z_over_p;   ///< -sigma_z/p, nodal (the case's recovery)
  std::vector<double> pressure_over_p;  ///< contact pressure / p from the contact solution
  bool empty() const { return x_over_a.empty(); }
};

/// The exact -sigma_z/p on z = 0 on a fine grid of x / a (infinite values left out).
struct ExactProfile {
  std::vector<double> x_over_a;
  std::vector<double> sigma_z_over_p;
  bool empty() const { return x_over_a.empty(); }
};

/// One node of the sampled surface as the solver reported it, unnormalized: what the import
/// layout holds (docs/import-export.md; `run --surface-csv`). In memory only: results.json
/// keeps the normalized profile.
struct SurfaceNodeValues {
  double x = 0.0;                          ///< reference coordinate x (r)
  double sigma_z = 0.0;                    ///< nodal sigma_z, tension positive
  double sigma_x = 0.0;                    ///< nodal sigma_x (sigma_r), tension positive
  std::optional<double> contact_pressure;  ///< > 0 in compression; none: not reported there
};

/// Everything recorded about one analysis.
struct CaseResult {
  CaseSpec spec;
  CaseStatus status = CaseStatus::failed;
  std::string reason;  ///< why a case did not converge or failed; empty when converged
  /// Where another code's run that did not converge or failed left its files for inspection
  /// (results.json only, not the reason: the directory differs between runs); empty if none.
  std::string kept_files;
  int iterations = 0;  ///< active-set (+ augmentation) iterations
  double wall_seconds = 0.0;
  double peak_rss_mb = 0.0;     ///< process peak resident memory when the case finished
  int n_elements = 0;           ///< elements of the indented body
  int n_equations = 0;          ///< free degrees of freedom of the whole model
  double element_size_h = 0.0;  ///< characteristic element size at the contact, over a (or b)
  std::vector<QuantityResult> quantities;
  SurfaceProfile profile;
  ExactProfile exact_profile;
  /// The interface checks (none: the case has no values or the solver gave no contact forces).
  std::optional<InterfaceChecks> interface;
  /// The sampled surface's nodal values, in surface order (nodal recoveries only; not written
  /// to results.json).
  std::vector<SurfaceNodeValues> surface_nodes;

  /// The record of `q`, or nullptr.
  const QuantityResult* quantity(Quantity q) const;
  /// True for the study's option sets: our solver, a discretized target, patch-recovered
  /// nodal stresses and no parameter overrides.
  bool is_baseline() const;
};

}  // namespace cs::schema
