// The compiled part of the Python package `contact_suite` (contact_suite._core, whose names the
// package exports): the suite's exact solutions, its results reader and its grading rules, for
// solver teams who test in Python. The package's case-directory reader and results writer are
// plain Python (python/contact_suite/).
//
//   import contact_suite as cs
//   c = cs.hertz_plane_contact(R=100.0, E=1000.0, nu=0.25, P=2.0)
//   c.p_max / c.p_mean                      # 4/pi (study Eq. 15)
//   cs.mcewen_stress(a=c.contact_half_width_a, p=c.p_mean, x=xs, z=zs)  # NumPy arrays in/out

#include "python/bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "contact-suite: exact solutions of frictionless and frictional contact problems (the "
      "oracles), the reader of results.json, and the grading rules of the study (Eq. 46, "
      "convergence, divergence, Eq. 47). Out-of-range parameters raise ValueError with the "
      "message the command line prints.";
  m.attr("__version__") = CONTACT_SUITE_VERSION;
  cs::python::bind_contact_oracles(m);
  cs::python::bind_field_oracles(m);
  cs::python::bind_results(m);
  cs::python::bind_grading(m);
}
