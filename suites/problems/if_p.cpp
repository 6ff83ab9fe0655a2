// IF_p: interference fit of a shaft in a ring (plane strain): conformal contact along a quarter
// circle, the radial interference delta an initial overlap the contact resolves. The model is built
// by build_interference_fit (suites/problems/interference_fit.cpp, whose header states the
// geometry, boundary conditions, oracle and sampling). Beyond the study (no table of its own). Run:
// contact-suite case IF_p --mesh F --element Q8 --algorithm LMP --contact ns

#include "suites/problems/interference_fit_parameters.hpp"
#include "suites/problems/problem_builders.hpp"

namespace cs::suites {

template <>
const ProblemDescriptor& problem_descriptor<ProblemId::IF_p>() {
  using schema::Quantity;
  static const ProblemDescriptor d{
      {ProblemId::IF_p,
       "interference fit of a shaft in a ring (plane strain)",
       "plane-strain interference fit",
       /*axisymmetric=*/false,
       /*singular=*/false,
       "",
       "Lame, Timoshenko & Goodier Sec. 28 (interference_fit.hpp)",
       {{Quantity::p_mean, "p<sub>mean</sub>/p", "p_mean/p", "", ""},
        {Quantity::p_arc, "p(θ<sub>max</sub>)/p", "p(theta_max)/p", "", ""}}},
      problems::interference_fit_parameters(),
      problems::build_interference_fit,
      schema::Situation::conformal_fit,
      schema::LengthScale::bore_radius_b,
      /*relative_cost=*/1.0,
      {MeshFamily::own, 0.0, 0, 0},
      {"", ""}};
  return d;
}

}  // namespace cs::suites
