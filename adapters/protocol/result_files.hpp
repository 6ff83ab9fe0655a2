#pragma once
// What an external code writes back into its case directory (docs/solver-protocol.md):
//   displacements.csv     node_id,ux,uz          required: every node of every deformable body
//   stresses.csv          node_id,sigma_x,sigma_z,tau_xz,sigma_out_of_plane
//                                                optional: the code's own nodal stresses (the
//                                                `own` basis), at least on the sampled surface
//   contact_pressure.csv  node_id,pressure       optional: > 0 in compression, contact nodes
//   status.json           {"converged": bool, "iterations": int, "n_equations": int,
//                          "reason": str, "solver_version": str}   optional, every key optional
// Node ids are case.json's (our node index + 1). Values are finite decimal numbers.
//
// Reading never throws for what the code wrote: a missing file, a missing node, an unparsable
// or non-finite value becomes ResultFiles::error (one line naming the file, line and cause).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cs::adapters::protocol {

/// One nodal contact pressure.
struct NodalPressure {
  int node = 0;  ///< node index (id - 1)
  double pressure = 0.0;
};

struct ResultFiles {
  std::string error;  ///< empty: read; else why the results cannot be used
  /// 2 values per node (ux, uz), indexed like the mesh's DOFs; nodes the code did not write
  /// (those of bodies that take no part) are 0.
  Eigen::VectorXd displacement;
  /// The code's own nodal stresses (sigma_x, sigma_z, tau_xz, out of plane) of the nodes it
  /// wrote; `has_stress[n]` says which.
  std::vector<Eigen::Vector4d> stress;
  std::vector<bool> has_stress;
  bool stresses_given = false;
  std::vector<NodalPressure> contact_pressure;
  bool contact_pressure_given = false;
  // status.json
  std::optional<bool> converged;
  int iterations = 0;
  long long n_equations = 0;
  std::string reason;  ///< one line: control characters read as spaces
  std::string solver_version;
};

/// Reads the results in `case_dir` of a mesh of `n_nodes` nodes; `required_nodes` (indices)
/// must all have a displacement.
ResultFiles read_result_files(const std::filesystem::path& case_dir, int n_nodes,
                              const std::vector<int>& required_nodes);

}  // namespace cs::adapters::protocol
