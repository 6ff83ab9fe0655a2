// P_a: contact patch test, matching nodes (axisymmetric). The model is built by build_patch_test
// (suites/problems/patch_test.cpp, whose header states the geometry, boundary conditions, oracle
// and sampling). Run: contact-suite case P_a --mesh F --element Q4 --algorithm LMP --contact ss

#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::P_a>() {
  using schema::Quantity;
  static const ProblemDescriptor d{
      {ProblemId::P_a,
       "contact patch test, matching nodes (axisymmetric)",
       "axisymmetric contact patch test, matched nodes",
       /*axisymmetric=*/true,
       /*singular=*/false,
       "5",
       "Eq. 8",
       {{Quantity::sigma_z_max, "−σ<sub>z</sub><sup>max</sup>/p", "-sigma_z^max/p", "5", "main"}}},
      problems::study_parameters({}),
      problems::build_patch_test,
      schema::Situation::matched_patch,
      schema::LengthScale::contact_half_width_a,
      /*relative_cost=*/1.0,
      {MeshFamily::patch, 1.0, 8, 64},
      {"table", "patch_test"}};
  return d;
}

}  // namespace cs::suites
