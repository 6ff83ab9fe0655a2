// Plane-strain Hertz contact (the study's Problem H_p) on the medium mesh: a block loaded by
// McEwen's far-field tractions, held only by a cylinder.
//
// Requirement: with Lagrange multipliers and a rigid analytic cylinder the peak contact
// pressure is within 2% of Hertz's 4p/pi and the contact half-width within one element of a;
// a meshed stiff indenter (E ratio 1e6) gives the same answer as the rigid profile within 0.1%;
// penalty approaches the Lagrange multiplier answer as FKN grows.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "oracles/hertz_plane.hpp"
#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using contact_test::HertzSpec;
using cs::testing::Near;

class ContactHertzTest : public ::testing::TestWithParam<ContactDiscretization> {};

TEST_P(ContactHertzTest, LagrangePeakPressureAndHalfWidth) {
  const HertzSpec spec;
  const Model model = contact_test::hertz_model(spec);
  const ContactResult r =
      solve_contact(model, contact_test::hertz_pair(spec),
                    contact_test::settings(GetParam(), ContactAlgorithm::LagrangeMultiplier));
  ASSERT_TRUE(r.converged()) << r.reason;
  // The oracle: a from the load P = 2 a p (Eq. 16), peak 4p/pi (Eq. 15).
  const oracles::HertzPlaneContact exact =
      oracles::hertz_plane_contact({spec.R(), spec.E, spec.nu, 2.0 * spec.a * spec.p});
  const double h = 4.0 * spec.a / spec.n;
  std::printf(
      "[ info     ] H_p %s LM: peak %.5f (exact %.5f, error %.2f%%), extent %.4f "
      "(a = %.4f, h = %.4f), %d iterations\n",
      to_string(GetParam()), r.peak_pressure, exact.p_max,
      100.0 * (r.peak_pressure / exact.p_max - 1.0), r.contact_extent, exact.contact_half_width_a,
      h, r.active_set_iterations);
  EXPECT_TRUE(Near(r.peak_pressure, exact.p_max, {0.02, 0.0}));           // the 2%
  EXPECT_LE(std::abs(r.contact_extent - exact.contact_half_width_a), h);  // one element
}

INSTANTIATE_TEST_SUITE_P(AllDiscretizations, ContactHertzTest,
                         ::testing::Values(ContactDiscretization::NodeToSurface,
                                           ContactDiscretization::SurfaceToSurface,
                                           ContactDiscretization::Mortar),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace cs::solver

namespace cs::solver {
namespace {

struct TargetCase {
  ElementType type;
  ContactDiscretization discretization;
  ContactAlgorithm algorithm;
};

class ContactHertzTargetTest : public ::testing::TestWithParam<TargetCase> {};

/// The displacement of the block's far corner (4a, 4a) and the peak pressure: the answer.
struct HertzAnswer {
  double peak = 0.0;
  double w_far = 0.0;
  double extent = 0.0;
};

HertzAnswer hertz_answer(const HertzSpec& spec, const TargetCase& c) {
  const Model model = contact_test::hertz_model(spec);
  const ContactResult r = solve_contact(model, contact_test::hertz_pair(spec),
                                        contact_test::settings(c.discretization, c.algorithm));
  EXPECT_TRUE(r.converged()) << r.reason;
  const int far = model.mesh.node_sets.at("block.top").back();
  return {r.peak_pressure, r.displacement.size() ? r.displacement[2 * far + 1] : 0.0,
          r.contact_extent};
}

TEST_P(ContactHertzTargetTest, RigidAndMeshedTargetsAgree) {
  HertzSpec spec;
  spec.type = GetParam().type;
  spec.n = 16;
  const HertzAnswer rigid = hertz_answer(spec, GetParam());
  spec.meshed_indenter = true;
  const HertzAnswer meshed = hertz_answer(spec, GetParam());
  std::printf(
      "[ info     ] H_p rigid vs meshed (E ratio 1e6), %s %s %s: peak %.6f vs %.6f "
      "(%.2e), far w %.6e vs %.6e (%.2e)\n",
      GetParam().type == ElementType::Q4 ? "Q4" : "Q8", to_string(GetParam().discretization),
      to_string(GetParam().algorithm), rigid.peak, meshed.peak, meshed.peak / rigid.peak - 1.0,
      rigid.w_far, meshed.w_far, meshed.w_far / rigid.w_far - 1.0);
  EXPECT_TRUE(Near(meshed.peak, rigid.peak, {1e-3, 0.0}));  // the 0.1%
  EXPECT_EQ(meshed.extent, rigid.extent);
  // The meshed Q4 cylinder is a polygon: between its nodes it lies closer to the block than the
  // circle by up to the chord sag h^2 / (8R), which shifts the floating block rigidly by about
  // that much where the gap is sampled between nodes (Gauss points, mortar); Q8 sides follow
  // the circle to O(h^3).
  const double h = 4.0 * spec.a / spec.n;
  const double sag = spec.type == ElementType::Q4 ? h * h / (8.0 * spec.R()) : 0.0;
  EXPECT_TRUE(Near(meshed.w_far, rigid.w_far, {1e-3, sag}));
}

INSTANTIATE_TEST_SUITE_P(
    Targets, ContactHertzTargetTest,
    ::testing::Values(TargetCase{ElementType::Q4, ContactDiscretization::NodeToSurface,
                                 ContactAlgorithm::LagrangeMultiplier},
                      TargetCase{ElementType::Q8, ContactDiscretization::NodeToSurface,
                                 ContactAlgorithm::LagrangeMultiplier},
                      TargetCase{ElementType::Q4, ContactDiscretization::SurfaceToSurface,
                                 ContactAlgorithm::AugmentedLagrangian},
                      TargetCase{ElementType::Q8, ContactDiscretization::SurfaceToSurface,
                                 ContactAlgorithm::Penalty},
                      TargetCase{ElementType::Q4, ContactDiscretization::Mortar,
                                 ContactAlgorithm::LagrangeMultiplier},
                      TargetCase{ElementType::Q8, ContactDiscretization::Mortar,
                                 ContactAlgorithm::LagrangeMultiplier}),
    [](const auto& info) {
      return std::string(info.param.type == ElementType::Q4 ? "Q4_" : "Q8_") +
             to_string(info.param.discretization) + "_" + to_string(info.param.algorithm);
    });

}  // namespace
}  // namespace cs::solver
