// Invariance under a change of units (issue 14): every length times L, every modulus and the
// loads times S (suites/problem_scaling.hpp) leaves every normalized result unchanged. Each
// problem of the catalogue is built on the C mesh with Q4 and Q8, run as built and scaled by
// (L, S) = (1e3, 2.1e5) (millimetres to metres' inverse, steel in MPa) and (1e-3, 7e10), through
// the same executor (sampling, grading, interface checks) as any case, with Lagrange multipliers
// (ss, mortar, ns), the augmented Lagrangian and the penalty (FKN relative to E / h) and MPC;
// the graded values, their contact-pressure versions and the profiles must agree to 1e-9
// relative. A strain check (displacements L times, coordinates changed) keeps a scaling that
// does nothing from passing.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "suites/problem_catalog.hpp"
#include "suites/problem_executor.hpp"
#include "suites/problem_scaling.hpp"

namespace cs::suites {
namespace {

/// The bounds of one comparison.
struct Bounds {
  /// Graded values, their contact-pressure versions, h/a: relative. 1e-9 is the bound.
  double graded = 1e-9;
  /// The surface profile: of its largest value (points near zero, e.g. off the contact, carry
  /// round-off of the peak's size).
  double profile = 1e-9;
  /// The exact profile (the oracle at x / L), of its largest value.
  double exact_profile = 1e-9;
  /// The interface checks, absolute in their normalized units (the load, p, h): their exact
  /// values are 0 (equilibrium, no tension, no pressure outside the patch, no penetration for
  /// multipliers), and where they are round-off a relative difference means nothing.
  double check = 1e-9;
};

/// Every problem but S: the 1e-9 throughout.
constexpr Bounds kStrict{};

/// S: Steuermann's pressure has an infinite slope at the contact edge, where the exact profile
/// has a point: x / L one ulp off x moves it by 3.4e-6 of the peak (measured), so 1e-5 there.
constexpr Bounds kSteuermann{.exact_profile = 1e-5};

/// S with a punch only 1e3 times stiffer than the block: the graded values to 1e-9; profiles
/// and checks carry the remaining round-off (measured 1.6e-9 and 4.7e-9).
constexpr Bounds kSofterPunch{.profile = 1e-8, .exact_profile = 1e-5, .check = 1e-8};

/// S with the study's discretized punch (E_ratio 1e6), held by the contact alone: the round-off
/// of the condensation grows with the stiffness ratio (S_1 LMP ss sigma_c: 3e-8, 3e-10 and 6e-11
/// at E_ratio 1e6, 1e4 and 1e3), so the invariance holds to round-off x 1e6 (measured worst:
/// graded 4.8e-7, profiles 4.3e-6, checks 7.5e-6 absolute; the checks' own resolution is 1e-4,
/// schema/interface_checks.hpp). The same cases at E_ratio 1e3 are held to kSteuermann.
constexpr Bounds kStiffFloatingPunch{
    .graded = 1e-6, .profile = 1e-5, .exact_profile = 1e-5, .check = 1e-4};

const solver::ModelScaling kScalings[] = {{1e3, 2.1e5}, {1e-3, 7e10}};

struct Method {
  Algorithm algorithm;
  ContactKind contact;
};

/// The methods run on every problem: Lagrange multipliers (ss, mortar, ns), AL and PM (ss), AL
/// mortar, and MPC (PLM mortar with friction, which refuses MPC). S, whose C meshes are 10 to 40
/// times larger, runs the brief's three (LMP ss and mortar, AL ss) to keep the test short.
std::vector<Method> methods_for(ProblemId problem) {
  if (problem == ProblemId::S_1 || problem == ProblemId::S_1_3 || problem == ProblemId::S_1_7) {
    return {{Algorithm::LMP, ContactKind::ss},
            {Algorithm::LMP, ContactKind::mortar},
            {Algorithm::AL, ContactKind::ss}};
  }
  std::vector<Method> out = {
      {Algorithm::LMP, ContactKind::ss}, {Algorithm::LMP, ContactKind::mortar},
      {Algorithm::LMP, ContactKind::ns}, {Algorithm::AL, ContactKind::ss},
      {Algorithm::PM, ContactKind::ss},  {Algorithm::AL, ContactKind::mortar}};
  if (is_frictional(problem))
    out.push_back({Algorithm::PLM, ContactKind::mortar});
  else
    out.push_back({Algorithm::MPC, ContactKind::ss});
  return out;
}

/// |x - y| / max(|x|, |y|); 0 when both are equal (both 0, both the same infinity, both NaN),
/// +inf when one is NaN and the other is not.
double relative_difference(double x, double y) {
  if (x == y || (std::isnan(x) && std::isnan(y)))
    return 0.0;
  if (std::isnan(x) || std::isnan(y) || std::isinf(x) || std::isinf(y))
    return std::numeric_limits<double>::infinity();
  return std::abs(x - y) / std::max(std::abs(x), std::abs(y));
}

/// The worst differences of one method over every problem, for the report.
struct Worst {
  double graded = 0.0;     ///< graded values and their contact-pressure versions
  double profile = 0.0;    ///< the normalized surface profile and the exact profile
  double check_rel = 0.0;  ///< interface checks not at round-off (|value| > 1e-6), relative
  double check_abs = 0.0;  ///< interface checks, absolute (normalized units)
};

using WorstByMethod = std::map<std::string, Worst>;

std::string method_name(const Method& m) {
  return fmt::format("{} {}", to_string(m.algorithm), to_string(m.contact));
}

/// Each pair to `bound` relative to the larger of the two, or with `scale` > 0 to `bound` of
/// the scale.
void expect_same_values(const std::vector<double>& a, const std::vector<double>& b,
                        const std::string& what, double bound, double& worst, double scale = 0.0) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = scale > 0.0 && std::isfinite(a[i]) && std::isfinite(b[i])
                         ? std::abs(a[i] - b[i]) / scale
                         : relative_difference(a[i], b[i]);
    worst = std::max(worst, d);
    EXPECT_LE(d, bound) << what << "[" << i << "]: " << a[i] << " vs " << b[i];
  }
}

void expect_same_check(const std::optional<double>& a, const std::optional<double>& b,
                       const std::string& what, double bound, Worst& worst) {
  ASSERT_EQ(a.has_value(), b.has_value()) << what;
  if (!a)
    return;
  const double diff = std::abs(*a - *b);
  worst.check_abs = std::max(worst.check_abs, diff);
  if (std::max(std::abs(*a), std::abs(*b)) > 1e-6)
    worst.check_rel = std::max(worst.check_rel, relative_difference(*a, *b));
  EXPECT_LE(diff, bound) << what << ": " << *a << " vs " << *b;
}

/// Every normalized value of `scaled` against `base` (same case in other units).
void expect_same_result(const CaseResult& base, const CaseResult& scaled, const std::string& what,
                        const Bounds& bounds, Worst& worst) {
  ASSERT_EQ(base.status, CaseStatus::converged) << what << ": " << base.reason;
  ASSERT_EQ(scaled.status, base.status) << what << ": " << scaled.reason;
  EXPECT_EQ(scaled.iterations, base.iterations) << what;
  ASSERT_EQ(scaled.quantities.size(), base.quantities.size()) << what;
  for (std::size_t q = 0; q < base.quantities.size(); ++q) {
    const QuantityResult &a = base.quantities[q], &b = scaled.quantities[q];
    const std::string name = fmt::format("{} {}", what, to_string(a.quantity));
    ASSERT_EQ(b.quantity, a.quantity) << name;
    ASSERT_TRUE(std::isfinite(a.value)) << name << " has no value";
    expect_same_values({a.value, a.exact}, {b.value, b.exact}, name, bounds.graded, worst.graded);
    EXPECT_EQ(b.grade, a.grade) << name;
    ASSERT_EQ(b.contact_pressure.has_value(), a.contact_pressure.has_value()) << name;
    if (a.contact_pressure) {
      expect_same_values({*a.contact_pressure}, {*b.contact_pressure}, name + " (contact)",
                         bounds.graded, worst.graded);
    }
  }
  expect_same_values({base.element_size_h}, {scaled.element_size_h}, what + " h/a", bounds.graded,
                     worst.graded);
  const auto largest = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v)
      m = std::isfinite(x) ? std::max(m, std::abs(x)) : m;
    return m;
  };
  const SurfaceProfile &pa = base.profile, &pb = scaled.profile;
  const ExactProfile &ea = base.exact_profile, &eb = scaled.exact_profile;
  expect_same_values(pa.x_over_a, pb.x_over_a, what + " profile x/a", bounds.profile, worst.profile,
                     largest(pa.x_over_a));
  expect_same_values(pa.sigma_z_over_p, pb.sigma_z_over_p, what + " profile sigma_z/p",
                     bounds.profile, worst.profile, largest(pa.sigma_z_over_p));
  expect_same_values(pa.pressure_over_p, pb.pressure_over_p, what + " profile pressure/p",
                     bounds.profile, worst.profile, largest(pa.pressure_over_p));
  expect_same_values(ea.x_over_a, eb.x_over_a, what + " exact profile x/a", bounds.graded,
                     worst.profile, largest(ea.x_over_a));
  expect_same_values(ea.sigma_z_over_p, eb.sigma_z_over_p, what + " exact profile",
                     bounds.exact_profile, worst.profile, largest(ea.sigma_z_over_p));
  ASSERT_EQ(base.interface.has_value(), scaled.interface.has_value()) << what;
  if (base.interface) {
    const auto &a = *base.interface, &b = *scaled.interface;
    expect_same_check(a.force_balance, b.force_balance, what + " force balance", bounds.check,
                      worst);
    expect_same_check(a.max_tensile_over_p, b.max_tensile_over_p, what + " tensile", bounds.check,
                      worst);
    expect_same_check(a.max_outside_over_p, b.max_outside_over_p, what + " outside", bounds.check,
                      worst);
    expect_same_check(a.max_penetration_over_h, b.max_penetration_over_h, what + " penetration",
                      bounds.check, worst);
  }
}

CaseSpec coarse_spec(ProblemId problem, Element element,
                     TargetKind target = TargetKind::Discretized) {
  return CaseSpec{.problem = problem,
                  .mesh = MeshLevel::C,
                  .element = element,
                  .target = target,
                  .overrides = {}};
}

/// Runs every method on `spec`'s problem as built and in each kScalings' units, and compares.
void check_invariance(const CaseSpec& representative, const std::vector<Method>& methods,
                      const Bounds& bounds, WorstByMethod& worst) {
  ProblemExecutor base(representative);
  std::vector<CaseResult> base_results;
  for (const Method& m : methods) {
    CaseSpec spec = representative;
    spec.algorithm = m.algorithm;
    spec.contact = m.contact;
    base_results.push_back(base.run(spec));
  }
  for (const solver::ModelScaling& s : kScalings) {
    ProblemExecutor other(scaled(build_problem(representative), s));
    for (std::size_t k = 0; k < methods.size(); ++k) {
      CaseSpec spec = representative;
      spec.algorithm = methods[k].algorithm;
      spec.contact = methods[k].contact;
      const std::string what =
          fmt::format("{} at L = {:g}, S = {:g}", case_id(spec), s.length_L, s.stress_S);
      expect_same_result(base_results[k], other.run(spec), what, bounds,
                         worst[method_name(methods[k])]);
    }
  }
}

/// One line per method: the worst differences observed (for the closing note).
void print_worst(std::string_view label, const WorstByMethod& worst) {
  for (const auto& [method, w] : worst) {
    std::printf("    %-12s %-10s graded %.1e  profiles %.1e  checks %.1e rel (> 1e-6), %.1e abs\n",
                std::string(label).c_str(), method.c_str(), w.graded, w.profile, w.check_rel,
                w.check_abs);
  }
}

bool is_steuermann(ProblemId p) {
  return p == ProblemId::S_1 || p == ProblemId::S_1_3 || p == ProblemId::S_1_7;
}

/// Q4 and Q8; S with Q4 only: its C mesh with Q8 has 108k equations (2.8 s a case here), 17 s
/// of this test. (Run with Q8 while this test was written: within kStiffFloatingPunch.)
std::vector<Element> elements_for(ProblemId p) {
  if (is_steuermann(p))
    return {Element::Q4};
  return {Element::Q4, Element::Q8};
}

class ScalingInvariance : public ::testing::TestWithParam<ProblemId> {};

// Requirement: for every problem of the catalogue on the C mesh, Q4 and Q8 (S: Q4), every method,
// the normalized results in units scaled by (L, S) equal the original ones to 1e-9 relative (the
// interface checks, exactly 0 in theory, to 1e-9 of their unit; S with the study's 1e6 stiff
// punch to its round-off, kStiffFloatingPunch), with the same iteration count and grade: the
// solver has no absolute length, force or pressure tolerance, and no tie that round-off decides.
TEST_P(ScalingInvariance, NormalizedResultsDoNotDependOnUnits) {
  const Bounds& bounds = is_steuermann(GetParam()) ? kStiffFloatingPunch : kStrict;
  WorstByMethod worst;
  for (Element element : elements_for(GetParam()))
    check_invariance(coarse_spec(GetParam(), element), methods_for(GetParam()), bounds, worst);
  print_worst(to_string(GetParam()), worst);
}

const auto kProblems = values<ProblemId>();

INSTANTIATE_TEST_SUITE_P(Catalogue, ScalingInvariance, ::testing::ValuesIn(kProblems),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// Requirement: S_1_3 (Q4) with a punch 1e3 times stiffer than the block (round-off 1e3 times
// smaller than at the study's 1e6) has its graded values invariant to 1e-9 like every other
// problem: the looser bound of the study's punch is its conditioning, not a scaling rule.
TEST(ScalingInvariance, SteuermannWithASofterPunchToOneInABillion) {
  WorstByMethod worst;
  CaseSpec spec = coarse_spec(ProblemId::S_1_3, Element::Q4);
  spec.overrides = {{"E_ratio", 1e3}};
  check_invariance(spec, {{Algorithm::LMP, ContactKind::ss}, {Algorithm::AL, ContactKind::ss}},
                   kSofterPunch, worst);
  print_worst("S E_ratio=1e3", worst);
}

// Requirement: with a rigid target (a plane, a circle, a rounded punch under load control, a
// sharp punch) the scaled profile gives the same normalized results: the load control's secant
// iterates on the support's advance are the original ones.
TEST(ScalingInvariance, RigidTargetsDoNotDependOnUnits) {
  WorstByMethod worst;
  for (ProblemId problem : {ProblemId::P_a, ProblemId::H_p, ProblemId::S_1_3, ProblemId::F_a}) {
    check_invariance(coarse_spec(problem, Element::Q4, TargetKind::Rigid),
                     {{Algorithm::LMP, ContactKind::ss}, {Algorithm::AL, ContactKind::mortar}},
                     is_steuermann(problem) ? kSteuermann : kStrict, worst);
  }
  print_worst("rigid", worst);
}

// Requirement: the scaled model is a different model (coordinates L times), whose displacement
// is L times the original's at every node (strains unchanged) to 1e-9 of the largest: a scaling
// that changed nothing, or lengths but not loads, fails here.
TEST(ScalingInvariance, DisplacementsScaleWithLength) {
  const CaseSpec spec{
      .problem = ProblemId::H_a, .mesh = MeshLevel::C, .element = Element::Q8, .overrides = {}};
  ProblemExecutor base(spec);
  base.recover_whole_field();  // reads the whole displacement
  ASSERT_EQ(base.run(spec).status, CaseStatus::converged);
  const Eigen::VectorXd u = base.last_displacement();
  const double u_max = u.cwiseAbs().maxCoeff();
  ASSERT_GT(u_max, 0.0);
  for (const solver::ModelScaling& s : kScalings) {
    ProblemExecutor other(scaled(build_problem(spec), s));
    ASSERT_EQ(other.run(spec).status, CaseStatus::converged);
    const auto& a = base.setup().model.mesh.nodes;
    const auto& b = other.setup().model.mesh.nodes;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t n = 0; n < a.size(); ++n) {
      if (a[n].norm() > 0.0) {
        ASSERT_FALSE(a[n] == b[n]) << "node " << n << " did not move";
      }
      EXPECT_NEAR((b[n] / s.length_L - a[n]).norm(), 0.0, 1e-12 * a[n].norm()) << "node " << n;
    }
    const Eigen::VectorXd& v = other.last_displacement();
    ASSERT_EQ(v.size(), u.size());
    const double diff = (v / s.length_L - u).cwiseAbs().maxCoeff();
    std::printf("    H_a Q8 LMP ss, L = %g, S = %g: max |u'/L - u| = %.2e of max |u|\n", s.length_L,
                s.stress_S, diff / u_max);
    EXPECT_LE(diff, 1e-9 * u_max);
    EXPECT_GT((v - u).cwiseAbs().maxCoeff(), 0.5 * u_max) << "the displacement did not change";
  }
}

}  // namespace
}  // namespace cs::suites
