// H_p: Hertz contact of a cylinder (plane strain). The model is built by build_hertz
// (suites/problems/hertz.cpp, whose header states the geometry, boundary conditions, oracle and
// sampling).
// Run: contact-suite case H_p --mesh F --element Q4 --algorithm LMP --contact ss

#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::H_p>() {
  using schema::Quantity;
  static const ProblemDescriptor d{
      {ProblemId::H_p,
       "Hertz contact of a cylinder (plane strain)",
       "plane-strain Hertzian contact",
       /*axisymmetric=*/false,
       /*singular=*/false,
       "7, 8",
       "Eq. 15",
       {{Quantity::sigma_c, "−σ<sub>z</sub>(0, 0)/p", "-sigma_z(0,0)/p", "7", "contact"},
        {Quantity::sigma_h, "−σ<sub>x</sub>(0, 0)/p", "-sigma_x(0,0)/p", "8", "horizontal"},
        {Quantity::contact_half_width,
         "a<sub>FE</sub>/a, halfway between the last node carrying pressure and the next", "a_FE/a",
         "", ""}}},
      problems::study_parameters(
          {problems::extent_parameter(), problems::half_space_gap_parameter()}),
      problems::build_hertz,
      schema::Situation::smooth_curved,
      schema::LengthScale::contact_half_width_a,
      /*relative_cost=*/1.0,
      {MeshFamily::hertz, 4.0, 16, 256},
      {"hertz-plane", "hertz_plane"}};
  return d;
}

}  // namespace cs::suites
