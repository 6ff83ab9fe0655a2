// The contact solutions (oracles/*): Hertz (plane, axisymmetric), the flat punches (Sadowsky,
// Harding-Sneddon), Steuermann's rounded punch, Cattaneo-Mindlin partial slip and the Lame
// interference fits. Parameters are keyword arguments named as in the study; a solved contact
// is an object with the C++ record's fields; pressures and tractions along the surface take a
// scalar or an array of positions.

#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "oracles/cattaneo_mindlin.hpp"
#include "oracles/flat_punch.hpp"
#include "oracles/hertz_axi.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/interference_fit.hpp"
#include "oracles/invalid_input.hpp"
#include "oracles/steuermann.hpp"
#include "python/bindings.hpp"

namespace cs::python {
namespace {

using namespace pybind11::literals;
namespace o = cs::oracles;

/// "with" / "without" (the command line's --eq32-factor values).
o::Eq32Factor eq32_factor(const std::string& text) {
  if (text == "with")
    return o::Eq32Factor::kWithOneMinusNu2;
  if (text == "without")
    return o::Eq32Factor::kWithoutOneMinusNu2;
  throw o::InvalidInput(fmt::format("--eq32-factor: expected 'with' or 'without', got '{}'", text));
}

/// "inner" / "outer".
o::FitBody fit_body(const std::string& text) {
  if (text == "inner")
    return o::FitBody::kInner;
  if (text == "outer")
    return o::FitBody::kOuter;
  throw o::InvalidInput(fmt::format("body: expected 'inner' or 'outer', got '{}'", text));
}

template <class T>
std::string repr_of(const char* name, const T& fields) {
  std::string out = std::string(name) + "(";
  bool first = true;
  for (const auto& [key, value] : fields) {
    out += fmt::format("{}{}={}", first ? "" : ", ", key, o::format_value(value));
    first = false;
  }
  return out + ")";
}

void bind_hertz(py::module_& m) {
  py::class_<o::HertzPlaneContact>(m, "HertzPlaneContact",
                                   "The Hertzian contact strip |x| < a (plane strain).")
      .def_readonly("contact_half_width_a", &o::HertzPlaneContact::contact_half_width_a,
                    "a [length]")
      .def_readonly("p_mean", &o::HertzPlaneContact::p_mean, "p = P/(2a) [stress]")
      .def_readonly("p_max", &o::HertzPlaneContact::p_max, "p0 = 4p/pi [stress], at x = 0")
      .def("__repr__", [](const o::HertzPlaneContact& c) {
        return repr_of("HertzPlaneContact", std::initializer_list<std::pair<const char*, double>>{
                                                {"contact_half_width_a", c.contact_half_width_a},
                                                {"p_mean", c.p_mean},
                                                {"p_max", c.p_max}});
      });
  m.def(
      "hertz_plane_contact",
      [](double R, double E, double nu, double P) {
        return o::hertz_plane_contact({R, E, nu, P});
      },
      py::kw_only(), "R"_a, "E"_a, "nu"_a, "P"_a,
      "Hertz, rigid cylinder on a half-space, plane strain (study Eq. 16): a^2 = 4 R (1 - nu^2) "
      "P / (pi E), p = P/(2a), p0 = 4p/pi.\n\nR: radius [length] > 0; E: Young's modulus "
      "[stress] > 0; nu: Poisson's ratio in [0, 0.5); P: load per unit length [force/length] "
      "> 0.");
  m.def(
      "hertz_plane_pressure",
      [](const o::HertzPlaneContact& c, const py::object& x) {
        return evaluate1(x, [&](double v) { return o::hertz_plane_pressure(c, v); });
      },
      "contact"_a, py::kw_only(), "x"_a,
      "Study Eq. 15: -sigma_z(x, 0) = (4p/pi) (1 - (x/a)^2)^(1/2) for |x| <= a, 0 outside "
      "[stress]. x: position(s) [length], scalar or array.");

  py::class_<o::HertzAxiContact>(m, "HertzAxiContact", "The Hertzian contact disc r < a.")
      .def_readonly("contact_radius_a", &o::HertzAxiContact::contact_radius_a, "a [length]")
      .def_readonly("p_mean", &o::HertzAxiContact::p_mean, "p = P/(pi a^2) [stress]")
      .def_readonly("p_max", &o::HertzAxiContact::p_max, "p0 = 3p/2 [stress], at r = 0");
  m.def(
      "hertz_axi_contact",
      [](double R, double E, double nu, double P) {
        return o::hertz_axi_contact({R, E, nu, P});
      },
      py::kw_only(), "R"_a, "E"_a, "nu"_a, "P"_a,
      "Hertz, rigid sphere on a half-space (study Eq. 23): a^3 = 3 R (1 - nu^2) P / (4E), "
      "p = P/(pi a^2), p0 = 3p/2.\n\nR: radius [length] > 0; E [stress] > 0; nu in [0, 0.5); "
      "P: total load [force] > 0.");
  m.def(
      "hertz_axi_pressure",
      [](const o::HertzAxiContact& c, const py::object& r) {
        return evaluate1(r, [&](double v) { return o::hertz_axi_pressure(c, v); });
      },
      "contact"_a, py::kw_only(), "r"_a,
      "Study Eq. 22: -sigma_z(r, 0) = (3p/2) (1 - (r/a)^2)^(1/2) for r <= a, 0 outside "
      "[stress]. r: radius(es) [length] >= 0, scalar or array.");
}

void bind_flat_punches(py::module_& m) {
  m.def(
      "sadowsky_mean_pressure",
      [](double a, double P) {
        return o::sadowsky_mean_pressure({a, P});
      },
      py::kw_only(), "a"_a, "P"_a,
      "The plane flat punch's p = P/(2a) [stress]. a: half-width [length] > 0; P: load per unit "
      "length [force/length] > 0.");
  m.def(
      "sadowsky_pressure",
      [](double a, double P, const py::object& x) {
        return evaluate1(x, [&](double v) { return o::sadowsky_pressure({a, P}, v); });
      },
      py::kw_only(), "a"_a, "P"_a, "x"_a,
      "Study Eq. 39 (Sadowsky): -sigma_z(x, 0) = P / (pi (a^2 - x^2)^(1/2)) for |x| < a, 0 for "
      "|x| > a [stress]; unbounded at |x| = a (ValueError). x: scalar or array [length].");
  m.def(
      "harding_sneddon_mean_pressure",
      [](double a, double P) {
        return o::harding_sneddon_mean_pressure({a, P});
      },
      py::kw_only(), "a"_a, "P"_a,
      "The circular flat punch's p = P/(pi a^2) [stress]. a: radius [length] > 0; P: total load "
      "[force] > 0.");
  m.def(
      "harding_sneddon_pressure",
      [](double a, double P, const py::object& r) {
        return evaluate1(r, [&](double v) { return o::harding_sneddon_pressure({a, P}, v); });
      },
      py::kw_only(), "a"_a, "P"_a, "r"_a,
      "Study Eq. 45 (Harding and Sneddon): -sigma_z(r, 0) = P / (2 pi a (a^2 - r^2)^(1/2)) for "
      "r < a, 0 for r > a [stress]; unbounded at r = a (ValueError). r: scalar or array.");
}

o::SteuermannPunch punch(double b, double r_e, double P, double E, double nu,
                         const std::string& factor) {
  return {b, r_e, P, E, nu, eq32_factor(factor)};
}

void bind_steuermann(py::module_& m) {
  py::class_<o::SteuermannContact>(m, "SteuermannContact",
                                   "Steuermann's solved contact: phi0 and a = b / sin(phi0).")
      .def_readonly("b", &o::SteuermannContact::b, "half-width of the flat face [length]")
      .def_readonly("P", &o::SteuermannContact::P, "load per unit length [force/length]")
      .def_readonly("phi0", &o::SteuermannContact::phi0, "the root of Eq. 32 [rad]")
      .def_readonly("half_pi_minus_phi0", &o::SteuermannContact::half_pi_minus_phi0,
                    "pi/2 - phi0 [rad], to full relative precision")
      .def_readonly("contact_half_width_a", &o::SteuermannContact::contact_half_width_a,
                    "a [length]");
  py::class_<o::SteuermannPeak>(m, "SteuermannPeak", "The peak of Steuermann's pressure.")
      .def_readonly("peak_pressure", &o::SteuermannPeak::peak_pressure, "max -sigma_z [stress]")
      .def_readonly("x_peak", &o::SteuermannPeak::x_peak, "where [length]")
      .def_readonly("phi_peak", &o::SteuermannPeak::phi_peak, "Eq. 31's angle there [rad]");
  const char* const params =
      "\n\nb: half-width of the flat face [length] > 0; r_e: edge radius [length] > 0; P: load "
      "per unit length [force/length] > 0; E [stress] > 0; nu in [0, 0.5); eq32_factor: 'with' "
      "(1 - nu^2) in Eq. 32, plane strain (default), or 'without' (the study's printed values).";
  m.def(
      "steuermann_load_parameter",
      [](double b, double r_e, double P, double E, double nu, const std::string& f) {
        return o::steuermann_load_parameter(punch(b, r_e, P, E, nu, f));
      },
      py::kw_only(), "b"_a, "r_e"_a, "P"_a, "E"_a, "nu"_a, "eq32_factor"_a = "with",
      (std::string("Eq. 32's left-hand side lambda = 2 r_e (1 - nu^2) P / (b^2 E) [-].") + params)
          .c_str());
  m.def(
      "steuermann_max_load",
      [](double b, double r_e, double E, double nu, const std::string& f) {
        return o::steuermann_max_load(punch(b, r_e, 1.0, E, nu, f));
      },
      py::kw_only(), "b"_a, "r_e"_a, "E"_a, "nu"_a, "eq32_factor"_a = "with",
      (std::string("The largest load [force/length] for which contact stays on the rounded "
                   "edges (a = b + r_e); inf beyond the largest double.") +
       params)
          .c_str());
  m.def(
      "steuermann_contact",
      [](double b, double r_e, double P, double E, double nu, const std::string& f) {
        return o::steuermann_contact(punch(b, r_e, P, E, nu, f));
      },
      py::kw_only(), "b"_a, "r_e"_a, "P"_a, "E"_a, "nu"_a, "eq32_factor"_a = "with",
      (std::string("Study Eq. 32: phi0 from lambda = (pi - 2 phi0)/(2 sin^2 phi0) - cot(phi0), "
                   "a = b / sin(phi0).") +
       params)
          .c_str());
  m.def(
      "steuermann_pressure",
      [](const o::SteuermannContact& c, const py::object& x) {
        return evaluate1(x, [&](double v) { return o::steuermann_pressure(c, v); });
      },
      "contact"_a, py::kw_only(), "x"_a,
      "Study Eq. 31: the contact pressure -sigma_z(x, 0) [stress] for |x| <= a, 0 beyond. x: "
      "scalar or array [length].");
  m.def("steuermann_peak", &o::steuermann_peak, "contact"_a,
        "The peak of Eq. 31 and where it is (b < x_peak < a).");
  m.def(
      "steuermann_study_punch",
      [](double b, double r_e, double E, double nu, double p_over_E, const std::string& f) {
        const o::SteuermannPunch s =
            o::steuermann_study_punch({b, r_e, E, nu, p_over_E, eq32_factor(f)});
        return py::dict("b"_a = s.b, "r_e"_a = s.r_e, "P"_a = s.P, "E"_a = s.E, "nu"_a = s.nu,
                        "eq32_factor"_a = f);
      },
      py::kw_only(), "b"_a, "r_e"_a, "E"_a, "nu"_a, "p_over_E"_a, "eq32_factor"_a = "with",
      "The study's loading: P = 2 (b + r_e) p, p = (p/E) E; returns the keyword arguments of "
      "steuermann_contact (b, r_e, P, E, nu, eq32_factor).");
  m.def(
      "steuermann_study_pressure",
      [](double b, double r_e, double P, double E, double nu, const std::string& f) {
        return o::steuermann_study_pressure(punch(b, r_e, P, E, nu, f));
      },
      py::kw_only(), "b"_a, "r_e"_a, "P"_a, "E"_a, "nu"_a, "eq32_factor"_a = "with",
      (std::string("The study's p = P / (2 (b + r_e)) [stress].") + params).c_str());
}

void bind_cattaneo_mindlin(py::module_& m) {
  using C = o::CattaneoMindlinContact;
  py::class_<C>(m, "CattaneoMindlinContact", "Cattaneo-Mindlin partial slip, plane strain.")
      .def_readonly("contact_half_width_a", &C::contact_half_width_a, "a [length]")
      .def_readonly("p0", &C::p0, "peak pressure 2P/(pi a) [stress]")
      .def_readonly("p_mean", &C::p_mean, "P/(2a) [stress]")
      .def_readonly("stick_half_width_c", &C::stick_half_width_c, "c = a (1 - Q/(mu P))^(1/2)")
      .def_readonly("c_over_a", &C::c_over_a, "c/a [-]")
      .def_readonly("Q_over_mu_P", &C::Q_over_mu_P, "Q/(mu P) [-]")
      .def_readonly("q_peak", &C::q_peak, "peak shear traction, at |x| = c [stress]")
      .def_readonly("q_peak_over_p0", &C::q_peak_over_p0, "(mu Q/P)^(1/2) [-]")
      .def_readonly("q_peak_over_p_mean", &C::q_peak_over_p_mean, "(4/pi) (mu Q/P)^(1/2) [-]")
      .def_readonly("mu", &C::mu, "friction coefficient [-]");
  m.def(
      "cattaneo_mindlin_contact",
      [](double R, double E, double nu, double P, double Q, double mu) {
        return o::cattaneo_mindlin_contact({R, E, nu, P, Q, mu});
      },
      py::kw_only(), "R"_a, "E"_a, "nu"_a, "P"_a, "Q"_a, "mu"_a,
      "Cattaneo-Mindlin (Johnson Eqs. 4.43-4.45, Sec. 7.1): a = (4PR/(pi E*))^(1/2), E* = "
      "E/(2(1 - nu^2)), c = a (1 - Q/(mu P))^(1/2).\n\nR: relative radius [length] > 0; E "
      "[stress] > 0; nu in [0, 0.5); P: normal load per unit length > 0; Q: tangential load, "
      "0 <= Q < mu P; mu in [0, 10].");
  m.def(
      "cattaneo_mindlin_pressure",
      [](const C& c, const py::object& x) {
        return evaluate1(x, [&](double v) { return o::cattaneo_mindlin_pressure(c, v); });
      },
      "contact"_a, py::kw_only(), "x"_a,
      "Hertz's pressure p0 (1 - x^2/a^2)^(1/2), 0 outside [stress]. x: scalar or array.");
  m.def(
      "cattaneo_mindlin_shear",
      [](const C& c, const py::object& x) {
        return evaluate1(x, [&](double v) { return o::cattaneo_mindlin_shear(c, v); });
      },
      "contact"_a, py::kw_only(), "x"_a,
      "The shear traction q(x) >= 0 on the lower body [stress]: mu p0 (1 - x^2/a^2)^(1/2) - mu p0 "
      "(c/a) (1 - x^2/c^2)^(1/2) in the stick zone, mu p(x) in the slip zones. x: scalar or "
      "array.");
}

o::InterferenceFit fit(double b, double c, double delta, double E_inner, double nu_inner,
                       double E_outer, double nu_outer) {
  return {b, c, delta, {E_inner, nu_inner}, {E_outer, nu_outer}};
}

void bind_interference_fits(py::module_& m) {
  const char* const params =
      "\n\nb: interface radius [length] > 0; c: outer radius [length] > b (inf: infinite); "
      "delta: radial interference [length], 0 < delta <= 1e-2 b; E_inner, nu_inner, E_outer, "
      "nu_outer: the two materials [stress], [-].";
  m.def(
      "interference_fit_cylinder_pressure",
      [](double b, double c, double delta, double Ei, double nui, double Eo, double nuo) {
        return o::interference_fit_cylinder_pressure(fit(b, c, delta, Ei, nui, Eo, nuo));
      },
      py::kw_only(), "b"_a, "c"_a, "delta"_a, "E_inner"_a, "nu_inner"_a, "E_outer"_a, "nu_outer"_a,
      (std::string("Shaft in a ring, plane strain (Lame): p = (delta/b) / [(1 + nu2)(1 + (1 - "
                   "2nu2) beta^2)/(E2 (1 - beta^2)) + (1 + nu1)(1 - 2nu1)/E1], beta = b/c "
                   "[stress].") +
       params)
          .c_str());
  m.def(
      "interference_fit_cylinder_state",
      [](double b, double c, double delta, double Ei, double nui, double Eo, double nuo,
         const std::string& body, const py::object& r) {
        const auto f = fit(b, c, delta, Ei, nui, Eo, nuo);
        const auto which = fit_body(body);
        const auto v = evaluate<1, 4>({r}, [&](const std::array<double, 1>& p) {
          const auto s = o::interference_fit_cylinder_state(f, which, p[0]);
          return std::array<double, 4>{s.sigma_r, s.sigma_theta, s.sigma_z, s.u_r};
        });
        return py::dict("sigma_r"_a = v[0], "sigma_theta"_a = v[1], "sigma_z"_a = v[2],
                        "u_r"_a = v[3]);
      },
      py::kw_only(), "b"_a, "c"_a, "delta"_a, "E_inner"_a, "nu_inner"_a, "E_outer"_a, "nu_outer"_a,
      "body"_a, "r"_a,
      (std::string("The plane-strain Lame state at radius r of body 'inner' (0 <= r <= b) or "
                   "'outer' (b <= r <= c): {'sigma_r', 'sigma_theta', 'sigma_z' [stress], 'u_r' "
                   "[length]}. r: scalar or array.") +
       params)
          .c_str());
  m.def(
      "interference_fit_cylinder_stress",
      [](double b, double c, double delta, double Ei, double nui, double Eo, double nuo,
         const std::string& body, const py::object& x, const py::object& z) {
        const auto f = fit(b, c, delta, Ei, nui, Eo, nuo);
        const auto which = fit_body(body);
        const auto v = evaluate<2, 3>({x, z}, [&](const std::array<double, 2>& p) {
          const auto s = o::interference_fit_cylinder_stress(f, which, {p[0], p[1]});
          return std::array<double, 3>{s.sigma_x, s.sigma_z, s.tau_xz};
        });
        return py::dict("sigma_x"_a = v[0], "sigma_z"_a = v[1], "tau_xz"_a = v[2]);
      },
      py::kw_only(), "b"_a, "c"_a, "delta"_a, "E_inner"_a, "nu_inner"_a, "E_outer"_a, "nu_outer"_a,
      "body"_a, "x"_a, "z"_a,
      (std::string("The cylinder fit's stress at (x, z) in Cartesian components: {'sigma_x', "
                   "'sigma_z', 'tau_xz'} [stress].") +
       params)
          .c_str());
  m.def(
      "interference_fit_sphere_pressure",
      [](double b, double c, double delta, double Ei, double nui, double Eo, double nuo) {
        return o::interference_fit_sphere_pressure(fit(b, c, delta, Ei, nui, Eo, nuo));
      },
      py::kw_only(), "b"_a, "c"_a, "delta"_a, "E_inner"_a, "nu_inner"_a, "E_outer"_a, "nu_outer"_a,
      (std::string("Sphere in a shell (Lame): p = (delta/b) / [((1 - 2nu2) beta^3 + (1 + nu2)/2)"
                   "/(E2 (1 - beta^3)) + (1 - 2nu1)/E1], beta = b/c [stress].") +
       params)
          .c_str());
  m.def(
      "interference_fit_sphere_state",
      [](double b, double c, double delta, double Ei, double nui, double Eo, double nuo,
         const std::string& body, const py::object& R) {
        const auto f = fit(b, c, delta, Ei, nui, Eo, nuo);
        const auto which = fit_body(body);
        const auto v = evaluate<1, 3>({R}, [&](const std::array<double, 1>& p) {
          const auto s = o::interference_fit_sphere_state(f, which, p[0]);
          return std::array<double, 3>{s.sigma_r, s.sigma_theta, s.u_r};
        });
        return py::dict("sigma_r"_a = v[0], "sigma_theta"_a = v[1], "u_r"_a = v[2]);
      },
      py::kw_only(), "b"_a, "c"_a, "delta"_a, "E_inner"_a, "nu_inner"_a, "E_outer"_a, "nu_outer"_a,
      "body"_a, "R"_a,
      (std::string("The spherical Lame state at radius R: {'sigma_r', 'sigma_theta' [stress], "
                   "'u_r' [length]}. R: scalar or array.") +
       params)
          .c_str());
  m.def(
      "interference_fit_sphere_stress",
      [](double b, double c, double delta, double Ei, double nui, double Eo, double nuo,
         const std::string& body, const py::object& r, const py::object& z) {
        const auto f = fit(b, c, delta, Ei, nui, Eo, nuo);
        const auto which = fit_body(body);
        const auto v = evaluate<2, 4>({r, z}, [&](const std::array<double, 2>& p) {
          const auto s = o::interference_fit_sphere_stress(f, which, {p[0], p[1]});
          return std::array<double, 4>{s.sigma_r, s.sigma_z, s.sigma_theta, s.tau_rz};
        });
        return py::dict("sigma_r"_a = v[0], "sigma_z"_a = v[1], "sigma_theta"_a = v[2],
                        "tau_rz"_a = v[3]);
      },
      py::kw_only(), "b"_a, "c"_a, "delta"_a, "E_inner"_a, "nu_inner"_a, "E_outer"_a, "nu_outer"_a,
      "body"_a, "r"_a, "z"_a,
      (std::string("The sphere fit's stress at (r, z) of the r-z model: {'sigma_r', 'sigma_z', "
                   "'sigma_theta', 'tau_rz'} [stress].") +
       params)
          .c_str());
}

}  // namespace

void bind_contact_oracles(py::module_& m) {
  bind_hertz(m);
  bind_flat_punches(m);
  bind_steuermann(m);
  bind_cattaneo_mindlin(m);
  bind_interference_fits(m);
}

}  // namespace cs::python
