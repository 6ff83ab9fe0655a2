#pragma once
// The cases as documented CSV for any other code (`contact-suite export`; the layout, column by
// column, is docs/import-export.md). A model — the mesh, sets, materials, boundary conditions,
// loads and contact pair that the cases of one group share (runner.hpp's model_key) — is
// written once into its own directory; cases.csv lists every case with its options and the
// quantities to sample. Everything comes from the same ProblemSetup the built-in solver and the
// CalculiX adapter run on: the loads are the solver's own consistent nodal forces
// (solver/load_vector.hpp) at free DOFs, the boundary conditions its prescribed DOFs.
//
// Numbering: node id = our node index + 1, element id = our element index + 1 (as in the
// CalculiX deck); y is our z (pointing into the indented body).

#include <string>
#include <string_view>
#include <vector>

#include "suites/case_spec.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// Throws SuiteInputError unless the import layout (suites/import_csv.hpp) can grade `spec`'s
/// case from surface stresses: a frictionless problem (the layout has no load path, no shear
/// stress and no stick/slip states) graded on its surface, not on the contact's nodal forces
/// (IF_p, IF_a). A rigid target is allowed: the case is rebuilt with its profile.
void require_importable(const CaseSpec& spec);

/// Throws SuiteInputError unless the export layout can describe `spec`'s case: what
/// require_importable() asks, and a discretized target (the layout has no rigid profile; the
/// solver protocol's case directory has one, docs/solver-protocol.md).
void require_exchangeable(const CaseSpec& spec);

/// The directory of the model `spec` runs on: "H_p_C_Q4", then "_name=value" for each
/// parameter override that changes the model (not the contact-only fkn, ftoln, pinball), as a
/// plain_file_name.
std::string model_directory_name(const CaseSpec& spec);

/// One file of an export: its name within the model's directory and its whole content.
struct ExportFile {
  std::string name;
  std::string text;
};

/// The files of one model: model.csv, nodes.csv, elements.csv, node_sets.csv, surfaces.csv,
/// boundary.csv, loads.csv, materials.csv, contact_pair.csv and mesh.vtu (no I/O here: the
/// command writes them into its output transaction).
std::vector<ExportFile> model_files(const ProblemSetup& setup);

/// The name of a sampling rule in the exchange formats: "max_on_surface", "at_axis", ...
std::string_view sample_rule_name(SamplePoint where);

/// A number as text that reads back to the same double ("{:.17g}"), for the exported files.
std::string round_trip_text(double v);

/// The name of a stress component in the exchange formats: "sigma_z", "sigma_x", "tau_xz".
std::string_view stress_component_name(StressComponent c);

/// The header of cases.csv.
std::string cases_csv_header();

/// The rows of cases.csv for one case (one per graded quantity), on the model written to
/// directory `model_dir`.
std::string cases_csv_rows(const CaseSpec& spec, const ProblemSetup& setup,
                           const std::string& model_dir);

}  // namespace cs::suites
