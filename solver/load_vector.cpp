#include "solver/load_vector.hpp"

#include "solver/edge_loads.hpp"
#include "solver/elements/element_stiffness.hpp"

namespace cs::solver {

Eigen::VectorXd assemble_load_vector(const Model& model, const LoadCase& loads) {
  const Mesh& mesh = model.mesh;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * mesh.n_nodes());
  for (const EdgeTraction& t : loads.tractions)
    add_edge_traction(model, t, f);
  for (const EdgePressure& p : loads.pressures)
    add_edge_pressure(model, p, f);
  for (const PointForce& p : loads.point_forces) {
    for (int n : resolve_nodes(mesh, p.where)) {
      f[2 * n] += p.force.x();
      f[2 * n + 1] += p.force.y();
    }
  }
  if (!loads.body_forces.empty()) {
    const int points = model.body_force_points();
    ElementVector f_e;
    for (int e = 0; e < mesh.n_elements(); ++e) {
      const int body = mesh.element_body[e];
      const ElementGeometry g = element_geometry(mesh, model.analysis, e);
      for (const BodyForce& b : loads.body_forces) {
        if (b.body >= 0 && b.body != body)
          continue;
        element_body_force(g, b.force_density, points, f_e);
        for (int a = 0; a < g.n_nodes; ++a) {
          f[2 * mesh.elements[e][a]] += f_e(2 * a);
          f[2 * mesh.elements[e][a] + 1] += f_e(2 * a + 1);
        }
      }
    }
  }
  return f;
}

}  // namespace cs::solver
