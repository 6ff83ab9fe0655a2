// The grading rules, so that a team can grade its own numbers in a test: Eq. 46, the
// convergence verdict, Eq. 47 and the strict divergence verdict, observed orders, Richardson
// extrapolation and the GCI, the noise-aware trend and the guarded observed order. (The rules
// live in grading/; this file is the one place that binds them.)

#include <cmath>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "grading/accuracy.hpp"
#include "grading/convergence.hpp"
#include "grading/divergence.hpp"
#include "grading/richardson.hpp"
#include "python/bindings.hpp"
#include "schema/row_verdict.hpp"

namespace cs::python {
namespace {

using namespace pybind11::literals;
namespace s = cs::schema;

/// `v`, or a ValueError naming `name` when it is not finite: a NaN error or value would pass
/// through the rules as a silent NaN verdict (or a false "asymptotic").
double finite(const char* name, double v) {
  if (!std::isfinite(v))
    throw py::value_error(std::string(name) + " = " + std::to_string(v) +
                          ": must be a finite number");
  return v;
}

/// finite() for each of the C, M, F arguments named `what` ("error" or "value").
void require_finite(const char* what, double c, double m, double f) {
  const std::string w(what);
  finite((w + "_c").c_str(), c);
  finite((w + "_m").c_str(), m);
  finite((w + "_f").c_str(), f);
}

/// f(c, m, f) on three finite arguments named `what`_c, `what`_m, `what`_f.
template <class F>
auto on_finite(const char* what, F f) {
  return [what, f](double c, double m, double fine) {
    require_finite(what, c, m, fine);
    return f(c, m, fine);
  };
}

void bind_records(py::module_& m) {
  py::class_<s::ErrorEstimate>(m, "ErrorEstimate",
                               "Observed order, Richardson limit and GCI of a C, M, F sequence.")
      .def_readonly("asymptotic", &s::ErrorEstimate::asymptotic)
      .def_readonly("observed_order", &s::ErrorEstimate::observed_order,
                    "p = log2(|f_C - f_M| / |f_M - f_F|)")
      .def_readonly("richardson", &s::ErrorEstimate::richardson, "f_F + (f_F - f_M)/(2^p - 1)")
      .def_readonly("gci_percent", &s::ErrorEstimate::gci_percent,
                    "1.25 |(f_F - f_M)/f_F| / (2^p - 1), percent")
      .def_readonly("note", &s::ErrorEstimate::note, "why there is no estimate");
  py::class_<s::DivergenceVerdict>(m, "DivergenceVerdict",
                                   "The divergence verdicts of a singular C, M, F sequence.")
      .def_readonly("eq47", &s::DivergenceVerdict::eq47, "|s_C - s_M| < |s_M - s_F|")
      .def_readonly("monotone", &s::DivergenceVerdict::monotone, "|s_C| < |s_M| < |s_F|")
      .def_readonly("exponent", &s::DivergenceVerdict::exponent, "alpha of |s| ~ h^-alpha")
      .def_readonly("diverges", &s::DivergenceVerdict::diverges,
                    "monotone and alpha in [0.25, 0.75]");
}

}  // namespace

void bind_grading(py::module_& m) {
  bind_records(m);
  m.def("error_percent", py::vectorize([](double value, double exact) {
          if (finite("exact", exact) == 0.0)
            throw py::value_error("exact = 0: the percentage error needs a non-zero exact value");
          return grading::error_percent(value, exact);
        }),
        py::kw_only(), "value"_a, "exact"_a,
        "Signed percentage error 100 (value - exact) / |exact| [%]; scalars or arrays (a NaN "
        "value, one not available, gives NaN; an exact value of 0 or not finite, ValueError).");
  m.def(
      "grade",
      [](double error_percent) {
        return std::string(to_string(grading::grade_of_error(error_percent)));
      },
      "error_percent"_a,
      "Eq. 46 on |error| [%]: 'e' < 1 <= 'g' < 5 <= 's' < 10 <= 'u' (nan: 'u').");
  m.def("is_converging", on_finite("error", &grading::study_converging), py::kw_only(), "error_c"_a,
        "error_m"_a, "error_f"_a,
        "The study's 'c' (Table 2) on the errors [%] of meshes C, M, F: they do not grow and the "
        "fine one is below the coarse one; differences below 0.01 % count as equal.");
  m.def("is_diverging", on_finite("value", &grading::eq47_diverging), py::kw_only(), "value_c"_a,
        "value_m"_a, "value_f"_a,
        "Eq. 47 on the values of meshes C, M, F: |s_C - s_M| < |s_M - s_F|.");
  m.def("divergence_verdict", on_finite("value", &grading::divergence_verdict), py::kw_only(),
        "value_c"_a, "value_m"_a, "value_f"_a,
        "Eq. 47 and the strict verdict: magnitudes growing with one sign and a growth exponent "
        "alpha of |s| ~ h^-alpha in [0.25, 0.75].");
  m.def("error_estimate", on_finite("value", &grading::error_estimate), py::kw_only(), "value_c"_a,
        "value_m"_a, "value_f"_a,
        "Observed order, Richardson limit and Roache's GCI (safety factor 1.25) from the values "
        "on C, M, F (refinement ratio 2).");
  m.def(
      "pair_orders",
      [](std::optional<double> c, std::optional<double> mm, std::optional<double> f) {
        for (const auto& [name, e] : {std::pair{"error_c", c}, {"error_m", mm}, {"error_f", f}}) {
          if (e)
            finite(name, *e);
        }
        return std::array<std::optional<double>, 2>{grading::pair_order(c, mm),
                                                    grading::pair_order(mm, f)};
      },
      py::kw_only(), "error_c"_a, "error_m"_a, "error_f"_a,
      "log2(|e_C|/|e_M|) and log2(|e_M|/|e_F|) from the errors [%] (None where an error is "
      "missing or below 1e-6 %).");
  m.def(
      "trend",
      [](double e_c, double e_m, double e_f, double resolution) {
        require_finite("error", e_c, e_m, e_f);
        finite("resolution_percent", resolution);
        const grading::ConvergenceAssessment a =
            grading::assess_convergence(e_c, e_m, e_f, resolution);
        return py::make_tuple(std::string(to_string(a.trend)), a.floor_percent, a.floor_reason);
      },
      py::kw_only(), "error_c"_a, "error_m"_a, "error_f"_a, "resolution_percent"_a = 0.0,
      "The noise-aware verdict on the errors [%] of C, M, F: ('converging' | 'settled' | "
      "'not_converging', floor [percentage points], the floor's reason); the floor of C -> M, "
      "max(0.01, 0.1 |e_F|, resolution_percent), the last the quantity's own resolution on C "
      "(half the node spacing for one read between two nodes, node_read_resolution_percent); "
      "M -> F's takes half the resolution.");
  m.def(
      "observed_order",
      [](double e_c, double e_m, double e_f, double resolution) {
        require_finite("error", e_c, e_m, e_f);
        finite("resolution_percent", resolution);
        const grading::ObservedOrder o = grading::observed_order(e_c, e_m, e_f, resolution);
        return py::make_tuple(o.order, o.note);
      },
      py::kw_only(), "error_c"_a, "error_m"_a, "error_f"_a, "resolution_percent"_a = 0.0,
      "The observed order of the errors [%] (mean of the two pair orders), or None with the "
      "reason when the sequence is not converging, at noise level or pre-asymptotic (the pair "
      "orders differ by more than 1, or C or M is off by 100 % or more).");
  m.def("node_read_resolution_percent", &grading::node_read_resolution_percent, py::kw_only(),
        "node_spacing"_a, "exact"_a,
        "The resolution [percentage points] of a value read between two nodes: 100 (s / 2) / "
        "|exact|; 0 unless both are positive and finite.");
  m.def("luck_of_one_mesh", on_finite("error", &grading::luck_of_one_mesh), py::kw_only(),
        "error_c"_a, "error_m"_a, "error_f"_a,
        "True when F is graded e or g after an error above 100 % on C or M: not evidence.");
}

}  // namespace cs::python
