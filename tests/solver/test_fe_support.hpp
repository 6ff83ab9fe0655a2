#pragma once
// Helpers shared by the FE core tests (tests/solver/test_fe_*.cpp): meshes built with the
// structured block generator, interior distortion, and fitting observed convergence orders.

#include <cmath>
#include <random>
#include <set>
#include <vector>

#include <Eigen/Core>

#include "solver/mesh/structured_block.hpp"
#include "solver/model.hpp"

namespace cs::solver::test {

/// A block [x0, x0 + lx] x [z0, z0 + lz] of nx x nz elements of `type`.
inline Mesh block(ElementType type, Eigen::Vector2d origin, Eigen::Vector2d size, int nx, int nz,
                  const std::string& body = "block") {
  BlockSpec spec;
  spec.type = type;
  spec.origin = origin;
  spec.size = size;
  spec.nx = nx;
  spec.nz = nz;
  spec.body_name = body;
  return make_block(spec);
}

/// Moves every corner node that is on none of the block's four edges by a random offset of
/// up to `fraction` of the smallest element size in each direction (fixed seed), then puts
/// every Q8 mid-side node back at the midpoint of its (straight) side.
inline void distort_interior(Mesh& mesh, double fraction, double h, unsigned seed = 7) {
  std::set<int> boundary;
  for (const char* name : {"left", "right", "bottom", "top"}) {
    for (int n : mesh.node_sets.at(name))
      boundary.insert(n);
  }
  std::set<int> corners;
  for (const auto& e : mesh.elements)
    corners.insert(e.begin(), e.begin() + 4);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset(-fraction * h, fraction * h);
  for (int n : corners) {
    if (boundary.count(n))
      continue;
    mesh.nodes[n] += Eigen::Vector2d(offset(rng), offset(rng));
  }
  if (mesh.type == ElementType::Q8) {
    for (const auto& e : mesh.elements) {
      for (int s = 0; s < 4; ++s) {
        mesh.nodes[e[4 + s]] = 0.5 * (mesh.nodes[e[s]] + mesh.nodes[e[(s + 1) % 4]]);
      }
    }
  }
}

/// Least-squares slope of log(error) against log(h): the observed order of convergence.
inline double observed_order(const std::vector<double>& h, const std::vector<double>& error) {
  const int n = static_cast<int>(h.size());
  double mx = 0, my = 0;
  for (int i = 0; i < n; ++i) {
    mx += std::log(h[i]) / n;
    my += std::log(error[i]) / n;
  }
  double sxy = 0, sxx = 0;
  for (int i = 0; i < n; ++i) {
    sxy += (std::log(h[i]) - mx) * (std::log(error[i]) - my);
    sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
  }
  return sxy / sxx;
}

/// The largest absolute entry of a vector (a scale for relative tolerances).
inline double max_abs(const Eigen::VectorXd& v) {
  return v.cwiseAbs().maxCoeff();
}

}  // namespace cs::solver::test
