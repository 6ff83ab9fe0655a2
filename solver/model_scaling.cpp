#include "solver/model_scaling.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "solver/model_error.hpp"

namespace cs::solver {
namespace {

void require_factor(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw ModelError(
        fmt::format("model scaling: {} {} (must be a positive finite number)", what, value));
  }
}

/// S f(x' / L): a traction, pressure or body-force density in the scaled coordinates.
/// An empty callable stays empty (validate() names it).
ScalarField scaled_field(ScalarField f, double L, double factor) {
  if (!f)
    return {};
  return [f = std::move(f), L, factor](const Eigen::Vector2d& x) { return factor * f(x / L); };
}

VectorField scaled_field(VectorField f, double L, double factor) {
  if (!f)
    return {};
  return [f = std::move(f), L, factor](const Eigen::Vector2d& x) -> Eigen::Vector2d {
    return factor * f(x / L);
  };
}

LoadCase scaled_loads(const LoadCase& loads, const ModelScaling& s, AnalysisType analysis) {
  const double L = s.length_L, S = s.stress_S;
  LoadCase out;
  for (const EdgeTraction& t : loads.tractions)
    out.tractions.push_back({t.edge_set, scaled_field(t.traction, L, S), t.gauss_points});
  for (const EdgePressure& p : loads.pressures)
    out.pressures.push_back({p.edge_set, scaled_field(p.pressure, L, S), p.gauss_points});
  const double force = s.force_factor(analysis);
  for (const PointForce& f : loads.point_forces)
    out.point_forces.push_back({f.where, force * f.force});
  for (const BodyForce& b : loads.body_forces)
    out.body_forces.push_back({scaled_field(b.force_density, L, S / L), b.body});
  return out;
}

}  // namespace

double ModelScaling::force_factor(AnalysisType analysis) const {
  return analysis == AnalysisType::Axisymmetric ? stress_S * length_L * length_L
                                                : stress_S * length_L;
}

void validate(const ModelScaling& scaling) {
  require_factor(scaling.length_L, "length factor L");
  require_factor(scaling.stress_S, "stress factor S");
}

Model scaled(const Model& model, const ModelScaling& scaling) {
  validate(scaling);
  const double L = scaling.length_L, S = scaling.stress_S;
  Model out;
  out.mesh = model.mesh;
  for (Eigen::Vector2d& x : out.mesh.nodes)
    x *= L;
  out.analysis = model.analysis;
  out.materials = model.materials;
  for (Material& m : out.materials)
    m.youngs_modulus_E *= S;
  for (const PrescribedDisplacement& p : model.prescribed)
    out.prescribed.push_back({p.where, p.component, scaled_field(p.value, L, L)});
  out.loads = scaled_loads(model.loads, scaling, model.analysis);
  out.quadrature = model.quadrature;
  return out;
}

}  // namespace cs::solver
