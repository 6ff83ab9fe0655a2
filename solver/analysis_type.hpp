#pragma once
// The analysis type of a 2D model: plane strain or axisymmetric, and the load convention.
//
// Coordinates are (x, z) in plane strain and (r, z) in axisymmetry, r >= 0, axis at r = 0.
//
// Plane strain: every integral is per unit thickness in y; forces are per unit thickness
// (N/m), tractions and pressures are per unit area (N/m^2), body forces per unit volume.
//
// Axisymmetric: THE LOAD CONVENTION IS PER RADIAN, everywhere in solver/. Volume integrals are
// int(... r dr dz) and surface integrals int(... r ds), without the factor 2 pi. Consequently
//   - the stiffness matrix is K = int B^T D B r dr dz (per radian);
//   - a traction t (force per unit area of the revolved surface) on an edge gives the nodal
//     forces int N t r ds (per radian);
//   - a point force given on a node is a force per radian: a total axial force P acting on
//     the full ring (or on an axis node) is entered as P / (2 pi);
//   - reaction forces are reported per radian: multiply by 2 pi for the full-circle resultant.
// Hoop strain u_r / r is evaluated at Gauss points only (never at r = 0), so nodes on the axis
// are allowed; their radial displacement must be constrained to 0 by the problem (the solver
// does not do it implicitly).

namespace cs::solver {

/// The kinematic assumption of a 2D model.
enum class AnalysisType {
  PlaneStrain,   ///< eps_y = 0; sigma_y = nu (sigma_x + sigma_z); integrals per unit thickness
  Axisymmetric,  ///< (r, z) section of a body of revolution; integrals per radian (see above)
};

/// "plane strain" or "axisymmetric".
constexpr const char* to_string(AnalysisType type) {
  return type == AnalysisType::PlaneStrain ? "plane strain" : "axisymmetric";
}

/// The displacement component of a degree of freedom: global DOF of node n is 2 n + component.
enum class Component : int {
  X = 0,  ///< x in plane strain
  R = 0,  ///< r in axisymmetry (same DOF as X)
  Z = 1,  ///< z
};

/// The global degree of freedom of component `c` of node `node`: 2 node + c.
constexpr int global_dof(int node, Component c) {
  return 2 * node + static_cast<int>(c);
}

}  // namespace cs::solver
