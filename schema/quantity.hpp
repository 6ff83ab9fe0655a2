#pragma once
// The graded quantities, normalized by p and positive in compression (docs/conventions.md).
// Where a quantity is sampled (the axis, the peak, the punch edge) is the problem's: see its
// descriptor in suites/problems/.

#include <cstdint>
#include <string_view>

#include "schema/name_table.hpp"

namespace cs::schema {

enum class Quantity : std::uint8_t {
  sigma_z_max,   ///< -sigma_z^max/p: the largest vertical stress on the surface (patch tests)
  sigma_c,       ///< -sigma_z/p at the contact centre (H) or its peak on z = 0 (S)
  sigma_h,       ///< -sigma_x(0,0)/p: the horizontal stress at the contact centre (H_p)
  sigma_c_star,  ///< -sigma_z(a,0)/p: the contact stress at a flat punch's edge (singular)
  tau_max,       ///< -tau_xz^max/p: the peak shear traction on the contact (friction problems)
  c_over_a,      ///< c/a: the stick zone's half-width over the contact's (Cattaneo-Mindlin)
  contact_half_width,  ///< the FE contact half-width over a (b for S), from the pressures
  p_mean,  ///< the mean contact pressure over the exact one (interference fits): resultant / exact
  p_arc,   ///< the nodal contact pressure over the exact one where it deviates most along the arc
};
constexpr std::string_view axis_name(Quantity) {
  return "quantity";
}
constexpr AxisEntry entry(Quantity v) {
  switch (v) {
    case Quantity::sigma_z_max:
      return {"sigma_z_max", "", "σ̄<sub>z</sub>"};
    case Quantity::sigma_c:
      return {"sigma_c", "", "σ̄<sub>c</sub>"};
    case Quantity::sigma_h:
      return {"sigma_h", "", "σ̄<sub>h</sub>"};
    case Quantity::sigma_c_star:
      return {"sigma_c_star", "", "σ̄<sub>c</sub><sup>*</sup>"};
    case Quantity::tau_max:
      return {"tau_max", "", "τ̄<sub>max</sub>"};
    case Quantity::c_over_a:
      return {"c_over_a", "", "c/a"};
    case Quantity::contact_half_width:
      return {"contact_half_width", "", "a<sub>FE</sub>"};
    case Quantity::p_mean:
      return {"p_mean", "", "p̄<sub>mean</sub>"};
    case Quantity::p_arc:
      return {"p_arc", "", "p̄<sub>arc</sub>"};
  }
  return {};
}

/// What a quantity is, in words, for the report's catalogue.
constexpr std::string_view description(Quantity v) {
  switch (v) {
    case Quantity::sigma_z_max:
      return "maximum vertical stress";
    case Quantity::sigma_c:
      return "contact stress";
    case Quantity::sigma_h:
      return "horizontal stress";
    case Quantity::sigma_c_star:
      return "contact stress at the punch edge";
    case Quantity::tau_max:
      return "peak shear traction";
    case Quantity::c_over_a:
      return "stick half-width";
    case Quantity::contact_half_width:
      return "contact half-width";
    case Quantity::p_mean:
      return "mean contact pressure";
    case Quantity::p_arc:
      return "largest deviation of the contact pressure along the arc";
  }
  return {};
}

/// True for a quantity read between two nodes: the contact half-width (halfway between the last
/// node carrying pressure and the next) and the stick zone's (between the last sticking node
/// and the first slipping one). Its resolution is half the node spacing
/// (grading::node_read_resolution_percent); the others are read at a point.
constexpr bool read_between_nodes(Quantity v) {
  switch (v) {
    case Quantity::contact_half_width:
    case Quantity::c_over_a:
      return true;
    case Quantity::sigma_z_max:
    case Quantity::sigma_c:
    case Quantity::sigma_h:
    case Quantity::sigma_c_star:
    case Quantity::tau_max:
    case Quantity::p_mean:
    case Quantity::p_arc:
      return false;
  }
  return false;
}

}  // namespace cs::schema
