#include "oracles/patch_test.hpp"

#include "oracles/invalid_input.hpp"

namespace cs::oracles {

PlaneStress patch_test_plane_stress(const PatchTestLoad& load, PlanePoint at) {
  constexpr const char* kWhere = "patch_test_plane_stress";
  require_positive(kWhere, "pressure p", load.p);
  require_finite(kWhere, "position x", at.x);
  require_in_half_space(kWhere, at.z);
  return {.sigma_x = 0.0, .sigma_z = -load.p, .tau_xz = 0.0};
}

AxiStress patch_test_axi_stress(const PatchTestLoad& load, AxiPoint at) {
  constexpr const char* kWhere = "patch_test_axi_stress";
  require_positive(kWhere, "pressure p", load.p);
  require_non_negative(kWhere, "radius r", at.r);
  require_in_half_space(kWhere, at.z);
  return {.sigma_r = 0.0, .sigma_z = -load.p, .sigma_theta = 0.0, .tau_rz = 0.0};
}

}  // namespace cs::oracles
