#include "solver/edge_loads.hpp"

#include "solver/elements/gauss_rule.hpp"
#include "solver/elements/side_geometry.hpp"

namespace cs::solver {
namespace {

/// f += int N_k t(x, n) w ds over every side of `edge_set`; t as a function of the point and
/// its outward normal.
template <typename TractionAt>
void integrate_along(const Model& model, const std::string& edge_set, int points,
                     const TractionAt& traction_at, Eigen::VectorXd& f) {
  const Mesh& mesh = model.mesh;
  const GaussRule1D& rule = gauss_rule_1d(model.edge_points(points));
  const bool axi = model.analysis == AnalysisType::Axisymmetric;
  for (const ElementSide& side : resolve_edge_set(mesh, edge_set)) {
    for (int q = 0; q < rule.size(); ++q) {
      const SidePoint p = side_point(mesh, side, rule.points[q]);
      const double weight = rule.weights[q] * p.jacobian * (axi ? p.position.x() : 1.0);
      const Eigen::Vector2d force = traction_at(p.position, p.outward_normal) * weight;
      for (int k = 0; k < p.shape.n; ++k) {
        f[2 * p.nodes[k]] += p.shape.N[k] * force.x();
        f[2 * p.nodes[k] + 1] += p.shape.N[k] * force.y();
      }
    }
  }
}

}  // namespace

void add_edge_traction(const Model& model, const EdgeTraction& traction, Eigen::VectorXd& f) {
  integrate_along(
      model, traction.edge_set, traction.gauss_points,
      [&](const Eigen::Vector2d& x, const Eigen::Vector2d&) { return traction.traction(x); }, f);
}

void add_edge_pressure(const Model& model, const EdgePressure& pressure, Eigen::VectorXd& f) {
  integrate_along(
      model, pressure.edge_set, pressure.gauss_points,
      [&](const Eigen::Vector2d& x, const Eigen::Vector2d& n) {
        return Eigen::Vector2d(-pressure.pressure(x) * n);
      },
      f);
}

}  // namespace cs::solver
