#pragma once
// The facts of a problem that the report reads from its record (schema/problem_record.hpp):
// the analyst's situation it stands for, and the length that normalizes its x and h. Each
// problem's descriptor (suites/problems/) must name both; results.json records them by name.
//
// Adding a value: add it to its enum and one `case` to its entry() (and to traits() for a
// length scale). -Werror=switch names every switch that must learn it.

#include <cstdint>
#include <string_view>

#include "schema/name_table.hpp"

namespace cs::schema {

/// The situation an analyst recognizes in a model, which the advice is given for: one per
/// family of problems (the patch tests split by how their nodes meet, Hertz, Steuermann, the
/// sharp punch, and the problems beyond the study: conformal fits and friction).
enum class Situation : std::uint8_t {
  matched_patch,                  ///< P: flat contact, nodes aligned
  mismatched_patch,               ///< P': flat contact, nodes not aligned, stiff indenter
  mismatched_patch_equal_moduli,  ///< P'(E1): nodes not aligned, bodies of one modulus
  smooth_curved,                  ///< H: smooth curved contact (Hertz)
  rounded_punch,                  ///< S: punch with rounded edges (Steuermann)
  flat_punch,                     ///< F: sharp punch edge, a stress singularity
  conformal_fit,                  ///< IF: conformal contact along an arc (interference fit)
  frictional,                     ///< FP, CM: Coulomb friction, stick and partial slip
};
constexpr std::string_view axis_name(Situation) {
  return "situation";
}
constexpr AxisEntry entry(Situation v) {
  switch (v) {
    case Situation::matched_patch:
      return {"matched_patch", "", "flat contact, nodes aligned"};
    case Situation::mismatched_patch:
      return {"mismatched_patch", "", "flat contact, nodes not aligned, stiff indenter"};
    case Situation::mismatched_patch_equal_moduli:
      return {"mismatched_patch_equal_moduli", "",
              "flat contact, nodes not aligned, bodies of one modulus"};
    case Situation::smooth_curved:
      return {"smooth_curved", "", "smooth curved contact (Hertz)"};
    case Situation::rounded_punch:
      return {"rounded_punch", "", "punch with rounded edges (Steuermann)"};
    case Situation::flat_punch:
      return {"flat_punch", "", "sharp punch edge (singular)"};
    case Situation::conformal_fit:
      return {"conformal_fit", "", "conformal contact (interference fit)"};
    case Situation::frictional:
      return {"frictional", "", "frictional contact"};
  }
  return {};
}

/// The length a problem's results are normalized by: x in the profiles and the element size h
/// (CaseResult::element_size_h) are over it.
enum class LengthScale : std::uint8_t {
  contact_half_width_a,  ///< a: the contact half-width (radius in axisymmetry)
  punch_half_width_b,    ///< b: the half-width of a punch's flat face (Steuermann)
  bore_radius_b,         ///< b: the radius of the bore (interference fits)
};
constexpr std::string_view axis_name(LengthScale) {
  return "length scale";
}
constexpr AxisEntry entry(LengthScale v) {
  switch (v) {
    case LengthScale::contact_half_width_a:
      return {"contact_half_width_a", "", "the contact half-width a"};
    case LengthScale::punch_half_width_b:
      return {"punch_half_width_b", "", "the punch half-width b"};
    case LengthScale::bore_radius_b:
      return {"bore_radius_b", "", "the bore radius b"};
  }
  return {};
}

/// The symbol of a length scale in formulas and axis titles: "a" in "x / a", "h / a".
constexpr std::string_view symbol(LengthScale v) {
  switch (v) {
    case LengthScale::contact_half_width_a:
      return "a";
    case LengthScale::punch_half_width_b:
    case LengthScale::bore_radius_b:
      return "b";
  }
  return "";
}

}  // namespace cs::schema
