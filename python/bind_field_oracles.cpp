// The interior stress fields (oracles/*): keyword arguments, the point as x (or r) and z, each
// a scalar or an array (broadcast together). A field answers a dict of its stress components,
// floats for a scalar point, arrays of the broadcast shape otherwise. Units: stresses in the
// unit of the load's pressure (or force per length / area), lengths in any one unit.

#include <string>

#include <pybind11/stl.h>

#include "oracles/boussinesq.hpp"
#include "oracles/flamant.hpp"
#include "oracles/flamant_tangential.hpp"
#include "oracles/frictional_patch_test.hpp"
#include "oracles/hertz_tangential_traction.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/patch_test.hpp"
#include "oracles/strip_load.hpp"
#include "python/bindings.hpp"

namespace cs::python {
namespace {

using namespace pybind11::literals;
namespace o = cs::oracles;

/// A plane field f(PlanePoint) at (x, z): {"sigma_x", "sigma_z", "tau_xz"}.
template <class F>
py::dict plane_field(const py::object& x, const py::object& z, F&& f) {
  const auto v = evaluate<2, 3>({x, z}, [&](const std::array<double, 2>& p) {
    const o::PlaneStress s = f(o::PlanePoint{p[0], p[1]});
    return std::array<double, 3>{s.sigma_x, s.sigma_z, s.tau_xz};
  });
  return py::dict("sigma_x"_a = v[0], "sigma_z"_a = v[1], "tau_xz"_a = v[2]);
}

/// An axisymmetric field f(AxiPoint) at (r, z): {"sigma_r", "sigma_z", "sigma_theta", "tau_rz"}.
template <class F>
py::dict axi_field(const py::object& r, const py::object& z, F&& f) {
  const auto v = evaluate<2, 4>({r, z}, [&](const std::array<double, 2>& p) {
    const o::AxiStress s = f(o::AxiPoint{p[0], p[1]});
    return std::array<double, 4>{s.sigma_r, s.sigma_z, s.sigma_theta, s.tau_rz};
  });
  return py::dict("sigma_r"_a = v[0], "sigma_z"_a = v[1], "sigma_theta"_a = v[2],
                  "tau_rz"_a = v[3]);
}

const char* const kPlaneReturns =
    "\n\nReturns {'sigma_x', 'sigma_z', 'tau_xz'} [stress], tension positive, z into the body; "
    "floats for a scalar point, arrays of the broadcast shape of x and z otherwise.";
const char* const kAxiReturns =
    "\n\nReturns {'sigma_r', 'sigma_z', 'sigma_theta', 'tau_rz'} [stress], tension positive, z "
    "into the body; floats for a scalar point, arrays of the broadcast shape of r and z.";

std::string doc(const char* text, const char* returns) {
  return std::string(text) + returns;
}

void bind_hertzian_fields(py::module_& m) {
  m.def(
      "mcewen_stress",
      [](double a, double p, const py::object& x, const py::object& z) {
        return plane_field(x, z, [&](o::PlanePoint at) { return o::mcewen_stress({a, p}, at); });
      },
      py::kw_only(), "a"_a, "p"_a, "x"_a, "z"_a,
      doc("McEwen's interior field of plane-strain Hertz contact (study Eqs. 11-12): the field "
          "under the pressure (4p/pi) (1 - x^2/a^2)^(1/2) on |x| < a. With k = 4p/(pi a), "
          "sigma_z = -k m (1 - (z^2 + n^2)/(m^2 + n^2)), sigma_x = -k (m (1 + (z^2 + n^2)/"
          "(m^2 + n^2)) - 2z), tau_xz = -k n (m^2 - z^2)/(m^2 + n^2).\n\na: contact half-width "
          "[length] > 0; p: mean contact pressure P/(2a) [stress] > 0; x, z: the point [length], "
          "z >= 0.",
          kPlaneReturns)
          .c_str());
  m.def(
      "hertz_tangential_traction_stress",
      [](double a, double q0, const py::object& x, const py::object& z) {
        return plane_field(x, z, [&](o::PlanePoint at) {
          return o::hertz_tangential_traction_stress({a, q0}, at);
        });
      },
      py::kw_only(), "a"_a, "q0"_a, "x"_a, "z"_a,
      doc("The field of the semi-elliptic tangential traction q0 (1 - x^2/a^2)^(1/2) on |x| < a "
          "acting on the body in +x (Johnson Sec. 7.1): sigma_z = -k n (m^2 - z^2)/(m^2 + n^2), "
          "tau_xz = -k (m (1 + (z^2 + n^2)/(m^2 + n^2)) - 2z), sigma_x = -2k (x - n) + "
          "k n (m^2 - z^2)/(m^2 + n^2), k = q0/a.\n\na: half-width [length] > 0; q0: peak "
          "traction [stress], finite and non-zero; x, z: the point [length], z >= 0.",
          kPlaneReturns)
          .c_str());
}

void bind_point_and_strip_fields(py::module_& m) {
  m.def(
      "strip_load_stress",
      [](double a, double p, const py::object& x, const py::object& z) {
        return plane_field(x, z, [&](o::PlanePoint at) {
          return o::strip_load_stress({a, p}, at);
        });
      },
      py::kw_only(), "a"_a, "p"_a, "x"_a, "z"_a,
      doc("Uniform pressure p on the strip |x| < a (study Eqs. 35-36; Johnson p. 21): sigma_z = "
          "-(p/2pi)(2(t1 - t2) - (sin 2t1 - sin 2t2)), sigma_x = -(p/2pi)(2(t1 - t2) + (sin 2t1 - "
          "sin 2t2)), tau_xz = (p/2pi)(cos 2t1 - cos 2t2), angles from the surface.\n\na: "
          "half-width [length] > 0; p: pressure [stress] > 0; x, z: the point [length], z >= 0, "
          "not a strip edge on the surface.",
          kPlaneReturns)
          .c_str());
  m.def(
      "flamant_stress",
      [](double P, const py::object& x, const py::object& z) {
        return plane_field(x, z, [&](o::PlanePoint at) { return o::flamant_stress({P}, at); });
      },
      py::kw_only(), "P"_a, "x"_a, "z"_a,
      doc("Flamant's normal line load (Johnson Ch. 2): sigma_x = -(2P/pi) x^2 z/r^4, sigma_z = "
          "-(2P/pi) z^3/r^4, tau_xz = -(2P/pi) x z^2/r^4.\n\nP: force per unit length [force/"
          "length] > 0; x, z: the point [length], z >= 0, not the load point.",
          kPlaneReturns)
          .c_str());
  m.def(
      "flamant_tangential_stress",
      [](double Q, const py::object& x, const py::object& z) {
        return plane_field(x, z,
                           [&](o::PlanePoint at) { return o::flamant_tangential_stress({Q}, at); });
      },
      py::kw_only(), "Q"_a, "x"_a, "z"_a,
      doc("Flamant's tangential line load in +x (Johnson Eq. 2.21): sigma_x = -(2Q/pi) x^3/r^4, "
          "sigma_z = -(2Q/pi) x z^2/r^4, tau_xz = -(2Q/pi) x^2 z/r^4.\n\nQ: force per unit "
          "length [force/length], non-zero; x, z: the point [length], z >= 0, not the load point.",
          kPlaneReturns)
          .c_str());
  m.def(
      "boussinesq_stress",
      [](double P, double nu, const py::object& r, const py::object& z) {
        return axi_field(r, z, [&](o::AxiPoint at) { return o::boussinesq_stress({P, nu}, at); });
      },
      py::kw_only(), "P"_a, "nu"_a, "r"_a, "z"_a,
      doc("Boussinesq's point force on a half-space (study Eqs. 18-19; Johnson p. 51): sigma_r = "
          "(P/2pi)((1 - 2nu)/r^2 (1 - z/rho) - 3 r^2 z/rho^5), sigma_theta = -(P/2pi)(1 - 2nu)"
          "(1/r^2 (1 - z/rho) - z/rho^3), sigma_z = -(3P/2pi) z^3/rho^5, tau_rz = -(3P/2pi) r z^2/"
          "rho^5.\n\nP: force [force] > 0; nu: Poisson's ratio in [0, 0.5); r, z: the point "
          "[length], >= 0, not the load point.",
          kAxiReturns)
          .c_str());
}

void bind_patch_fields(py::module_& m) {
  m.def(
      "patch_test_plane_stress",
      [](double p, const py::object& x, const py::object& z) {
        return plane_field(x, z,
                           [&](o::PlanePoint at) { return o::patch_test_plane_stress({p}, at); });
      },
      py::kw_only(), "p"_a, "x"_a, "z"_a,
      doc("The contact patch test, plane strain (study Eq. 6): sigma_z = -p, sigma_x = tau_xz = "
          "0.\n\np: applied pressure [stress] > 0; x, z: the point [length], z >= 0.",
          kPlaneReturns)
          .c_str());
  m.def(
      "patch_test_axi_stress",
      [](double p, const py::object& r, const py::object& z) {
        return axi_field(r, z, [&](o::AxiPoint at) { return o::patch_test_axi_stress({p}, at); });
      },
      py::kw_only(), "p"_a, "r"_a, "z"_a,
      doc("The contact patch test, axisymmetric (study Eq. 8): sigma_z = -p, the others 0.\n\np: "
          "applied pressure [stress] > 0; r, z: the point [length], >= 0.",
          kAxiReturns)
          .c_str());
  m.def(
      "frictional_patch_stick_stress",
      [](double p, double tau, double mu, const py::object& x, const py::object& z) {
        return plane_field(x, z, [&](o::PlanePoint at) {
          return o::frictional_patch_stick_stress({p, tau, mu}, at);
        });
      },
      py::kw_only(), "p"_a, "tau"_a, "mu"_a, "x"_a, "z"_a,
      doc("Frictional patch test, sticking: sigma_x = 0, sigma_z = -p, tau_xz = -tau.\n\np: "
          "pressure [stress] > 0; tau: shear [stress], 0 <= tau < mu p; mu: friction coefficient "
          "in [0, 10]; x, z: the point [length], z >= 0.",
          kPlaneReturns)
          .c_str());
  m.def(
      "frictional_patch_slip_stress",
      [](double p, double mu, const py::object& x, const py::object& z) {
        return plane_field(x, z, [&](o::PlanePoint at) {
          return o::frictional_patch_slip_stress({p, mu}, at);
        });
      },
      py::kw_only(), "p"_a, "mu"_a, "x"_a, "z"_a,
      doc("Frictional patch test, sliding in +x: sigma_x = 0, sigma_z = -p, tau_xz = -mu p.\n\n"
          "p: pressure [stress] > 0; mu: friction coefficient in [0, 10]; x, z: the point "
          "[length], z >= 0.",
          kPlaneReturns)
          .c_str());
}

}  // namespace

void bind_field_oracles(py::module_& m) {
  bind_hertzian_fields(m);
  bind_point_and_strip_fields(m);
  bind_patch_fields(m);
}

}  // namespace cs::python
