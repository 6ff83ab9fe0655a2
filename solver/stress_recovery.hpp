#pragma once
// Stresses from a displacement solution: at Gauss points, at nodes (extrapolated from the Gauss
// points of each element and averaged over the elements of the same body sharing the node, the
// nodal stresses commercial codes print; or by superconvergent patch recovery, see
// solver/patch_recovery.hpp), and along a named surface.
//
// Extrapolation: the stresses at the element's sampling points are fitted exactly by a
// polynomial in (xi, eta) which is evaluated at the element's nodes:
//   Q4: 2x2 Gauss points, bilinear fit {1, xi, eta, xi eta};
//   Q8 (Reduced2x2, the default): 2x2 Gauss points (the Barlow points of Q8, where its
//     stresses are most accurate; ANSYS PLANE82, the study's element, integrates and
//     extrapolates from 2x2), bilinear fit, mid-side nodes the mean of their corners;
//   Q8 (Full3x3): 3x3 Gauss points, biquadratic fit (9 terms).
// Both Q8 choices converge at O(h^2) at a loaded surface; on Lame's cylinder (tests/solver/
// test_fe_lame.cpp) the 2x2 values are 30-40% more accurate, hence the default.
// Averaging never crosses bodies: a node shared by an indenter and a block has one value per
// body. Stress components as in solver/material.hpp: sigma_out is sigma_theta (axisymmetric)
// or sigma_y = nu (sigma_x + sigma_z) (plane strain).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "solver/model.hpp"
#include "solver/patch_recovery.hpp"

namespace cs::solver {

/// How stresses are reported.
enum class StressRecoveryMethod {
  GaussPoint,            ///< at the Gauss points of every element, unsmoothed
  ExtrapolatedAveraged,  ///< extrapolated to nodes, averaged per body over sharing elements
  PatchRecovered,        ///< superconvergent patch recovery per body (patch_recovery.hpp);
                         ///< nodes no patch reaches keep the extrapolated, averaged value
};

/// True for the methods with one value per node and body (all but GaussPoint).
constexpr bool is_nodal(StressRecoveryMethod method) {
  return method != StressRecoveryMethod::GaussPoint;
}

/// Which sampling points Q8 elements extrapolate from (Q4 always uses 2x2).
enum class Q8Extrapolation {
  Reduced2x2,  ///< 2x2 Gauss (Barlow) points, bilinear fit (the default)
  Full3x3,     ///< 3x3 Gauss points, biquadratic fit
};

const char* to_string(StressRecoveryMethod method);
const char* to_string(Q8Extrapolation rule);

/// A stress state: (sigma_x|r, sigma_z, tau_xz|rz, sigma_y|theta).
struct Stress {
  double sigma_x = 0.0;    ///< sigma_x (plane strain) | sigma_r (axisymmetric)
  double sigma_z = 0.0;    ///< sigma_z
  double tau_xz = 0.0;     ///< tau_xz | tau_rz
  double sigma_out = 0.0;  ///< sigma_y = nu (sigma_x + sigma_z) | sigma_theta

  static Stress from(const Eigen::Vector4d& v) { return {v[0], v[1], v[2], v[3]}; }
  Eigen::Vector4d vector() const { return {sigma_x, sigma_z, tau_xz, sigma_out}; }
};

struct StressRecoveryOptions {
  StressRecoveryMethod method = StressRecoveryMethod::ExtrapolatedAveraged;
  Q8Extrapolation q8_extrapolation = Q8Extrapolation::Reduced2x2;
};

/// The stress at one Gauss point.
struct GaussPointStress {
  int element = -1;
  int body = -1;
  Eigen::Vector2d natural;   ///< (xi, eta)
  Eigen::Vector2d position;  ///< (x|r, z)
  Stress stress;
};

/// Recovered stresses, with the method that produced them.
struct StressField {
  StressRecoveryMethod method = StressRecoveryMethod::ExtrapolatedAveraged;
  Q8Extrapolation q8_extrapolation = Q8Extrapolation::Reduced2x2;
  /// GaussPoint: every sampling point of every element, element by element (empty otherwise).
  /// Q4 and Q8 use their stiffness rule (2x2, 3x3).
  std::vector<GaussPointStress> gauss_points;
  /// Nodal methods: nodal[body][node] (zero where the node is not in the body).
  std::vector<std::vector<Stress>> nodal;
  /// Nodal methods: elements (or patches) averaged into nodal[body][node] (0: node not in body).
  std::vector<std::vector<int>> nodal_count;

  /// Whether the field has a nodal value of `node` in `body`.
  bool has_node(int node, int body) const;
  /// The nodal stress of `node` in `body`; throws std::out_of_range if there is none.
  const Stress& at_node(int node, int body) const;
  /// The nodal stress of a node that belongs to exactly one body; throws std::out_of_range
  /// otherwise (use the overload with a body for nodes shared by bodies).
  const Stress& at_node(int node) const;
};

/// Recovers the stresses of the global displacement `u` (size 2 n_nodes) of a validated model.
StressField recover_stresses(const Model& model, const Eigen::VectorXd& u,
                             const StressRecoveryOptions& options = {});

/// A stress sample along a surface.
struct SurfaceStressSample {
  int node = -1;     ///< node (nodal methods) or -1 (GaussPoint)
  int element = -1;  ///< element of the Gauss point (GaussPoint) or of the side (nodal)
  int body = -1;     ///< body whose value is reported
  Eigen::Vector2d position;
  double arc_length = 0.0;  ///< along the surface path (see surface_path.hpp)
  Stress stress;
};

/// The stresses along edge set `edge_set`, ordered along its surface path:
///   nodal methods: the nodal values of the set's nodes (in the body of the sides);
///   GaussPoint: the row of Gauss points of each side's element nearest that side.
/// Throws ModelError if the set is unknown or empty.
std::vector<SurfaceStressSample> surface_stresses(const Model& model, const StressField& field,
                                                  const std::string& edge_set);

/// The stresses along one edge set of a model, recovered for any displacement at the cost of the
/// elements (and, for patch recovery, the patches) that reach the set's nodes instead of the
/// whole mesh: what a case that samples one surface needs. Which elements and patches those are
/// is found once, when this is made. The model must outlive it.
class SurfaceStressRecovery {
 public:
  /// Throws ModelError if the set is unknown or empty.
  SurfaceStressRecovery(const Model& model, std::string edge_set);
  /// surface_stresses(model, recover_stresses(model, u, options), edge_set), bit for bit.
  std::vector<SurfaceStressSample> recover(const Eigen::VectorXd& u,
                                           const StressRecoveryOptions& options) const;
  /// The nodes whose displacement recover() reads (those of every element it samples),
  /// increasing: u may be anything elsewhere.
  std::vector<int> nodes_read() const;

 private:
  const Model* model_;
  std::string edge_set_;
  PatchScope patches_;         ///< the set's nodes and the patches that reach them
  std::vector<int> elements_;  ///< the elements holding a node of the set, increasing
  std::vector<int> nodes_;     ///< the set's nodes, increasing
};

/// SurfaceStressRecovery(model, edge_set).recover(u, options): for one displacement.
std::vector<SurfaceStressSample> recover_surface_stresses(const Model& model,
                                                          const Eigen::VectorXd& u,
                                                          const StressRecoveryOptions& options,
                                                          const std::string& edge_set);

}  // namespace cs::solver
