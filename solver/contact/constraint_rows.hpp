#pragma once
// Which constraint rows a contact analysis uses: what the condensation and the friction history
// of a step depend on (see solver/contact/contact_analysis.hpp).

namespace cs::solver {

/// The constraint rows a discretization and algorithm use (what the condensation depends on).
enum class ConstraintRows {
  NodeToSurface,      ///< ns, every algorithm
  GaussPoints,        ///< ss with PM / AL
  NodalWeightedGaps,  ///< ss with LM / MPC
  Mortar,             ///< mortar, every algorithm
};

/// "ns", "ss Gauss points", "ss nodal weighted gaps", "mortar".
constexpr const char* to_string(ConstraintRows rows) {
  switch (rows) {
    case ConstraintRows::NodeToSurface:
      return "ns";
    case ConstraintRows::GaussPoints:
      return "ss Gauss points";
    case ConstraintRows::NodalWeightedGaps:
      return "ss nodal weighted gaps";
    case ConstraintRows::Mortar:
      return "mortar";
  }
  return "unknown";
}

}  // namespace cs::solver
