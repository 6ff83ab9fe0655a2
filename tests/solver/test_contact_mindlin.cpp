// Cattaneo-Mindlin in plane strain (Johnson, Contact Mechanics, Sec. 7.1): a cylinder of
// radius R pressed onto a block of the same material by the normal load P, then sheared by the
// tangential load Q = 0.5 mu P in two increments (MindlinSpec in test_contact_support.hpp). For
// elastically similar bodies the normal and tangential problems uncouple: the pressure is
// Hertz's, and the contact sticks over |x| < c with
//
//   c = a sqrt(1 - Q / (mu P)),
//
// slipping (shear = mu p) over c < |x| < a. The bodies are finite (8a wide, 4a deep, the
// tractions of a uniform stress state on their far faces), so a is taken from the computed
// normal step (a_FE, compared with Hertz's two-body a in the output) and c is expected at
// a_FE sqrt(1 - Q / (mu P)).
//
// Requirements, every discretization and PM, AL, LMP, PLM, Q4 and Q8, h = a / 8:
//   - every step converges;
//   - the stick half-width is within 2 elements of a_FE sqrt(1 - Q / (mu P)) (the stick-slip
//     boundary lies between two nodes: one element is the resolution, 2 leaves the finite
//     bodies' small deviation from the half-space room), and the stick zone is centred to
//     within one element (the model is symmetric about x = 0);
//   - slipping nodes carry shear = mu p exactly (1e-8) in the direction of their slip
//     increment; sticking nodes |shear| <= mu p;
//   - the shear transmitted adds up to Q (1e-3: the target's tangent turns by at most a / R =
//     0.01 inside the contact, so the normal forces carry an x component of that order).
// The output reports c, the peak shear against the exact mu p0 sqrt(1 - c^2 / a^2), the
// iterations and the time per step. (The block is held in x by friction alone, so this model
// has no frictionless solution to time against: FrictionTiming below uses H_p.)

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_contact_mindlin {
namespace {

using contact_test::FrictionLoad;
using contact_test::MindlinSpec;
using cs::testing::Near;
using Clock = std::chrono::steady_clock;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMu = 0.3;
constexpr double kQOverMuP = 0.5;

struct MindlinCase {
  ElementType type;
  ContactDiscretization discretization;
  ContactAlgorithm algorithm;
  TangentialEnforcement tangential;
};

std::string method_name(const MindlinCase& c) {
  switch (c.algorithm) {
    case ContactAlgorithm::Penalty:
      return "PM";
    case ContactAlgorithm::AugmentedLagrangian:
      return "AL";
    default:
      return c.tangential == TangentialEnforcement::Penalty ? "LMP" : "PLM";
  }
}

std::string case_name(const ::testing::TestParamInfo<MindlinCase>& info) {
  const MindlinCase& c = info.param;
  return std::string(c.type == ElementType::Q4 ? "Q4" : "Q8") + "_" + to_string(c.discretization) +
         "_" + method_name(c);
}

/// Half-widths of a zone of nodes (sorted by x): from the midpoints between its outermost
/// nodes and their outside neighbours. Also its centre.
struct Zone {
  double half_width = 0.0;
  double centre = 0.0;
};

template <class InZone>
Zone zone_of(const std::vector<ContactNodeResult>& nodes, InZone in_zone) {
  int first = -1, last = -1;
  for (int i = 0; i < static_cast<int>(nodes.size()); ++i) {
    if (in_zone(nodes[i])) {
      first = first < 0 ? i : first;
      last = i;
    }
  }
  if (first < 0)
    return {};
  const auto x = [&](int i) { return nodes[i].position.x(); };
  const double left = first > 0 ? 0.5 * (x(first - 1) + x(first)) : x(first);
  const double right =
      last + 1 < static_cast<int>(nodes.size()) ? 0.5 * (x(last) + x(last + 1)) : x(last);
  return {0.5 * (right - left), 0.5 * (right + left)};
}

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// The Coulomb law node by node: slipping nodes carry mu p along their slip increment, sticking
/// ones at most mu p. Nodal rows carry the law node by node; Gauss-point rows (ss with PM / AL)
/// carry it per Gauss point, and a Q8 node's shares (N_a, negative at corners) mix points of
/// both kinds, so those are not checked here.
void expect_coulomb(const ContactResult& r, ConstraintRows rows) {
  if (rows == ConstraintRows::GaussPoints)
    return;
  for (const ContactNodeResult& n : r.nodes) {
    if (n.friction == FrictionState::Slip) {
      EXPECT_TRUE(Near(std::abs(n.shear), kMu * n.pressure, {1e-8, 1e-12})) << n.position.x();
      EXPECT_GE(n.shear * n.slip_increment, 0.0) << n.position.x();
    } else if (n.friction == FrictionState::Stick) {
      EXPECT_LE(std::abs(n.shear), kMu * n.pressure * (1.0 + 1e-8)) << n.position.x();
    }
  }
}

/// The normal load P, then the tangential load Q in two increments.
std::vector<LoadStep> mindlin_steps(const MindlinSpec& spec,
                                    const std::shared_ptr<FrictionLoad>& load, double P, double Q) {
  const double width = 2.0 * spec.L;
  std::vector<LoadStep> steps{{"normal", [=] {
                                 load->p = P / width;
                                 load->tau_top = load->tau_sides = 0.0;
                               }}};
  for (int k = 1; k <= 2; ++k)
    steps.push_back({"tangential", [=] { load->tau_top = load->tau_sides = 0.5 * k * Q / width; }});
  return steps;
}

class MindlinTest : public ::testing::TestWithParam<MindlinCase> {};

TEST_P(MindlinTest, StickZoneHalfWidth) {
  const MindlinCase& c = GetParam();
  MindlinSpec spec;
  spec.type = c.type;
  const double h = 2.0 * spec.L / spec.n_x;
  // P for Hertz's a = 1 (two equal bodies), Q = 0.5 mu P.
  const double P = kPi * spec.E / (8.0 * spec.R * (1.0 - spec.nu * spec.nu));
  const double Q = kQOverMuP * kMu * P;
  auto load = std::make_shared<FrictionLoad>();
  const Model model = contact_test::mindlin_model(spec, load);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::mindlin_pair());
  const std::vector<LoadStep> steps = mindlin_steps(spec, load, P, Q);
  const ContactSettings settings =
      contact_test::friction_settings(c.discretization, c.algorithm, kMu, c.tangential);
  std::vector<ContactResult> path = contact.solve_steps(settings, steps);  // factorizes
  auto t0 = Clock::now();
  path = contact.solve_steps(settings, steps);  // timed: the factorization is reused
  const double frictional_s = seconds_since(t0) / 3.0;
  ASSERT_EQ(path.size(), 3u) << path.back().reason;
  ASSERT_TRUE(path.back().converged()) << path.back().reason;

  const auto closed = [](const ContactNodeResult& n) { return n.closed; };
  const auto sticking = [](const ContactNodeResult& n) {
    return n.friction == FrictionState::Stick;
  };
  const double a_fe = zone_of(path[0].nodes, closed).half_width;
  const Zone stick = zone_of(path[2].nodes, sticking);
  const double c_expected = a_fe * std::sqrt(1.0 - kQOverMuP);
  EXPECT_LE(std::abs(stick.half_width - c_expected), 2.0 * h);  // see the file comment
  EXPECT_LE(std::abs(stick.centre), h);  // symmetric bodies: centred, to the node spacing

  double shear_sum = 0.0;
  for (double f : path[2].friction_history.force_t)
    shear_sum += f;
  EXPECT_TRUE(Near(shear_sum, Q, {1e-3, 0.0}));  // see the file comment
  expect_coulomb(path[2], constraint_rows(settings));

  // Cattaneo-Mindlin's peak shear, at x = c: mu p0 sqrt(1 - c^2 / a^2), p0 = 2 P / (pi a).
  const double a_hertz = spec.hertz_a(P);
  const double peak_exact = kMu * 2.0 * P / (kPi * a_hertz) * std::sqrt(kQOverMuP);
  std::printf(
      "[ info     ] CM %s: a_FE %.4f (Hertz %.4f), c %.4f centred at %+.3f, expected %.4f: "
      "%+.2f h; peak shear %.4f (CM %.4f, %+.1f%%), peak p %.4f (Hertz %.4f); iterations "
      "%d/%d/%d, augmentations %d/%d/%d; %.1f ms per step\n",
      case_name({c, 0}).c_str(), a_fe, a_hertz, stick.half_width, stick.centre, c_expected,
      (stick.half_width - c_expected) / h, path[2].peak_shear, peak_exact,
      100.0 * (path[2].peak_shear / peak_exact - 1.0), path[0].peak_pressure,
      2.0 * P / (kPi * a_hertz), path[0].active_set_iterations, path[1].active_set_iterations,
      path[2].active_set_iterations, path[0].augmentations, path[1].augmentations,
      path[2].augmentations, 1e3 * frictional_s);
}

std::vector<MindlinCase> all_cases() {
  std::vector<MindlinCase> cases;
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    for (ContactDiscretization d :
         {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
          ContactDiscretization::Mortar}) {
      cases.push_back({type, d, ContactAlgorithm::Penalty, TangentialEnforcement::Penalty});
      cases.push_back(
          {type, d, ContactAlgorithm::AugmentedLagrangian, TangentialEnforcement::Penalty});
      cases.push_back(
          {type, d, ContactAlgorithm::LagrangeMultiplier, TangentialEnforcement::Penalty});
      cases.push_back({type, d, ContactAlgorithm::LagrangeMultiplier,
                       TangentialEnforcement::LagrangeMultiplier});
    }
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllMethods, MindlinTest, ::testing::ValuesIn(all_cases()), case_name);

}  // namespace
}  // namespace cs::solver::test_contact_mindlin
