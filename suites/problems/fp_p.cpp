// FP_p: frictional contact patch test, stick (plane strain): uniform pressure p, then uniform
// shear tau = tau_over_mu_p x mu p < mu p. The model is built by build_frictional_patch
// (suites/problems/frictional_patch.cpp, whose header states the geometry, boundary conditions,
// oracle and sampling). Beyond the study (no table of its own). MPC is refused (no slip).
// There is no FP_a, stick or sliding: a uniform tau_rz breaks axisymmetric equilibrium
// (d tau_rz/dr + d sigma_z/dz + tau_rz/r = tau_rz/r != 0), so the frictional patch test has no
// uniform exact state in the r-z plane; the sliding variant (|tau| = mu p everywhere with p
// uniform) needs the same uniform |tau_rz| > 0, which also contradicts tau_rz(0, z) = 0 on the
// axis. Computed in tests/solver/test_fe_axisymmetric_shear.cpp: the uniform shear field is
// reproduced to round-off in plane strain and departs from itself in the r-z plane.
// Run: contact-suite case FP_p --mesh F --element Q4 --algorithm PLM --contact ss --set mu=0.3

#include "suites/friction_cases.hpp"
#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::FP_p>() {
  using schema::Quantity;
  auto parameters = problems::study_parameters(friction_parameters(0.3));
  std::erase_if(parameters, [](const ParameterSpec& s) { return s.name == "E_ratio"; });
  parameters.push_back({"tau_over_mu_p", 0.5, 0.0, 1e3, true, true,
                        "applied shear over mu p (< 1: stick; >= 1 is past the stick oracle)"});
  static const ProblemDescriptor d{
      {ProblemId::FP_p,
       "frictional contact patch test, stick (plane strain)",
       "plane-strain frictional patch test",
       /*axisymmetric=*/false,
       /*singular=*/false,
       "",
       "uniform state (frictional_patch_test.hpp)",
       {{Quantity::tau_max, "−τ<sub>xz</sub><sup>max</sup>/p", "-tau_xz^max/p", "", ""},
        {Quantity::sigma_z_max, "−σ<sub>z</sub><sup>max</sup>/p", "-sigma_z^max/p", "", ""}}},
      parameters,
      problems::build_frictional_patch,
      schema::Situation::frictional,
      schema::LengthScale::contact_half_width_a,
      /*relative_cost=*/1.0,
      {MeshFamily::patch, 1.0, 8, 0},
      {"", ""}};
  return d;
}

}  // namespace cs::suites
