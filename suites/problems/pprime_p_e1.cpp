// Pprime_p_E1: the mismatched-node contact patch test P′_p with an indenter of the block's
// modulus (E_ratio = 1 by default; plane strain). The study's P′ indenter is nearly rigid (E ratio
// 1e6), which makes the test trivial: every option of ours passes it exactly. With equal moduli
// both bodies strain and the mismatched nodes of the interface must transmit the uniform
// pressure between two deformable surfaces, which is what a patch test is for. The exact
// state is still uniform, sigma_z = -p (Eq. 6: with one E and nu both bodies expand alike, so
// the frictionless interface carries no shear). Built by build_patch_test
// (suites/problems/patch_test.cpp). Run: contact-suite case Pprime_p_E1 --mesh C --element Q4
// --algorithm LMP --contact mortar

#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::Pprime_p_E1>() {
  using schema::Quantity;
  static const ProblemDescriptor d{
      {ProblemId::Pprime_p_E1,
       "contact patch test, non-matching nodes, equal moduli (plane strain)",
       "plane-strain contact patch test, mismatched nodes, indenter of the block's modulus",
       /*axisymmetric=*/false,
       /*singular=*/false,
       "",
       "Eq. 6",
       {{Quantity::sigma_z_max, "−σ<sub>z</sub><sup>max</sup>/p", "-sigma_z^max/p", "", ""}}},
      problems::with_default(problems::study_parameters({}), "E_ratio", 1.0),
      problems::build_patch_test,
      schema::Situation::mismatched_patch_equal_moduli,
      schema::LengthScale::contact_half_width_a,
      /*relative_cost=*/1.0,
      {MeshFamily::mismatched_patch, 1.0, 10, 0},
      {"table", "patch_test"}};
  return d;
}

}  // namespace cs::suites
