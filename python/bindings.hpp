#pragma once
// The parts of the Python module `contact_suite`, one function per binding file, and the helper
// that evaluates an oracle at many points: scalars in give a float, NumPy arrays (or anything
// numpy.asarray takes) in give arrays of their broadcast shape.

#include <array>
#include <cstddef>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace cs::python {

namespace py = pybind11;

void bind_contact_oracles(py::module_& m);  // bind_contact_oracles.cpp
void bind_field_oracles(py::module_& m);    // bind_field_oracles.cpp
void bind_results(py::module_& m);          // bind_results.cpp
void bind_grading(py::module_& m);          // bind_grading.cpp

/// f (std::array<double, NIn> -> std::array<double, NOut>) at every point of the NumPy
/// broadcast of `inputs`; each output a float when every input is a scalar, else an array.
template <std::size_t NIn, std::size_t NOut, class F>
std::array<py::object, NOut> evaluate(const std::array<py::object, NIn>& inputs, F&& f) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const py::module_ np = py::module_::import("numpy");
  py::tuple args(NIn);
  for (std::size_t k = 0; k < NIn; ++k)
    args[k] = np.attr("asarray")(inputs[k], "float64");
  const py::tuple broadcast = np.attr("broadcast_arrays")(*args);
  std::array<Array, NIn> in;
  for (std::size_t k = 0; k < NIn; ++k)  // a copy too large raises MemoryError here
    in[k] = np.attr("require")(broadcast[k], "float64", "C").template cast<Array>();
  const std::vector<py::ssize_t> shape(in[0].shape(), in[0].shape() + in[0].ndim());
  std::array<Array, NOut> out;
  for (auto& o : out)
    o = Array(shape);
  for (py::ssize_t i = 0; i < in[0].size(); ++i) {
    std::array<double, NIn> point;
    for (std::size_t k = 0; k < NIn; ++k)
      point[k] = in[k].data()[i];
    const std::array<double, NOut> value = f(point);
    for (std::size_t k = 0; k < NOut; ++k)
      out[k].mutable_data()[i] = value[k];
  }
  std::array<py::object, NOut> result;
  for (std::size_t k = 0; k < NOut; ++k)
    result[k] = shape.empty() ? py::object(py::float_(out[k].data()[0])) : py::object(out[k]);
  return result;
}

/// One input, one output.
template <class F>
py::object evaluate1(const py::object& x, F&& f) {
  return evaluate<1, 1>(
      {x}, [&](const std::array<double, 1>& p) { return std::array<double, 1>{f(p[0])}; })[0];
}

}  // namespace cs::python
