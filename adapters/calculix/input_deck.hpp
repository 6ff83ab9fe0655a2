#pragma once
// Writes a CalculiX input deck (.inp) for one contact analysis of the solver's plain data.
//
// Numbering: CalculiX node id = our node index + 1, element id = our element index + 1 (so
// results map back by subtracting 1; see ccx_node_id()).
//
// What is written, in order:
//   *NODE (x|r, z|y; CalculiX's y is our z; in axisymmetry nodes on the axis at a tiny r, see
//   CalculixOptions::axis_offset), *ELEMENT per body with TYPE=CPE4|CPE8 (plane
//   strain) or CAX4|CAX8 (axisymmetric) and ELSET=BODY<k+1> (our node order is CalculiX's:
//   corners counter-clockwise, then the mid-side nodes of sides 1-2, 2-3, 3-4, 4-1);
//   *MATERIAL MAT<k+1> with *ELASTIC E, nu and *SOLID SECTION per body (thickness 1);
//   *SURFACE SLAVE (the contact surface) and MASTER (the target's edge set) as element faces:
//   our local side s (corner s to corner s+1) is CalculiX's face S<s+1>;
//   *SURFACE INTERACTION with *SURFACE BEHAVIOR (CalculixOptions), *CONTACT PAIR SLAVE, MASTER;
//   *BOUNDARY: every prescribed DOF of the model, evaluated at its node (one line per node);
//   *STEP / *STATIC (one increment of the full load, CalculiX cuts it back if needed);
//   *CLOAD: the consistent nodal forces of the model's loads from the solver's own assembly
//   (solver/load_vector.hpp), at free DOFs only and above 1e-13 of the largest (round-off). In
//   axisymmetry our forces are per radian and CalculiX's are for the full circumference, so they
//   are multiplied by 2 pi; *NODE FILE U, RF, *EL FILE S, *CONTACT FILE CDIS, CSTR (ASCII .frd),
//   *END STEP.
//
// Every number is written in at most 20 characters (13 significant digits): ccx reads each
// field through its first 20 characters only. No text from the model (body or set names)
// reaches the deck except in comment lines, reduced to [A-Za-z0-9._-].

#include <ostream>
#include <string>

#include "adapters/calculix/calculix_options.hpp"
#include "solver/contact/contact_analysis.hpp"
#include "solver/model.hpp"

namespace cs::adapters::calculix {

/// CalculiX's id of our node index.
constexpr int ccx_node_id(int node) {
  return node + 1;
}
/// CalculiX's id of our element index.
constexpr int ccx_element_id(int element) {
  return element + 1;
}

/// CalculiX's face label of our local side s (0..3): "S1".."S4".
std::string ccx_face_label(int side);

/// The element type written for `model`: "CPE4", "CPE8", "CAX4" or "CAX8".
std::string ccx_element_type(const solver::Model& model);

/// The factor from our nodal forces to CalculiX's: 1 in plane strain (per unit thickness, and
/// the plane-strain elements have thickness 1), 2 pi in axisymmetry (per radian -> full
/// circumference).
double ccx_force_factor(const solver::Model& model);

/// Writes the deck. Validates the model (solver::ModelError) and the options (CalculixError);
/// throws UnsupportedByCalculix for a rigid analytic target and CalculixError for a contact or
/// target edge set that does not exist.
void write_input_deck(std::ostream& out, const solver::Model& model,
                      const solver::ContactPair& pair, const CalculixOptions& options);

/// The deck as a string (write_input_deck into a buffer).
std::string input_deck(const solver::Model& model, const solver::ContactPair& pair,
                       const CalculixOptions& options);

}  // namespace cs::adapters::calculix
