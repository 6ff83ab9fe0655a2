// Pprime_p: contact patch test, non-matching nodes (plane strain). The model is built by
// build_patch_test (suites/problems/patch_test.cpp, whose header states the geometry, boundary
// conditions, oracle and sampling). Run: contact-suite case Pprime_p --mesh F --element Q4
// --algorithm LMP --contact ss

#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::Pprime_p>() {
  using schema::Quantity;
  static const ProblemDescriptor d{
      {ProblemId::Pprime_p,
       "contact patch test, non-matching nodes (plane strain)",
       "plane-strain contact patch test, mismatched nodes",
       /*axisymmetric=*/false,
       /*singular=*/false,
       "4",
       "Eq. 6",
       {{Quantity::sigma_z_max, "−σ<sub>z</sub><sup>max</sup>/p", "-sigma_z^max/p", "4", "main"}}},
      problems::study_parameters({}),
      problems::build_patch_test,
      schema::Situation::mismatched_patch,
      schema::LengthScale::contact_half_width_a,
      /*relative_cost=*/1.0,
      {MeshFamily::mismatched_patch, 1.0, 10, 100},
      {"table", "patch_test"}};
  return d;
}

}  // namespace cs::suites
