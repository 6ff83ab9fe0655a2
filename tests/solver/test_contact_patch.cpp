// Contact patch tests P and P' (the study's Problems P_p, P_a, P'_p, P'_a): a block pressed by a
// uniform pressure p onto a flat target must carry exactly p at every contact node.
//
// Requirement: Lagrange multipliers with matching nodes, and mortar with and without matching
// nodes, reproduce the uniform pressure to round-off (<= 1e-8 relative), in plane strain and in
// axisymmetry, with Q4 and Q8; penalty tends to the Lagrange multiplier answer as FKN grows.

#include <cstdio>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using contact_test::PatchSpec;
using cs::testing::Near;

struct PatchCase {
  ElementType type;
  AnalysisType analysis;
  int indenter_nx;  // 0: rigid plane; != nx: non-matching meshes
  ContactDiscretization discretization;
  ContactAlgorithm algorithm;
  bool loaded_indenter = false;  // the indenter pressed onto a supported block
};

std::string name(const ::testing::TestParamInfo<PatchCase>& info) {
  const PatchCase& c = info.param;
  return std::string(c.type == ElementType::Q4 ? "Q4" : "Q8") + "_" +
         (c.analysis == AnalysisType::PlaneStrain ? "plane" : "axi") + "_" +
         (c.indenter_nx == 0 ? std::string("rigid") : "meshed" + std::to_string(c.indenter_nx)) +
         "_" + to_string(c.discretization) + "_" + to_string(c.algorithm) +
         (c.loaded_indenter ? "_loaded_indenter" : "");
}

class ContactPatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(ContactPatchTest, UniformPressureExactly) {
  const PatchCase& c = GetParam();
  PatchSpec spec;
  spec.type = c.type;
  spec.analysis = c.analysis;
  spec.indenter_nx = c.indenter_nx;
  spec.loaded_indenter = c.loaded_indenter;
  const Model model = contact_test::patch_model(spec);
  const ContactResult r = solve_contact(model, contact_test::patch_pair(spec),
                                        contact_test::settings(c.discretization, c.algorithm));
  ASSERT_TRUE(r.converged()) << r.reason;
  const auto dev = contact_test::pressure_deviation(r, spec.p);
  EXPECT_EQ(dev.n_open, 0);
  // Round-off: the exact solution (uniform stress) lies in the discrete space.
  EXPECT_LE(dev.max_relative, 1e-8);
  std::printf("[ info     ] %s: max |p_node / p - 1| = %.2e, %d nodes\n", name({c, 0}).c_str(),
              dev.max_relative, static_cast<int>(r.nodes.size()));
  // Top of the block: u_z = -p h (1 - nu^2) / E (plane strain) or -p h / E (axisymmetric),
  // up to the target's compliance (E ratio 1e6) and the interface offset (zero for LM).
  const double strain = c.analysis == AnalysisType::PlaneStrain
                            ? spec.p * (1 - spec.nu * spec.nu) / spec.E
                            : spec.p / spec.E;
  const int top = model.mesh.node_sets.at("block.top").front();
  const int bottom = model.mesh.node_sets.at("block.bottom").front();
  const double shortening = r.displacement[2 * bottom + 1] - r.displacement[2 * top + 1];
  EXPECT_TRUE(Near(shortening, strain * spec.h, {1e-8, 0.0}));  // round-off
}

INSTANTIATE_TEST_SUITE_P(
    LagrangeMatching, ContactPatchTest,
    ::testing::Values(
        PatchCase{ElementType::Q4, AnalysisType::PlaneStrain, 0,
                  ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::PlaneStrain, 0,
                  ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q4, AnalysisType::Axisymmetric, 0,
                  ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::Axisymmetric, 0,
                  ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q4, AnalysisType::PlaneStrain, 4,
                  ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::Axisymmetric, 4,
                  ContactDiscretization::SurfaceToSurface, ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::PlaneStrain, 4,
                  ContactDiscretization::SurfaceToSurface, ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q4, AnalysisType::PlaneStrain, 4,
                  ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier,
                  true}),
    name);

INSTANTIATE_TEST_SUITE_P(
    MortarNonMatching, ContactPatchTest,
    ::testing::Values(
        PatchCase{ElementType::Q4, AnalysisType::PlaneStrain, 7, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::PlaneStrain, 7, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q4, AnalysisType::Axisymmetric, 7, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::Axisymmetric, 7, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q4, AnalysisType::PlaneStrain, 4, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::Axisymmetric, 0, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier},
        PatchCase{ElementType::Q8, AnalysisType::Axisymmetric, 7, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier, true},
        PatchCase{ElementType::Q4, AnalysisType::PlaneStrain, 7, ContactDiscretization::Mortar,
                  ContactAlgorithm::LagrangeMultiplier, true}),
    name);

TEST(ContactPatchNonMatching, OnlyMortarPassesBetweenElasticNonMatchingMeshes) {
  // The two-body contact patch test (Taylor & Papadopoulos): two equally stiff blocks, meshed
  // 10 and 9 elements across, pressed together. Node-to-surface and unsegmented Gauss-point
  // constraints do not transmit the uniform pressure exactly between non-matching meshes;
  // mortar does. (Against the study's stiff indenter, E ratio 1e6, the target barely deforms
  // and all three are exact to about 1 / E ratio.)
  PatchSpec spec;
  spec.nx = 10;
  spec.nz = 10;
  spec.indenter_nx = 9;
  spec.E_ratio = 1.0;
  const Model model = contact_test::patch_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::patch_pair(spec));
  double deviation[3] = {0, 0, 0};
  int k = 0;
  for (ContactDiscretization d :
       {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
        ContactDiscretization::Mortar}) {
    const ContactResult r =
        contact.solve(contact_test::settings(d, ContactAlgorithm::LagrangeMultiplier));
    ASSERT_TRUE(r.converged()) << r.reason;
    deviation[k++] = contact_test::pressure_deviation(r, spec.p).max_relative;
  }
  std::printf(
      "[ info     ] two-body patch, Q4 10 vs 9 elements, LM: max |p_node / p - 1| ns %.3g, "
      "ss %.3g, mortar %.2e\n",
      deviation[0], deviation[1], deviation[2]);
  EXPECT_GT(deviation[0], 1e-3);  // visibly not uniform
  EXPECT_GT(deviation[1], 1e-3);
  EXPECT_LE(deviation[2], 1e-8);  // round-off
}

}  // namespace
}  // namespace cs::solver
