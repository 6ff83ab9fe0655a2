#include "suites/problem_scaling.hpp"

namespace cs::suites {
namespace {

StudyMeshInfo scaled_mesh_info(StudyMeshInfo info, double L) {
  for (double* length : {&info.block_width, &info.block_depth, &info.indenter_half_width,
                         &info.indenter_height, &info.h_contact, &info.h_background}) {
    *length *= L;
  }
  for (solver::RefinementBox& box : info.steuermann_boxes) {
    for (double* length : {&box.cell_size, &box.x_min, &box.x_max, &box.z_min, &box.z_max})
      *length *= L;
  }
  return info;
}

}  // namespace

ProblemSetup scaled(const ProblemSetup& setup, const solver::ModelScaling& scaling) {
  const double L = scaling.length_L, S = scaling.stress_S;
  ProblemSetup out;
  out.model = solver::scaled(setup.model, scaling);  // validates the factors
  const double force = scaling.force_factor(setup.model.analysis);
  out.pair = {setup.pair.contact_surface, solver::scale_lengths(setup.pair.target, L)};
  if (setup.load_control) {
    out.load_control = setup.load_control;  // delta and delta_guess in the original units
    out.load_control->target_load *= force;
  }
  out.mesh_info = scaled_mesh_info(setup.mesh_info, L);
  out.p = S * setup.p;
  out.length_unit = L * setup.length_unit;
  out.contact_half_width_a = L * setup.contact_half_width_a;
  out.quantities = setup.quantities;
  if (setup.exact_pressure_over_p) {
    out.exact_pressure_over_p = [exact = setup.exact_pressure_over_p, L](double x) {
      return exact(x / L);
    };
  }
  out.load_steps = setup.load_steps;
  out.exact_interface_force = force * setup.exact_interface_force;
  return out;
}

}  // namespace cs::suites
