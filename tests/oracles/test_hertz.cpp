// Hertz contact, plane strain (Eqs. 15-16) and axisymmetric (Eqs. 22-23), and the McEwen field
// on the surface: the printed relations, the study's normalized peaks 4/pi and 3/2, and the
// contact condition itself: the surface slope produced by the Hertz pressure (a Cauchy
// principal-value integral, GSL QAWC) equals the slope -x/R of the cylinder.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "oracles/hertz_axi.hpp"
#include "oracles/hertz_plane.hpp"
#include "oracles/mcewen.hpp"
#include "oracles/quadrature.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::oracles::test_hertz {
namespace {

using cs::testing::Near;
using std::numbers::pi;

// Closed forms evaluated two ways: a few roundings apart.
constexpr cs::testing::Tolerance kRounding{.rel = 1e-14};

TEST(HertzPlane, HalfWidthSatisfiesEq16WithTheMeanPressure) {
  for (const double nu : {0.0, 0.25, 0.49}) {
    const HertzCylinder cylinder{.R = 12.0, .E = 7e4, .nu = nu, .P = 35.0};
    const HertzPlaneContact c = hertz_plane_contact(cylinder);
    const double p = cylinder.P / (2.0 * c.contact_half_width_a);
    EXPECT_TRUE(Near(c.p_mean, p, kRounding));
    EXPECT_TRUE(Near(c.contact_half_width_a,
                     8.0 * cylinder.R * (1.0 - nu * nu) * p / (pi * cylinder.E), kRounding));
  }
}

TEST(HertzPlane, NormalizedPeakIsFourOverPi) {
  // The study's exact -sigma_z(0,0)/p = -sigma_x(0,0)/p = 1.2732 (Eq. 15).
  const HertzPlaneContact c = hertz_plane_contact({.R = 3.0, .E = 2e5, .nu = 0.3, .P = 10.0});
  EXPECT_TRUE(Near(c.p_max / c.p_mean, 4.0 / pi, kRounding));
  EXPECT_TRUE(Near(hertz_plane_pressure(c, 0.0) / c.p_mean, 4.0 / pi, kRounding));
  const PlaneStress at_centre =
      mcewen_stress({.a = c.contact_half_width_a, .p = c.p_mean}, {0.0, 0.0});
  EXPECT_TRUE(Near(-at_centre.sigma_z / c.p_mean, 4.0 / pi, kRounding));
  EXPECT_TRUE(Near(-at_centre.sigma_x / c.p_mean, 4.0 / pi, kRounding));
  EXPECT_NEAR(4.0 / pi, 1.2732, 0.5e-4);  // the study's printed value, to its 4 decimals
}

TEST(HertzPlane, PressureIsEllipticalAndVanishesOutside) {
  const HertzPlaneContact c{.contact_half_width_a = 2.0, .p_mean = 1.0, .p_max = 4.0 / pi};
  EXPECT_TRUE(Near(hertz_plane_pressure(c, 1.0), 4.0 / pi * std::sqrt(0.75), kRounding));
  EXPECT_TRUE(Near(hertz_plane_pressure(c, -1.0), 4.0 / pi * std::sqrt(0.75), kRounding));
  EXPECT_EQ(hertz_plane_pressure(c, 2.0), 0.0);
  EXPECT_EQ(hertz_plane_pressure(c, -2.5), 0.0);
}

TEST(HertzPlane, McEwenOnTheSurfaceIsEq15UnderTheContactAndFreeOutside) {
  const McEwenLoad load{.a = 0.7, .p = 3.0};
  const HertzPlaneContact c{.contact_half_width_a = 0.7, .p_mean = 3.0, .p_max = 12.0 / pi};
  for (const double x : {-0.69999, -0.5, -0.1, 0.0, 0.2, 0.6, 0.69}) {
    const PlaneStress s = mcewen_stress(load, {x, 0.0});
    const double eq15 = -4.0 * load.p / pi * std::sqrt(1.0 - (x / load.a) * (x / load.a));
    EXPECT_TRUE(Near(s.sigma_z, eq15, {.rel = 1e-12})) << x;
    EXPECT_TRUE(Near(s.sigma_x, eq15, {.rel = 1e-12})) << x;
    EXPECT_TRUE(Near(s.sigma_z, -hertz_plane_pressure(c, x), {.rel = 1e-12})) << x;
    EXPECT_EQ(s.tau_xz, 0.0) << x;
  }
  for (const double x : {-3.0, -0.70001, 0.7, 0.71, 2.0}) {
    const PlaneStress s = mcewen_stress(load, {x, 0.0});
    EXPECT_EQ(s.sigma_z, 0.0) << x;
    EXPECT_EQ(s.sigma_x, 0.0) << x;  // Hertz: the surface outside is stress free
    EXPECT_EQ(s.tau_xz, 0.0) << x;
  }
}

TEST(HertzPlane, PressureProducesTheCylinderProfile) {
  // Plane-strain surface slope under a pressure p(s) (Johnson Ch. 2):
  //   dw/dx = (2 (1 - nu^2) / (pi E)) PV int p(s) / (s - x) ds, w into the body;
  // frictionless contact with the cylinder (Eq. 14) requires dw/dx = -x / R on |x| < a.
  const HertzCylinder cylinder{.R = 5.0, .E = 1e3, .nu = 0.3, .P = 2.0};
  const HertzPlaneContact c = hertz_plane_contact(cylinder);
  const double a = c.contact_half_width_a;
  for (const double x_over_a : {-0.9, -0.4, 0.1, 0.5, 0.95}) {
    const double x = x_over_a * a;
    const auto pv =
        integrate_cauchy_principal_value([&](double s) { return hertz_plane_pressure(c, s); }, -a,
                                         a, x, {.abs = 1e-13 * c.p_max, .rel = 1e-11});
    const double slope = 2.0 * (1.0 - cylinder.nu * cylinder.nu) / (pi * cylinder.E) * pv.value;
    // Quadrature to 1e-11 next to the square-root ends: 1e-9 relative.
    EXPECT_TRUE(Near(slope, -x / cylinder.R, {.rel = 1e-9})) << "x/a = " << x_over_a;
  }
}

TEST(HertzAxi, RadiusSatisfiesEq23WithTheMeanPressure) {
  for (const double nu : {0.0, 0.25, 0.49}) {
    const HertzSphere sphere{.R = 12.0, .E = 7e4, .nu = nu, .P = 35.0};
    const HertzAxiContact c = hertz_axi_contact(sphere);
    const double a = c.contact_radius_a;
    const double p = sphere.P / (pi * a * a);
    EXPECT_TRUE(Near(c.p_mean, p, kRounding));
    EXPECT_TRUE(Near(a, 3.0 * pi * sphere.R * (1.0 - nu * nu) * p / (4.0 * sphere.E), kRounding));
  }
}

TEST(HertzAxi, NormalizedPeakIsThreeHalves) {
  const HertzAxiContact c = hertz_axi_contact({.R = 3.0, .E = 2e5, .nu = 0.3, .P = 10.0});
  EXPECT_TRUE(Near(c.p_max / c.p_mean, 1.5, kRounding));
  EXPECT_TRUE(Near(hertz_axi_pressure(c, 0.0) / c.p_mean, 1.5, kRounding));
  const double a = c.contact_radius_a;
  EXPECT_TRUE(Near(hertz_axi_pressure(c, 0.6 * a), 1.5 * c.p_mean * 0.8, kRounding));
  EXPECT_EQ(hertz_axi_pressure(c, a), 0.0);
  EXPECT_EQ(hertz_axi_pressure(c, 2.0 * a), 0.0);
}

}  // namespace
}  // namespace cs::oracles::test_hertz
