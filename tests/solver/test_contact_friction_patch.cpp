// Frictional contact patch tests: two bodies of the same material with a flat interface, loaded
// in two load cases, the uniform pressure p first and then a shear (see FrictionPatchSpec in
// test_contact_support.hpp: the exact solution is a uniform stress, linear displacements).
//
// Requirements:
//   - stick (the shear tau = 0.5 mu p by tractions, the block held in x by friction alone): every
//     method transmits tau and p exactly (1e-8, equilibrium of a uniform state) and every point
//     sticks; PLM has no slip increment (1e-8 of the block's shear displacement); the penalty
//     tangents (PM, LMP) slip elastically by exactly tau h / (FKT FKN E); AL by <= FTOLT h;
//   - slip (a sliding support drives the block's top to 1.2 x the displacement that transmits
//     mu p, after a stick step at 0.6 x, then back to -1.2 x): every point slips and the shear
//     is mu p, then -mu p, exactly (1e-8) for every method, with the slips the kinematics
//     demand; in the stick step PLM transmits 0.6 mu p exactly with no slip;
//   - LMP and PLM are different methods: on the same stick case their blocks differ by exactly
//     LMP's elastic slip.
// ns and ss with matching meshes, mortar also between non-matching meshes (7 vs 10 elements).

#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using contact_test::FrictionLoad;
using contact_test::FrictionPatchSpec;
using cs::testing::Near;

/// PM, AL, LMP, PLM.
enum class Method { PM, AL, LMP, PLM };

const char* name_of(Method m) {
  switch (m) {
    case Method::PM:
      return "PM";
    case Method::AL:
      return "AL";
    case Method::LMP:
      return "LMP";
    case Method::PLM:
      return "PLM";
  }
  return "?";
}

ContactSettings method_settings(ContactDiscretization d, Method m, double mu) {
  switch (m) {
    case Method::PM:
      return contact_test::friction_settings(d, ContactAlgorithm::Penalty, mu);
    case Method::AL:
      return contact_test::friction_settings(d, ContactAlgorithm::AugmentedLagrangian, mu);
    case Method::LMP:
      return contact_test::friction_settings(d, ContactAlgorithm::LagrangeMultiplier, mu);
    case Method::PLM:
      break;
  }
  return contact_test::friction_settings(d, ContactAlgorithm::LagrangeMultiplier, mu,
                                         TangentialEnforcement::LagrangeMultiplier);
}

struct FrictionPatchCase {
  ElementType type;
  ContactDiscretization discretization;
  Method method;
  int base_nx;  // 4: matching the block's 4 elements; 7: non-matching
};

std::string case_name(const ::testing::TestParamInfo<FrictionPatchCase>& info) {
  const FrictionPatchCase& c = info.param;
  return std::string(c.type == ElementType::Q4 ? "Q4" : "Q8") + "_" + to_string(c.discretization) +
         "_" + name_of(c.method) + (c.base_nx == 4 ? "" : "_base" + std::to_string(c.base_nx));
}

constexpr double kMu = 0.3;
constexpr double kP = 1.0;

class FrictionPatchTest : public ::testing::TestWithParam<FrictionPatchCase> {
 protected:
  FrictionPatchSpec spec() const {
    FrictionPatchSpec s;
    s.type = GetParam().type;
    s.base_nx = GetParam().base_nx;
    return s;
  }
  ContactSettings settings() const {
    return method_settings(GetParam().discretization, GetParam().method, kMu);
  }
  bool exact_stick() const { return GetParam().method == Method::PLM; }
  bool penalty_tangent() const {
    return GetParam().method == Method::PM || GetParam().method == Method::LMP;
  }
};

/// Every node closed, pressure p and shear `shear` to round-off (1e-8 of p).
void expect_uniform(const ContactResult& r, double shear, FrictionState state, const char* step) {
  ASSERT_TRUE(r.converged()) << step << ": " << r.reason;
  for (const ContactNodeResult& n : r.nodes) {
    EXPECT_TRUE(n.closed) << step << " x = " << n.position.x();
    EXPECT_TRUE(Near(n.pressure, kP, {0.0, 1e-8 * kP})) << step << " x = " << n.position.x();
    EXPECT_TRUE(Near(n.shear, shear, {0.0, 1e-8 * kP})) << step << " x = " << n.position.x();
    EXPECT_EQ(n.friction, state) << step << " x = " << n.position.x();
  }
}

double max_abs_slip_increment(const ContactResult& r) {
  double s = 0.0;
  for (const ContactNodeResult& n : r.nodes)
    s = std::max(s, std::abs(n.slip_increment));
  return s;
}

TEST_P(FrictionPatchTest, StickTransmitsTheShearExactly) {
  const FrictionPatchSpec s = spec();
  auto load = std::make_shared<FrictionLoad>();
  const Model model = contact_test::friction_patch_model(s, load);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::friction_patch_pair());
  const double tau = 0.5 * kMu * kP;
  const std::vector<LoadStep> steps{
      {"normal", [&] { load->p = kP; }},
      {"shear", [&] { load->tau_top = load->tau_sides = tau; }},
  };
  const ContactSettings cs = settings();
  const std::vector<ContactResult> path = contact.solve_steps(cs, steps);
  ASSERT_EQ(path.size(), 2u) << path.back().reason;
  expect_uniform(path[0], 0.0, FrictionState::Stick, "normal");
  expect_uniform(path[1], tau, FrictionState::Stick, "shear");
  // The slip increment of the shear step: none with PLM (round-off of the block's shear
  // displacement tau 2h / G); the penalty compliance tau h_e / (FKT FKN E) with PM and LMP
  // (h_e = h / nz the block's element depth); AL below FTOLT h_e.
  const double h_e = s.h / s.nz;
  const double slip = max_abs_slip_increment(path[1]);
  const double shear_displacement = tau * 2.0 * s.h / s.shear_modulus();
  if (exact_stick()) {
    EXPECT_LE(slip, 1e-8 * shear_displacement);
  } else if (penalty_tangent()) {
    EXPECT_TRUE(Near(slip, tau * h_e / (cs.fkt * cs.fkn * s.E), {1e-8, 0.0}));  // round-off
  } else {
    EXPECT_LE(slip, cs.ftolt * h_e);
    EXPECT_GE(path[1].augmentations, 1);  // PM's slip (1.5e-4 h_e) is above FTOLT
  }
  std::printf(
      "[ info     ] %s: shear step slip %.3e (block shear displacement %.3e), %d + %d "
      "iterations, %d augmentations\n",
      case_name({GetParam(), 0}).c_str(), slip, shear_displacement, path[0].active_set_iterations,
      path[1].active_set_iterations, path[1].augmentations);
}

TEST_P(FrictionPatchTest, SlidingSupportSlipsEverywhereAtMuP) {
  FrictionPatchSpec s = spec();
  s.sliding_support = true;
  auto load = std::make_shared<FrictionLoad>();
  const Model model = contact_test::friction_patch_model(s, load);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::friction_patch_pair());
  // U_mu: the top displacement that transmits mu p through both bodies (2h of shear strain).
  const double U_mu = kMu * kP * 2.0 * s.h / s.shear_modulus();
  const std::vector<LoadStep> steps{
      {"normal", [&] { load->p = kP; }},
      {"stick 0.6",
       [&] {
         load->top_ux = 0.6 * U_mu;
         load->tau_sides = 0.6 * kMu * kP;
       }},
      {"slip 1.2",
       [&] {
         load->top_ux = 1.2 * U_mu;
         load->tau_sides = kMu * kP;
       }},
      {"back to -1.2",
       [&] {
         load->top_ux = -1.2 * U_mu;
         load->tau_sides = -kMu * kP;
       }},
  };
  const std::vector<ContactResult> path = contact.solve_steps(settings(), steps);
  ASSERT_EQ(path.size(), 4u) << path.back().reason;
  expect_uniform(path[0], 0.0, FrictionState::Stick, "normal");
  if (exact_stick()) {  // penalty tangents transmit less than 0.6 mu p: their compliance
    expect_uniform(path[1], 0.6 * kMu * kP, FrictionState::Stick, "stick 0.6");
    EXPECT_LE(max_abs_slip_increment(path[1]), 1e-8 * U_mu);
  }
  expect_uniform(path[2], kMu * kP, FrictionState::Slip, "slip 1.2");
  // Kinematics of the slipping state: the total slip is U - U_mu = 0.2 U_mu at every node.
  for (const ContactNodeResult& n : path[2].nodes) {
    EXPECT_TRUE(Near(n.slip, 0.2 * U_mu, {1e-8, 0.0})) << "x = " << n.position.x();
    EXPECT_GT(n.slip_increment, 0.0);  // along +t, the sign of the shear
  }
  // Reversed: the block slides back, shear -mu p, total slip -0.2 U_mu (an increment of
  // -0.4 U_mu from the slipping state: the history carries the sign).
  expect_uniform(path[3], -kMu * kP, FrictionState::Slip, "back to -1.2");
  for (const ContactNodeResult& n : path[3].nodes) {
    EXPECT_TRUE(Near(n.slip, -0.2 * U_mu, {1e-8, 0.0})) << "x = " << n.position.x();
    EXPECT_TRUE(Near(n.slip_increment, -0.4 * U_mu, {1e-8, 0.0})) << "x = " << n.position.x();
  }
  std::printf("[ info     ] %s: slip step %d iterations, peak shear / (mu p) - 1 = %.1e\n",
              case_name({GetParam(), 0}).c_str(), path[2].active_set_iterations,
              path[2].peak_shear / (kMu * kP) - 1.0);
}

std::vector<FrictionPatchCase> all_cases() {
  std::vector<FrictionPatchCase> cases;
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    for (ContactDiscretization d :
         {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
          ContactDiscretization::Mortar}) {
      for (Method m : {Method::PM, Method::AL, Method::LMP, Method::PLM})
        cases.push_back({type, d, m, 4});
    }
    for (Method m : {Method::PM, Method::AL, Method::LMP, Method::PLM})
      cases.push_back({type, ContactDiscretization::Mortar, m, 7});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllMethods, FrictionPatchTest, ::testing::ValuesIn(all_cases()),
                         case_name);

TEST(FrictionPatchLmpPlm, LmpAndPlmAreDifferentMethods) {
  // The same stick case with LMP (penalty tangent) and PLM (exact stick), one analysis: the
  // block of LMP has moved by its elastic slip tau h_e / (FKT FKN E) relative to PLM's, which
  // has not slipped at all.
  const FrictionPatchSpec s;
  auto load = std::make_shared<FrictionLoad>();
  const Model model = contact_test::friction_patch_model(s, load);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::friction_patch_pair());
  const double tau = 0.5 * kMu * kP;
  const std::vector<LoadStep> steps{
      {"normal",
       [&] {
         load->p = kP;
         load->tau_top = load->tau_sides = 0.0;
       }},
      {"shear", [&] { load->tau_top = load->tau_sides = tau; }},
  };
  const ContactDiscretization d = ContactDiscretization::Mortar;
  const ContactResult lmp = contact.solve_steps(method_settings(d, Method::LMP, kMu), steps).back();
  const ContactResult plm = contact.solve_steps(method_settings(d, Method::PLM, kMu), steps).back();
  ASSERT_TRUE(lmp.converged()) << lmp.reason;
  ASSERT_TRUE(plm.converged()) << plm.reason;
  const double elastic_slip = tau * (s.h / s.nz) / s.E;  // FKT = FKN = 1
  const int top = model.mesh.node_sets.at("block.top").front();
  const double shift = lmp.displacement[2 * top] - plm.displacement[2 * top];
  EXPECT_TRUE(Near(shift, elastic_slip, {1e-8, 0.0}));  // round-off
  EXPECT_LE(max_abs_slip_increment(plm), 1e-8 * elastic_slip);
  std::printf("[ info     ] LMP - PLM block shift %.6e (elastic slip %.6e); PLM slip %.1e\n", shift,
              elastic_slip, max_abs_slip_increment(plm));
}

TEST(FrictionPatchRigid, RigidPlaneTargetUsesItsTangent) {
  // A block (nu = 0: no lateral expansion to resist) on a rigid plane: the slip is the block's
  // tangential displacement along the plane's tangent (+x); PLM transmits the shear with none.
  contact_test::PatchSpec spec;
  spec.nu = 0.0;
  Model model = contact_test::patch_model(spec);
  model.prescribed.clear();  // no symmetry support: the block is held in x by friction alone
  const double tau = 0.2;
  model.loads.add_traction("block.top", constant_field(Eigen::Vector2d(tau, 0.0)));
  model.loads.add_traction("block.left", constant_field(Eigen::Vector2d(0.0, -tau)));
  model.loads.add_traction("block.right", constant_field(Eigen::Vector2d(0.0, tau)));
  for (ContactDiscretization d :
       {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
        ContactDiscretization::Mortar}) {
    const ContactResult r =
        solve_contact(model, contact_test::patch_pair(spec),
                      method_settings(d, Method::PLM, 0.5));  // tau = 0.4 mu p: stick
    ASSERT_TRUE(r.converged()) << r.reason;
    for (const ContactNodeResult& n : r.nodes) {
      EXPECT_TRUE(Near(n.shear, tau, {0.0, 1e-8}));  // round-off
      EXPECT_LE(std::abs(n.slip), 1e-8 * tau * spec.h / (0.5 * spec.E));
      EXPECT_EQ(n.friction, FrictionState::Stick);
    }
    // The block's top moved by the shear strain only: u_x(top) = tau h / G (G = E / 2).
    const int top = model.mesh.node_sets.at("block.top").front();
    EXPECT_TRUE(Near(r.displacement[2 * top], tau * spec.h / (0.5 * spec.E), {1e-8, 0.0}));
  }
}

}  // namespace
}  // namespace cs::solver
