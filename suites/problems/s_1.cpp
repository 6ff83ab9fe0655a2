// S_1: Steuermann rounded punch, r_e/b = 1 (plane strain). The model is built by build_steuermann
// (suites/problems/steuermann.cpp, whose header states the geometry, boundary conditions, oracle
// and sampling). Run: contact-suite case S_1 --mesh F --element Q4 --algorithm LMP --contact ss

#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::S_1>() {
  using schema::Quantity;
  static const ProblemDescriptor d{
      {ProblemId::S_1,
       "Steuermann rounded punch, r_e/b = 1 (plane strain)",
       "plane-strain Steuermann contact, r_e/b = 1",
       /*axisymmetric=*/false,
       /*singular=*/false,
       "10",
       "Eq. 31",
       {{Quantity::sigma_c, "max of −σ<sub>z</sub>/p on z = 0", "max -sigma_z/p on z = 0", "10",
         "main"},
        {Quantity::contact_half_width,
         "a<sub>FE</sub>/b, halfway between the last node carrying pressure and the next", "a_FE/b",
         "", ""}}},
      problems::study_parameters(
          {{"re_over_b", 1.0, 0.0, 10.0, false, true,
            "edge radius r_e over the half-width b of the punch's flat face"},
           problems::extent_parameter(),
           problems::half_space_gap_parameter()}),
      problems::build_steuermann,
      schema::Situation::rounded_punch,
      schema::LengthScale::punch_half_width_b,
      /*relative_cost=*/30.0,
      {MeshFamily::steuermann, 0.0, 0, 8372},
      {"steuermann", "steuermann"}};
  return d;
}

}  // namespace cs::suites
