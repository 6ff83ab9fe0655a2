#pragma once
// Points and stress states shared by every oracle.
//
// Coordinates: x (or r) along the undeformed surface z = 0, z pointing INTO the indented body,
// so the body is z >= 0. Stresses are signed, tension positive (compression negative), in the
// basis (e_x, e_z) or (e_r, e_z, e_theta). Contact pressures elsewhere are positive numbers.

namespace cs::oracles {

/// A point of a plane-strain body; z >= 0 points into the half-space.
struct PlanePoint {
  double x;
  double z;
};

/// In-plane stress components of a plane-strain state (the out-of-plane sigma_y follows from
/// plane strain as nu (sigma_x + sigma_z) and is not carried).
struct PlaneStress {
  double sigma_x;
  double sigma_z;
  double tau_xz;
};

/// A point of an axisymmetric body: radius r >= 0 from the axis, depth z >= 0.
struct AxiPoint {
  double r;
  double z;
};

/// Stress components of an axisymmetric state (tau_r_theta = tau_z_theta = 0).
struct AxiStress {
  double sigma_r;
  double sigma_z;
  double sigma_theta;
  double tau_rz;
};

}  // namespace cs::oracles
