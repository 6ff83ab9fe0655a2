// Prints every oracle's value at fixed arguments, computed in C++, as one JSON object per line:
//   {"function": NAME, "args": {...}, "contact": {"function": ..., "args": {...}} (optional),
//    "result": NUMBER or {FIELD: NUMBER, ...}}
// test_contact_suite.py calls the Python module's function of the same name with the same
// keyword arguments and compares the results bit for bit: the module must pass each argument to
// the right parameter and return each field under its name.

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "oracles/boussinesq.hpp"
#include "oracles/cattaneo_mindlin.hpp"
#include "oracles/flamant.hpp"
#include "oracles/flamant_tangential.hpp"
#include "oracles/flat_punch.hpp"
#include "oracles/frictional_patch_test.hpp"
#include "oracles/hertz_axi.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/hertz_tangential_traction.hpp"
#include "oracles/interference_fit.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/patch_test.hpp"
#include "oracles/steuermann.hpp"
#include "oracles/strip_load.hpp"

namespace {

using Json = nlohmann::json;
namespace o = cs::oracles;

void emit(const std::string& function, const Json& args, const Json& result,
          const Json& contact = nullptr) {
  Json line{{"function", function}, {"args", args}, {"result", result}};
  if (!contact.is_null())
    line["contact"] = contact;
  std::puts(line.dump(-1, ' ', false, Json::error_handler_t::strict).c_str());
}

Json plane(const o::PlaneStress& s) {
  return {{"sigma_x", s.sigma_x}, {"sigma_z", s.sigma_z}, {"tau_xz", s.tau_xz}};
}
Json axi(const o::AxiStress& s) {
  return {{"sigma_r", s.sigma_r},
          {"sigma_z", s.sigma_z},
          {"sigma_theta", s.sigma_theta},
          {"tau_rz", s.tau_rz}};
}

void hertz() {
  const Json args{{"R", 100.0}, {"E", 1000.0}, {"nu", 0.3}, {"P", 2.5}};
  const auto c = o::hertz_plane_contact({100.0, 1000.0, 0.3, 2.5});
  emit(
      "hertz_plane_contact", args,
      {{"contact_half_width_a", c.contact_half_width_a}, {"p_mean", c.p_mean}, {"p_max", c.p_max}});
  emit("hertz_plane_pressure", {{"x", 0.37 * c.contact_half_width_a}},
       o::hertz_plane_pressure(c, 0.37 * c.contact_half_width_a),
       {{"function", "hertz_plane_contact"}, {"args", args}});
  const auto a = o::hertz_axi_contact({50.0, 2000.0, 0.2, 3.0});
  const Json axi_args{{"R", 50.0}, {"E", 2000.0}, {"nu", 0.2}, {"P", 3.0}};
  emit("hertz_axi_contact", axi_args,
       {{"contact_radius_a", a.contact_radius_a}, {"p_mean", a.p_mean}, {"p_max", a.p_max}});
  emit("hertz_axi_pressure", {{"r", 0.61 * a.contact_radius_a}},
       o::hertz_axi_pressure(a, 0.61 * a.contact_radius_a),
       {{"function", "hertz_axi_contact"}, {"args", axi_args}});
}

void fields() {
  emit("mcewen_stress", {{"a", 1.5}, {"p", 2.0}, {"x", 0.7}, {"z", 0.9}},
       plane(o::mcewen_stress({1.5, 2.0}, {0.7, 0.9})));
  emit("hertz_tangential_traction_stress", {{"a", 1.5}, {"q0", -0.4}, {"x", -0.3}, {"z", 0.8}},
       plane(o::hertz_tangential_traction_stress({1.5, -0.4}, {-0.3, 0.8})));
  emit("strip_load_stress", {{"a", 2.0}, {"p", 3.0}, {"x", 1.1}, {"z", 0.4}},
       plane(o::strip_load_stress({2.0, 3.0}, {1.1, 0.4})));
  emit("flamant_stress", {{"P", 5.0}, {"x", 0.3}, {"z", 1.7}},
       plane(o::flamant_stress({5.0}, {0.3, 1.7})));
  emit("flamant_tangential_stress", {{"Q", 2.0}, {"x", -0.6}, {"z", 1.2}},
       plane(o::flamant_tangential_stress({2.0}, {-0.6, 1.2})));
  emit("boussinesq_stress", {{"P", 7.0}, {"nu", 0.3}, {"r", 0.5}, {"z", 1.3}},
       axi(o::boussinesq_stress({7.0, 0.3}, {0.5, 1.3})));
  emit("patch_test_plane_stress", {{"p", 2.5}, {"x", 0.1}, {"z", 0.2}},
       plane(o::patch_test_plane_stress({2.5}, {0.1, 0.2})));
  emit("patch_test_axi_stress", {{"p", 2.5}, {"r", 0.1}, {"z", 0.2}},
       axi(o::patch_test_axi_stress({2.5}, {0.1, 0.2})));
  emit("frictional_patch_stick_stress",
       {{"p", 2.0}, {"tau", 0.3}, {"mu", 0.2}, {"x", 1.0}, {"z", 0.5}},
       plane(o::frictional_patch_stick_stress({2.0, 0.3, 0.2}, {1.0, 0.5})));
  emit("frictional_patch_slip_stress", {{"p", 2.0}, {"mu", 0.3}, {"x", 1.0}, {"z", 0.5}},
       plane(o::frictional_patch_slip_stress({2.0, 0.3}, {1.0, 0.5})));
}

void punches() {
  emit("sadowsky_mean_pressure", {{"a", 1.5}, {"P", 4.0}}, o::sadowsky_mean_pressure({1.5, 4.0}));
  emit("sadowsky_pressure", {{"a", 1.5}, {"P", 4.0}, {"x", 0.4}},
       o::sadowsky_pressure({1.5, 4.0}, 0.4));
  emit("harding_sneddon_mean_pressure", {{"a", 1.5}, {"P", 4.0}},
       o::harding_sneddon_mean_pressure({1.5, 4.0}));
  emit("harding_sneddon_pressure", {{"a", 1.5}, {"P", 4.0}, {"r", 0.9}},
       o::harding_sneddon_pressure({1.5, 4.0}, 0.9));
}

void steuermann() {
  const o::SteuermannPunch punch{1.0,  1.0 / 3.0, 0.02,
                                 10.0, 0.25,      o::Eq32Factor::kWithoutOneMinusNu2};
  const Json args{{"b", 1.0},  {"r_e", 1.0 / 3.0}, {"P", 0.02},
                  {"E", 10.0}, {"nu", 0.25},       {"eq32_factor", "without"}};
  emit("steuermann_load_parameter", args, o::steuermann_load_parameter(punch));
  emit("steuermann_max_load",
       {{"b", 1.0}, {"r_e", 1.0 / 3.0}, {"E", 10.0}, {"nu", 0.25}, {"eq32_factor", "without"}},
       o::steuermann_max_load(punch));
  emit("steuermann_study_pressure", args, o::steuermann_study_pressure(punch));
  const auto c = o::steuermann_contact(punch);
  emit("steuermann_contact", args,
       {{"b", c.b},
        {"P", c.P},
        {"phi0", c.phi0},
        {"half_pi_minus_phi0", c.half_pi_minus_phi0},
        {"contact_half_width_a", c.contact_half_width_a}});
  const Json contact{{"function", "steuermann_contact"}, {"args", args}};
  emit("steuermann_pressure", {{"x", 1.01}}, o::steuermann_pressure(c, 1.01), contact);
  const auto peak = o::steuermann_peak(c);
  emit(
      "steuermann_peak", Json::object(),
      {{"peak_pressure", peak.peak_pressure}, {"x_peak", peak.x_peak}, {"phi_peak", peak.phi_peak}},
      contact);
  const auto s = o::steuermann_study_punch({1.0, 1.0 / 7.0, 1.0, 0.25, 1e-3});
  emit("steuermann_study_punch",
       {{"b", 1.0}, {"r_e", 1.0 / 7.0}, {"E", 1.0}, {"nu", 0.25}, {"p_over_E", 1e-3}},
       {{"b", s.b}, {"r_e", s.r_e}, {"P", s.P}, {"E", s.E}, {"nu", s.nu}});
}

void cattaneo_mindlin() {
  const Json args{{"R", 10.0}, {"E", 200.0}, {"nu", 0.3}, {"P", 1.5}, {"Q", 0.2}, {"mu", 0.3}};
  const auto c = o::cattaneo_mindlin_contact({10.0, 200.0, 0.3, 1.5, 0.2, 0.3});
  emit("cattaneo_mindlin_contact", args,
       {{"contact_half_width_a", c.contact_half_width_a},
        {"p0", c.p0},
        {"p_mean", c.p_mean},
        {"stick_half_width_c", c.stick_half_width_c},
        {"c_over_a", c.c_over_a},
        {"Q_over_mu_P", c.Q_over_mu_P},
        {"q_peak", c.q_peak},
        {"q_peak_over_p0", c.q_peak_over_p0},
        {"q_peak_over_p_mean", c.q_peak_over_p_mean},
        {"mu", c.mu}});
  const Json contact{{"function", "cattaneo_mindlin_contact"}, {"args", args}};
  const double x = 0.3 * c.contact_half_width_a;
  emit("cattaneo_mindlin_pressure", {{"x", x}}, o::cattaneo_mindlin_pressure(c, x), contact);
  emit("cattaneo_mindlin_shear", {{"x", x}}, o::cattaneo_mindlin_shear(c, x), contact);
}

void interference_fits() {
  const o::InterferenceFit fit{1.0, 2.5, 1e-3, {200.0, 0.3}, {70.0, 0.33}};
  const Json args{{"b", 1.0},        {"c", 2.5},        {"delta", 1e-3},   {"E_inner", 200.0},
                  {"nu_inner", 0.3}, {"E_outer", 70.0}, {"nu_outer", 0.33}};
  auto with = [&](Json extra) {
    Json a = args;
    a.update(extra);
    return a;
  };
  emit("interference_fit_cylinder_pressure", args, o::interference_fit_cylinder_pressure(fit));
  const auto cs = o::interference_fit_cylinder_state(fit, o::FitBody::kOuter, 1.7);
  emit("interference_fit_cylinder_state", with({{"body", "outer"}, {"r", 1.7}}),
       {{"sigma_r", cs.sigma_r},
        {"sigma_theta", cs.sigma_theta},
        {"sigma_z", cs.sigma_z},
        {"u_r", cs.u_r}});
  emit("interference_fit_cylinder_stress", with({{"body", "outer"}, {"x", 1.2}, {"z", 0.9}}),
       plane(o::interference_fit_cylinder_stress(fit, o::FitBody::kOuter, {1.2, 0.9})));
  emit("interference_fit_sphere_pressure", args, o::interference_fit_sphere_pressure(fit));
  const auto ss = o::interference_fit_sphere_state(fit, o::FitBody::kInner, 0.6);
  emit("interference_fit_sphere_state", with({{"body", "inner"}, {"R", 0.6}}),
       {{"sigma_r", ss.sigma_r}, {"sigma_theta", ss.sigma_theta}, {"u_r", ss.u_r}});
  emit("interference_fit_sphere_stress", with({{"body", "outer"}, {"r", 1.1}, {"z", 0.8}}),
       axi(o::interference_fit_sphere_stress(fit, o::FitBody::kOuter, {1.1, 0.8})));
}

}  // namespace

int main() {
  hertz();
  fields();
  punches();
  steuermann();
  cattaneo_mindlin();
  interference_fits();
  return 0;
}
