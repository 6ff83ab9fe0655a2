#pragma once
// Superconvergent patch recovery (Zienkiewicz & Zhu, "The superconvergent patch recovery and
// a posteriori error estimates", IJNME 33, 1992) of nodal stresses from the stresses at an
// element's superconvergent sampling points.
//
// A patch is the set of elements of one body around an interior vertex node. Each stress
// component is fitted, in the least-squares sense, by a complete polynomial of the element's
// degree over the patch's sampling points:
//   Q4: the element centres (where bilinear stresses are superconvergent), linear {1, x, z};
//   Q8: the 2x2 Gauss (Barlow) points, quadratic {1, x, z, x^2, x z, z^2}.
// The interior vertex takes its own patch's value. Nodes on the body's boundary and Q8 mid-side
// nodes take the mean of the polynomials of every patch that contains them (evaluated there).
// A node no patch reaches (a body one element thick, a rank-deficient patch) keeps the value it
// had on entry (the caller passes the extrapolated, averaged field).
//
// Why: a bilinear element's strain e_z cannot vary in z, so near a loaded surface the
// extrapolated nodal sigma_z inherits nu/(1-nu) of the slope of sigma_x across the first row
// of elements, an O(h) bias; the centre values carry no such bias and the fitted polynomial is
// accurate to O(h^2) at the surface.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "solver/mesh/mesh.hpp"

namespace cs::solver {

/// A stress sample at a point of an element.
struct StressSample {
  Eigen::Vector2d position;  ///< (x|r, z)
  Eigen::Vector4d stress;    ///< as in solver/material.hpp
};

/// The sampling points of each element (samples[e]), in any order.
using ElementSamples = std::vector<std::vector<StressSample>>;

/// The degree of the patch polynomial of an element type: 1 (Q4) or 2 (Q8).
int patch_polynomial_degree(ElementType type);

/// The natural coordinates of the patch sampling points of an element type: the centre (Q4) or
/// the 2x2 Gauss points (Q8).
const std::vector<Eigen::Vector2d>& patch_sampling_points(ElementType type);

/// Overwrites nodal[body][node] (and sets count[body][node] to the number of patches averaged)
/// for every node a patch of its body reaches; leaves the other entries unchanged.
void recover_by_patches(const Mesh& mesh, const ElementSamples& samples,
                        std::vector<std::vector<Eigen::Vector4d>>& nodal,
                        std::vector<std::vector<int>>& count);

/// The patches that reach the nodes marked in `nodes` (size n_nodes; e.g. a sampled surface), per
/// body 0 .. n_bodies - 1, found once per mesh and node set: the recovery at those nodes alone
/// then costs the patches, not the mesh.
class PatchScope {
 public:
  PatchScope(const Mesh& mesh, int n_bodies, std::vector<char> nodes);
  /// The nodes marked.
  const std::vector<char>& nodes() const;
  /// The elements (a mask of size n_elements) whose samples the patches read.
  const std::vector<char>& elements() const;

 private:
  friend void recover_by_patches(const Mesh&, const ElementSamples&, const PatchScope&,
                                 std::vector<std::vector<Eigen::Vector4d>>&,
                                 std::vector<std::vector<int>>&);
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

/// The same recovery at the nodes of `scope` only: their entries get the values, bit for bit,
/// that the whole-mesh recovery gives them (the same patches fitted and summed in the same
/// order); the other entries are left unchanged. `samples` need only hold scope.elements().
void recover_by_patches(const Mesh& mesh, const ElementSamples& samples, const PatchScope& scope,
                        std::vector<std::vector<Eigen::Vector4d>>& nodal,
                        std::vector<std::vector<int>>& count);

}  // namespace cs::solver
