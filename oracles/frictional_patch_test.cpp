#include "oracles/frictional_patch_test.hpp"

#include "oracles/invalid_input.hpp"

namespace cs::oracles {

PlaneStress frictional_patch_stick_stress(const FrictionalPatchStick& load, PlanePoint at) {
  constexpr const char* kWhere = "frictional_patch_stick_stress";
  require_positive(kWhere, "pressure p", load.p);
  require_friction_coefficient(kWhere, load.mu);
  require_non_negative(kWhere, "shear traction tau", load.tau);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);
  const double mu_p = load.mu * load.p;
  if (!(load.tau < mu_p)) {
    throw InvalidInput(std::string(kWhere) +
                       ": Q >= mu P: the stick oracle needs Q < mu P (got tau = " +
                       format_value(load.tau) + ", mu p = " + format_value(mu_p) + ")");
  }
  return {.sigma_x = 0.0, .sigma_z = -load.p, .tau_xz = -load.tau};
}

PlaneStress frictional_patch_slip_stress(const FrictionalPatchSlip& load, PlanePoint at) {
  constexpr const char* kWhere = "frictional_patch_slip_stress";
  require_positive(kWhere, "pressure p", load.p);
  require_friction_coefficient(kWhere, load.mu);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);
  return {.sigma_x = 0.0, .sigma_z = -load.p, .tau_xz = -load.mu * load.p};
}

}  // namespace cs::oracles
