#pragma once
// Runs one contact analysis with CalculiX: writes the deck, runs ccx, reads the results back
// onto OUR node indices.
//
//   run_calculix(model, pair, options, work_dir)
//     1. checks that the executable is on PATH (require_ccx: CalculixError if not) and that
//        the deck can be written (ModelError, CalculixError, UnsupportedByCalculix);
//     2. writes <work_dir>/<job>.inp (work_dir is created; files of an earlier run of the same
//        job there are replaced);
//     3. runs "ccx -i <job>" in work_dir through platform::run_child, without a shell, with
//        OMP_NUM_THREADS=1 and CCX_NPROC_EQUATION_SOLVER=1 (one thread per job; parallelism
//        is the caller's --jobs), stdout and stderr in <job>.log, and the options' time limit;
//     4. classifies the run (run_status.hpp) and, when it converged, reads <job>.frd (and
//        <job>.12d to map expanded node-to-surface results back to the deck's nodes).
// A ccx failure is a status with a reason, never an exception, so a battery goes on: that
// includes results that cannot be parsed (status failed, "cannot read the results: ...").
//
// Results, on our node indices (CalculiX node id - 1):
//   nodal_stress: CalculiX's nodal stresses (integration-point values extrapolated to the
//     nodes and averaged over the elements of the node), as solver::Stress: sigma_x = SXX,
//     sigma_z = SYY (CalculiX's y is our z), tau_xz = SXY, sigma_out = SZZ (sigma_y in plane
//     strain, sigma_theta in axisymmetry). NaN for a node without a value.
//   displacement: U (x|r, z).
//   reaction: RF at prescribed DOFs, per unit thickness | PER RADIAN (CalculiX's full-circle
//     forces divided by 2 pi), like our solver's reactions.
//   contact: one entry per node of the contact (slave) surface, sorted along the surface:
//     CPRESS (pressure, > 0 in compression) and the penetration -COPEN (> 0 when penetrating),
//     averaged over the node's expanded copies; a node with no contact output (no contact
//     element was generated: far from the target) has pressure 0 and reported = false.
// Values come from the .frd's E12.5 fields: 6 significant digits.

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "adapters/calculix/calculix_options.hpp"
#include "adapters/calculix/run_status.hpp"
#include "solver/contact/contact_analysis.hpp"
#include "solver/model.hpp"
#include "solver/stress_recovery.hpp"

namespace cs::adapters::calculix {

/// CalculiX's contact output at one node of the contact surface.
struct CalculixContactNode {
  int node = -1;             ///< our node index
  Eigen::Vector2d position;  ///< reference position (x|r, z)
  double pressure = 0.0;     ///< CPRESS, > 0 in compression
  double penetration = 0.0;  ///< -COPEN, > 0 when the node penetrates the target
  bool reported = false;     ///< false: no contact output for the node (taken as open)
};

/// The result of one CalculiX run.
struct CalculixResult {
  CalculixStatus status = CalculixStatus::Failed;
  std::string reason;  ///< why it did not converge or failed (ccx's own message when it has one)
  std::vector<solver::Stress> nodal_stress;   ///< per node (empty unless converged)
  std::vector<Eigen::Vector2d> displacement;  ///< per node (empty unless converged)
  std::vector<Eigen::Vector2d> reaction;      ///< per node (empty unless converged)
  std::vector<CalculixContactNode> contact;   ///< per contact-surface node (idem)
  int increments = -1;                        ///< converged increments (.sta), -1 if unknown
  int iterations = -1;        ///< Newton iterations over all attempts (.sta), -1 if unknown
  double wall_seconds = 0.0;  ///< the ccx run
  double peak_rss_mb = 0.0;   ///< ccx's peak resident memory
  std::filesystem::path job_directory;

  bool converged() const { return status == CalculixStatus::Converged; }
};

/// Throws CalculixError "CalculiX: 'ccx' not found in PATH (install the Debian package
/// calculix-ccx)" unless `executable` is an executable file (a path with '/') or is found in a
/// directory of PATH.
void require_ccx(const std::string& executable = "ccx");

/// Runs the analysis (see the file comment).
CalculixResult run_calculix(const solver::Model& model, const solver::ContactPair& pair,
                            const CalculixOptions& options, const std::filesystem::path& work_dir);

}  // namespace cs::adapters::calculix
