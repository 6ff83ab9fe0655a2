#include "oracles/flamant_tangential.hpp"

#include "oracles/flamant.hpp"
#include "oracles/invalid_input.hpp"

namespace cs::oracles {

PlaneStress flamant_tangential_stress(const FlamantTangentialLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "flamant_tangential_stress";
  require_finite(kWhere, "tangential load per unit length Q", load.Q);
  if (load.Q == 0.0)
    throw InvalidInput(std::string(kWhere) + ": tangential load Q must be non-zero (got 0)");
  return radial_line_load_stress(kWhere, load.Q, LineLoadDirection::tangential, at);
}

}  // namespace cs::oracles
