#include "solver/internal_forces.hpp"

#include <vector>

#include "solver/elements/element_stiffness.hpp"
#include "solver/material.hpp"

namespace cs::solver {

Eigen::VectorXd internal_forces(const Model& model, const Eigen::VectorXd& u) {
  const Mesh& mesh = model.mesh;
  std::vector<Eigen::Matrix4d> D;
  for (const auto& m : model.materials)
    D.push_back(elasticity_matrix(m));
  const int nen = mesh.n_element_nodes();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size());
  ElementMatrix K_e;
  Eigen::VectorXd u_e(2 * nen);
  for (int e = 0; e < mesh.n_elements(); ++e) {
    element_stiffness(element_geometry(mesh, model.analysis, e), D[mesh.element_body[e]],
                      model.element_points(), K_e);
    const auto& nodes = mesh.elements[e];
    for (int a = 0; a < nen; ++a)
      u_e.segment<2>(2 * a) = u.segment<2>(2 * nodes[a]);
    const Eigen::VectorXd f_e = K_e * u_e;
    for (int a = 0; a < nen; ++a)
      f.segment<2>(2 * nodes[a]) += f_e.segment<2>(2 * a);
  }
  return f;
}

}  // namespace cs::solver
