// F_p: Sadowsky flat punch, singular (plane strain). The model is built by build_flat_punch
// (suites/problems/flat_punch.cpp, whose header states the geometry, boundary conditions, oracle
// and sampling). Run: contact-suite case F_p --mesh F --element Q4 --algorithm LMP --contact ss

#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::F_p>() {
  using schema::Quantity;
  static const ProblemDescriptor d{
      {ProblemId::F_p,
       "Sadowsky flat punch, singular (plane strain)",
       "plane-strain flat punch",
       /*axisymmetric=*/false,
       /*singular=*/true,
       "13",
       "Eq. 39",
       {{Quantity::sigma_c_star, "−σ<sub>z</sub>(a, 0)/p", "-sigma_z(a,0)/p", "13", ""}}},
      problems::study_parameters(
          {problems::extent_parameter(), problems::half_space_gap_parameter()}),
      problems::build_flat_punch,
      schema::Situation::flat_punch,
      schema::LengthScale::contact_half_width_a,
      /*relative_cost=*/1.0,
      {MeshFamily::flat_punch, 4.0, 32, 1024},
      {"sadowsky", "flat_punch_plane"}};
  return d;
}

}  // namespace cs::suites
