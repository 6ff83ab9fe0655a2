#include "solver/contact/load_step.hpp"

namespace cs::solver {

LoadCase superpose(const std::vector<std::pair<double, LoadCase>>& terms) {
  LoadCase out;
  for (const auto& [factor, loads] : terms) {
    const double f = factor;
    for (const EdgeTraction& t : loads.tractions) {
      VectorField traction = [f, v = t.traction](const Eigen::Vector2d& x) -> Eigen::Vector2d {
        return f * v(x);
      };
      out.tractions.push_back({t.edge_set, std::move(traction), t.gauss_points});
    }
    for (const EdgePressure& p : loads.pressures) {
      ScalarField pressure = [f, v = p.pressure](const Eigen::Vector2d& x) { return f * v(x); };
      out.pressures.push_back({p.edge_set, std::move(pressure), p.gauss_points});
    }
    for (const PointForce& p : loads.point_forces)
      out.point_forces.push_back({p.where, f * p.force});
    for (const BodyForce& b : loads.body_forces) {
      VectorField density = [f, v = b.force_density](const Eigen::Vector2d& x) -> Eigen::Vector2d {
        return f * v(x);
      };
      out.body_forces.push_back({std::move(density), b.body});
    }
  }
  return out;
}

}  // namespace cs::solver
