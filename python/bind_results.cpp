// The reader of results.json (schema/results_file.hpp) as Python objects: the C++ reader itself
// validates the file and parses every number, so the values are the C++ reader's bit for bit.
// Every axis value is its results.json name ("H_p", "Q4", "converged", "e"); a value that is
// absent is None; surface profiles are NumPy arrays. Records are read-only.

#include <pybind11/stl.h>

#include "python/bindings.hpp"
#include "schema/results_file.hpp"
#include "schema/schema_error.hpp"

namespace cs::python {
namespace {

using namespace pybind11::literals;
namespace s = cs::schema;

template <class E>
std::string name(E v) {
  return std::string(s::to_string(v));
}

template <class E>
std::optional<std::string> name(const std::optional<E>& v) {
  return v ? std::optional<std::string>(name(*v)) : std::nullopt;
}

py::array_t<double> array(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

py::object from_json(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

void bind_spec(py::module_& m) {
  py::class_<s::CaseSpec>(m, "CaseSpec", "One analysis: its value on every case axis.")
      .def_property_readonly(
          "id", [](const s::CaseSpec& c) { return s::case_id(c); },
          "the case id, e.g. 'H_p/F/Q4/LMP/ss'")
      .def_property_readonly(
          "key", [](const s::CaseSpec& c) { return s::case_key(c); },
          "the case id less its mesh, e.g. 'H_p/Q4/LMP/ss'")
      .def_property_readonly("problem", [](const s::CaseSpec& c) { return name(c.problem); })
      .def_property_readonly("mesh", [](const s::CaseSpec& c) { return name(c.mesh); })
      .def_property_readonly("element", [](const s::CaseSpec& c) { return name(c.element); })
      .def_property_readonly("algorithm", [](const s::CaseSpec& c) { return name(c.algorithm); })
      .def_property_readonly("contact", [](const s::CaseSpec& c) { return name(c.contact); })
      .def_property_readonly("target", [](const s::CaseSpec& c) { return name(c.target); })
      .def_property_readonly("recovery", [](const s::CaseSpec& c) { return name(c.recovery); })
      .def_property_readonly("solver", [](const s::CaseSpec& c) { return s::solver_label(c); })
      .def_readonly("overrides", &s::CaseSpec::overrides, "--set name=value pairs")
      .def("__repr__", [](const s::CaseSpec& c) { return "CaseSpec('" + s::case_id(c) + "')"; });
}

void bind_case(py::module_& m) {
  using Q = s::QuantityResult;
  py::class_<Q>(m, "QuantityResult",
                "One graded quantity, normalized by p, positive in compression (e.g. "
                "-sigma_z/p) [-].")
      .def_property_readonly("quantity", [](const Q& q) { return name(q.quantity); })
      .def_readonly("value", &Q::value, "from the nodal stresses (nan: not available)")
      .def_readonly("exact", &Q::exact, "the exact value (inf: singular)")
      .def_readonly("error_percent", &Q::error_percent, "signed, percent")
      .def_property_readonly(
          "grade", [](const Q& q) { return name(q.grade); }, "Eq. 46")
      .def_readonly("contact_pressure", &Q::contact_pressure,
                    "the same quantity from the contact pressure, or None")
      .def_readonly("study_exact", &Q::study_exact, "the study's printed exact value, or None")
      .def_property_readonly("singular", &Q::singular);
  using C = s::CaseResult;
  py::class_<C>(m, "CaseResult", "Everything recorded about one analysis.")
      .def_readonly("spec", &C::spec)
      .def_property_readonly("id", [](const C& c) { return s::case_id(c.spec); })
      .def_property_readonly("status", [](const C& c) { return name(c.status); })
      .def_readonly("reason", &C::reason)
      .def_readonly("kept_files", &C::kept_files,
                    "where another code's failed or unconverged run left its files ('' if none)")
      .def_readonly("iterations", &C::iterations)
      .def_readonly("wall_seconds", &C::wall_seconds, "[s]")
      .def_readonly("peak_rss_mb", &C::peak_rss_mb, "[MB]")
      .def_readonly("n_elements", &C::n_elements)
      .def_readonly("n_equations", &C::n_equations)
      .def_readonly("element_size_h", &C::element_size_h, "over a (or b) [-]")
      .def_readonly("quantities", &C::quantities)
      .def(
          "quantity",
          [](const C& c, const std::string& q) -> std::optional<Q> {
            const Q* r = c.quantity(s::parse<s::Quantity>(q));
            return r ? std::optional<Q>(*r) : std::nullopt;
          },
          "name"_a, "The record of a quantity ('sigma_c'), or None.")
      .def_property_readonly("x_over_a", [](const C& c) { return array(c.profile.x_over_a); })
      .def_property_readonly("sigma_z_over_p",
                             [](const C& c) { return array(c.profile.sigma_z_over_p); })
      .def_property_readonly("pressure_over_p",
                             [](const C& c) { return array(c.profile.pressure_over_p); })
      .def(
          "to_dict", [](const C& c) { return from_json(s::to_json(c)); },
          "The record as results.json holds it.");
}

void bind_row(py::module_& m) {
  using R = s::RowVerdict;
  py::class_<R>(m, "RowVerdict",
                "One quantity of one option set on meshes C, M, F: graded (Eq. 46) and checked "
                "for convergence or, singular problems, divergence (Eq. 47).")
      .def_readonly("id", &R::id)
      .def_readonly("spec", &R::spec)
      .def_property_readonly("quantity", [](const R& r) { return name(r.quantity); })
      .def_readonly("values", &R::values, "C, M, F [-] (None: missing or failed)")
      .def_readonly("errors", &R::errors, "percent, C, M, F")
      .def_property_readonly("grade", [](const R& r) { return name(r.grade); })
      .def_property_readonly("graded_mesh", [](const R& r) { return name(r.graded_mesh); })
      .def_readonly("converging", &R::converging)
      .def_readonly("diverging", &R::diverging)
      .def_readonly("pair_orders", &R::pair_orders, "log2(|e_C|/|e_M|), log2(|e_M|/|e_F|)")
      .def_readonly("estimate", &R::estimate)
      .def_readonly("divergence", &R::divergence)
      .def("to_dict", [](const R& r) { return from_json(s::to_json(r)); });
}

void bind_document(py::module_& m) {
  using D = s::ResultsDocument;
  py::class_<D>(m, "ResultsDocument", "A whole results file.")
      .def_readonly("source", &D::source)
      .def_readonly("cases", &D::cases)
      .def_readonly("rows", &D::rows)
      .def_property_readonly(
          "run", [](const D& d) { return from_json(s::to_json(d)["run"]); },
          "the run's record (machine, versions, settings, timing) as a dict")
      .def_property_readonly("problems",
                             [](const D& d) { return from_json(s::to_json(d)["problems"]); })
      .def(
          "case",
          [](const D& d, const std::string& id) -> std::optional<s::CaseResult> {
            for (const auto& c : d.cases) {
              if (s::case_id(c.spec) == id)
                return c;
            }
            return std::nullopt;
          },
          "id"_a, "The case of an id, or None.")
      .def(
          "row",
          [](const D& d, const std::string& id) -> std::optional<s::RowVerdict> {
            for (const auto& r : d.rows) {
              if (r.id == id)
                return r;
            }
            return std::nullopt;
          },
          "id"_a, "The row of an id, or None.");
  m.def(
      "read_results", [](const std::string& path) { return s::read_results_file(path); }, "path"_a,
      "Reads and validates a results.json (schema contact-suite/results, docs/results-schema.md) "
      "with the suite's own reader. Raises ValueError with the command line's message for a "
      "missing, malformed or invalid file.");
}

}  // namespace

void bind_results(py::module_& m) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const s::SchemaError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  bind_spec(m);
  bind_case(m);
  bind_row(m);
  bind_document(m);
}

}  // namespace cs::python
