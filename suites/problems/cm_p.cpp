// CM_p: Cattaneo-Mindlin partial slip of two similar bodies (plane strain): Hertz's normal load,
// then a tangential load Q = Q_over_mu_P x mu P < mu P in increments. The model is built by
// build_cattaneo_mindlin (suites/problems/cattaneo_mindlin.cpp, whose header states the
// geometry, boundary conditions, oracle and sampling). Beyond the study; MPC is refused.
// Run: contact-suite case CM_p --mesh F --element Q4 --algorithm PLM --contact ss

#include "suites/friction_cases.hpp"
#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::CM_p>() {
  using schema::Quantity;
  auto parameters = problems::study_parameters(friction_parameters(0.3));
  std::erase_if(parameters, [](const ParameterSpec& s) { return s.name == "E_ratio"; });
  parameters.push_back({"Q_over_mu_P", 0.5, 0.0, 1e3, true, true,
                        "tangential load over mu P (< 1: partial slip; >= 1 is past the oracle)"});
  parameters.push_back({"q_increments", 4, 1, 100, true, true,
                        "load steps of the tangential load (after the normal one)", true});
  static const ProblemDescriptor d{
      {ProblemId::CM_p,
       "Cattaneo-Mindlin partial slip of a cylinder (plane strain)",
       "plane-strain Cattaneo-Mindlin",
       /*axisymmetric=*/false,
       /*singular=*/false,
       "",
       "Johnson Sec. 7.1 (cattaneo_mindlin.hpp)",
       {{Quantity::tau_max, "−τ<sub>xz</sub><sup>max</sup>/p", "-tau_xz^max/p", "", ""},
        {Quantity::c_over_a, "c/a", "c/a", "", ""},
        {Quantity::sigma_c, "−σ<sub>z</sub>(0, 0)/p", "-sigma_z(0,0)/p", "", ""}}},
      parameters,
      problems::build_cattaneo_mindlin,
      schema::Situation::frictional,
      schema::LengthScale::contact_half_width_a,
      /*relative_cost=*/1.0,
      {MeshFamily::own, 0.0, 0, 0},
      {"", ""}};
  return d;
}

}  // namespace cs::suites
