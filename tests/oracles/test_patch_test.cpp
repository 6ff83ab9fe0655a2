// The patch tests' exact uniform stress (Eqs. 6 and 8).

#include <gtest/gtest.h>

#include "oracles/patch_test.hpp"

namespace cs::oracles {
namespace {

TEST(PatchTest, PlaneStrainStressIsUniformCompression) {
  for (const PlanePoint at : {PlanePoint{0.0, 0.0}, PlanePoint{0.7, 0.3}, PlanePoint{1.0, 2.0}}) {
    const PlaneStress s = patch_test_plane_stress({.p = 2.5}, at);
    EXPECT_EQ(s.sigma_z, -2.5);
    EXPECT_EQ(s.sigma_x, 0.0);
    EXPECT_EQ(s.tau_xz, 0.0);
  }
}

TEST(PatchTest, AxisymmetricStressIsUniaxialCompression) {
  for (const AxiPoint at : {AxiPoint{0.0, 0.0}, AxiPoint{0.7, 0.3}, AxiPoint{1.0, 2.0}}) {
    const AxiStress s = patch_test_axi_stress({.p = 2.5}, at);
    EXPECT_EQ(s.sigma_z, -2.5);
    EXPECT_EQ(s.sigma_r, 0.0);
    EXPECT_EQ(s.sigma_theta, 0.0);
    EXPECT_EQ(s.tau_rz, 0.0);
  }
}

}  // namespace
}  // namespace cs::oracles
