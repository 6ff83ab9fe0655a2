// The solution loop and the condensation: termination paths, bad input, and agreement of the
// condensed solve with a direct solve of the same active-set system.
//
// Requirement: the active-set loop always ends with an explicit status (iteration cap, cycling,
// singular system) and never returns a non-finite number; bad input raises ContactError with a
// message naming the cause; the condensed solution equals a direct sparse solve of the final
// active-set system (to 1e-10), and both condensation methods agree.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/SparseLU>

#include "solver/contact/condensation.hpp"
#include "solver/contact/contact_error.hpp"
#include "solver/contact/dense_kernels.hpp"
#include "solver/contact/lagrange_multiplier.hpp"
#include "solver/spare_cores.hpp"
#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using contact_test::HertzSpec;
using contact_test::PatchSpec;
using cs::testing::Near;

// ---- termination ------------------------------------------------------------------------------

TEST(ContactLoop, IterationCapOfOneStopsWithStatus) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  ContactSettings s = contact_test::settings(ContactDiscretization::NodeToSurface,
                                             ContactAlgorithm::LagrangeMultiplier);
  s.max_iterations = 1;  // all candidates start active: Hertz needs more than one solve
  const ContactResult r = solve_contact(model, contact_test::hertz_pair(spec), s);
  EXPECT_EQ(r.status, ContactStatus::NotConverged);
  EXPECT_EQ(r.failure, ContactFailure::IterationLimit);
  EXPECT_NE(r.reason.find("iteration cap of 1"), std::string::npos) << r.reason;
  EXPECT_EQ(r.active_set_iterations, 1);
  EXPECT_GT(r.residual, kActiveSetTolerance);
  // The last iterate is returned, finite, and labelled as not converged.
  ASSERT_GT(r.displacement.size(), 0);
  EXPECT_TRUE(r.displacement.allFinite());
}

TEST(ContactLoop, CyclingActiveSetIsDetected) {
  // A 3-row condensed problem (rho = 1, W scaled below the identity as every condensation is)
  // on which the primal-dual active set method cycles with period 3 from the empty set (found by
  // a random search; W is not an M-matrix).
  Eigen::MatrixXd W(3, 3);
  W << 0.39817232324052376, 0.27141843557126283, -0.33990139496955835,  //
      0.27141843557126283, 0.60541064681182533, -0.047956217926974666,  //
      -0.33990139496955835, -0.047956217926974666, 0.63529388830484623;
  Eigen::VectorXd d(3);
  d << -0.34289435042213545, 0.96082366724178958, 0.5431947584045147;
  const Eigen::VectorXd g0 = Eigen::VectorXd::Zero(3);
  const Eigen::VectorXd rho = Eigen::VectorXd::Ones(3);
  const CondensedProblem problem{W, d, rho, g0, 1e-12};
  const LagrangeMultiplierRules rules(rho);
  const AlgorithmOutcome out = run_active_set(problem, rules, {0, 0, 0}, 50);
  EXPECT_EQ(out.status, ContactStatus::NotConverged);
  EXPECT_EQ(out.failure, ContactFailure::Cycling);
  EXPECT_NE(out.reason.find("cycling"), std::string::npos) << out.reason;
  EXPECT_LT(out.iterations, 50);  // stopped at the first repetition, not at the cap
  EXPECT_TRUE(out.step.lambda.allFinite());
}

TEST(ContactLoop, BodyPulledOffTheTargetIsASingularStatus) {
  PatchSpec spec;
  spec.p = -1.0;  // a tension pulls the floating block away: nothing holds it
  const Model model = contact_test::patch_model(spec);
  const ContactResult r =
      solve_contact(model, contact_test::patch_pair(spec),
                    contact_test::settings(ContactDiscretization::NodeToSurface,
                                           ContactAlgorithm::LagrangeMultiplier));
  EXPECT_EQ(r.status, ContactStatus::NotConverged);
  EXPECT_EQ(r.failure, ContactFailure::SingularSystem);
  EXPECT_NE(r.reason.find("singular"), std::string::npos) << r.reason;
  if (r.displacement.size() > 0) {
    EXPECT_TRUE(r.displacement.allFinite());
  }
}

TEST(ContactLoop, AugmentationCapStopsWithStatus) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  ContactSettings s = contact_test::settings(ContactDiscretization::NodeToSurface,
                                             ContactAlgorithm::AugmentedLagrangian);
  s.fkn = 1e-4;
  s.ftoln = 1e-3;
  s.pinball = 10.0;
  s.max_augmentations = 2;
  const ContactResult r = solve_contact(model, contact_test::hertz_pair(spec), s);
  EXPECT_EQ(r.status, ContactStatus::NotConverged);
  EXPECT_EQ(r.failure, ContactFailure::AugmentationLimit);
  EXPECT_NE(r.reason.find("FTOLN"), std::string::npos) << r.reason;
  EXPECT_TRUE(r.displacement.allFinite());
}

// ---- bad input -----------------------------------------------------------------------------

void expect_contact_error(const std::function<void()>& f, const std::string& cause) {
  try {
    f();
    ADD_FAILURE() << "no ContactError (expected one naming '" << cause << "')";
  } catch (const ContactError& e) {
    EXPECT_NE(std::string(e.what()).find(cause), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
  }
}

// The condensed systems' dense factorization: Cholesky where the matrix is positive definite;
// two Cholesky factorizations where it is quasi-definite (the rows of a negative diagonal a
// negative definite block, the Schur complement of the rest positive definite), as the contact
// system is with open rows: rho^{1/2} W rho^{1/2} - I there, W = B M^{-1} B^T; else Bunch-Kaufman
// LDL^T (a negative block that is not negative definite, or a Schur complement that is not
// positive definite). Each solves A x = b to
// round-off; an exactly singular matrix is refused or reads rcond 0, in every method.
TEST(DenseFactorization, CholeskyQuasiDefiniteOrLdlt) {
  using dense::SymmetricMethod;
  Eigen::MatrixXd spd(3, 3), indefinite(3, 3);
  spd << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  indefinite << 1, 2, 0, 2, 1, 1, 0, 1, -3;
  // The contact system's shape: a compliance with rho W < I (here B = I, M = S + I with S
  // positive definite, so rho W = (S + I)^{-1}) and -1 added on the open rows 1 and 3.
  Eigen::MatrixXd S(4, 4);
  S << 3, 1, 0, 0.5, 1, 2, 0.5, 0, 0, 0.5, 4, 1, 0.5, 0, 1, 2;
  Eigen::MatrixXd contact = (S + Eigen::MatrixXd::Identity(4, 4)).inverse();
  contact(1, 1) -= 1.0;
  contact(3, 3) -= 1.0;
  // A negative diagonal entry whose block is not negative definite: [[-1, 3], [3, -1]].
  Eigen::MatrixXd saddle(3, 3);
  saddle << 2, 0, 1, 0, -1, 3, 1, 3, -1;
  const std::pair<Eigen::MatrixXd, SymmetricMethod> cases[] = {
      {spd, SymmetricMethod::cholesky},
      {indefinite, SymmetricMethod::bunch_kaufman},  // its P block's Schur complement is not
      {contact, SymmetricMethod::quasi_definite},
      {saddle, SymmetricMethod::bunch_kaufman}};
  for (const auto& [A, method] : cases) {
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, -2.0);
    dense::SymmetricFactorization f;
    ASSERT_TRUE(f.factorize(A)) << A;
    EXPECT_EQ(f.method(), method) << A;
    EXPECT_GT(f.rcond(), 0.01) << A;
    Eigen::VectorXd b = A * x;
    f.solve_in_place(b);
    EXPECT_LT((b - x).norm(), 1e-13) << A;
  }
  // Singular, one per method tried first: positive semidefinite; a negative block that is
  // singular; a quasi-definite split whose Schur complement is 0 ([[0, 0], [0, -1]]).
  Eigen::MatrixXd psd(2, 2), negative(2, 2), zero_schur(2, 2);
  psd << 1, 1, 1, 1;
  negative << -1, 1, 1, -1;
  zero_schur << 0, 0, 0, -1;
  for (const auto& A : {psd, negative, zero_schur}) {
    dense::SymmetricFactorization f;
    EXPECT_FALSE(f.factorize(A) && f.rcond() > 1e-14) << A;
  }
}

// The frictional system's LU (LAPACK dgetrf): it solves A^T x = b for a matrix that is not
// symmetric, to round-off; its condition estimate is the 1-norm one, within LAPACK's factor of
// the exact 1 / (|A|_1 |A^-1|_1) and never below it (with the infinity norm it would read far
// below at n = 60); a singular matrix is refused or reads
// rcond 0, and one workspace serves matrices of other sizes.
TEST(DenseFactorization, GeneralLuSolvesTheTransposedSystem) {
  dense::GeneralLu lu;
  for (const int n : {7, 3, 60}) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j)
        A(i, j) = std::sin(1.0 + i + 3.0 * j * j) + (i == j ? 0.5 * n : 0.0) + (j == i + 1 ? 2 : 0);
    }
    A.row(0).array() += 40.0;  // a heavy row: the infinity norm far above the 1-norm
    A(0, 0) = 0.0;             // a zero first pivot: only row exchanges factor it
    lu.matrix(n) = A;
    ASSERT_TRUE(lu.factorize()) << A;
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 1.0, -2.0);
    Eigen::VectorXd b = A.transpose() * x;
    lu.solve_transposed_in_place(b);
    EXPECT_LT((b - x).norm(), 1e-12 * n) << n;
    const double exact = 1.0 / (A.cwiseAbs().colwise().sum().maxCoeff() *
                                A.inverse().cwiseAbs().colwise().sum().maxCoeff());
    EXPECT_GE(lu.rcond(), exact * (1 - 1e-12)) << n;
    EXPECT_LT(lu.rcond(), 10.0 * exact) << n;
  }
  Eigen::MatrixXd singular(3, 3);
  singular << 1, 2, 3, 2, 4, 6, 0, 1, 1;
  lu.matrix(3) = singular;
  EXPECT_FALSE(lu.factorize() && lu.rcond() > 1e-14);
}

TEST(ContactInput, BadInputRaisesContactErrorNamingTheCause) {
  PatchSpec spec;
  spec.indenter_nx = 4;
  const Model model = contact_test::patch_model(spec);
  const ContactSettings ok;
  expect_contact_error(
      [&] {
        solve_contact(model, {"block.btm", TargetSurface{"indenter.top"}}, ok);
      },
      "unknown contact surface 'block.btm'");
  expect_contact_error(
      [&] {
        solve_contact(model, {"block.bottom", TargetSurface{"punch"}}, ok);
      },
      "unknown target surface 'punch'");
  expect_contact_error(
      [&] {
        solve_contact(model, {"block.bottom", RigidCircle{{0.0, -1.0}, -1.0}}, ok);
      },
      "radius R = -1");
  for (double bad : {0.0, -1.0, std::nan("")}) {
    ContactSettings s;
    s.fkn = bad;
    expect_contact_error([&] { validate(s); }, "FKN");
    s = ContactSettings{};
    s.ftoln = bad;
    expect_contact_error([&] { validate(s); }, "FTOLN");
    s = ContactSettings{};
    s.pinball = bad;
    expect_contact_error([&] { validate(s); }, "pinball");
  }
  ContactSettings s;
  s.max_iterations = 0;
  expect_contact_error([&] { validate(s); }, "max_iterations");
  // A rigid plane 10 below the surface, with the default pinball of one element depth.
  expect_contact_error(
      [&] {
        solve_contact(model, {"block.bottom", RigidPlane{{0.0, -10.0}, {0.0, 1.0}}}, ok);
      },
      "never comes within the pinball");
}

// ---- condensed solve vs direct solve ---------------------------------------------------------

/// Solves the final active-set system of `r` directly (no condensation) and returns the global
/// displacement: K u = f + B_A^T lambda with B_A u = -g0_A (LM), or K u = f - B_A^T k (g0_A +
/// B_A u) (PM).
Eigen::VectorXd direct_solve(LinearStaticAnalysis& elastic, ContactAnalysis& contact,
                             const ContactResult& r) {
  const ConstraintSet& set = contact.constraints(constraint_rows(r.settings));
  const DofMap& dofs = elastic.dof_map();
  const Eigen::SparseMatrix<double> K_lower = elastic.stiffness().K_ff;
  const Eigen::SparseMatrix<double> K =
      Eigen::SparseMatrix<double>(K_lower.selfadjointView<Eigen::Lower>());
  const Eigen::VectorXd f = elastic.reduced_load(elastic.model().loads);
  // The active rows: those of closed nodes (nodal rows).
  std::vector<int> active_rows;
  for (int j = 0; j < set.n_rows(); ++j) {
    for (const ContactNodeResult& n : r.nodes) {
      if (n.node == set.nodes[j].node && n.closed)
        active_rows.push_back(j);
    }
  }
  const int n = dofs.n_free();
  const int a = static_cast<int>(active_rows.size());
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < K.outerSize(); ++k) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, k); it; ++it) {
      t.emplace_back(it.row(), it.col(), it.value());
    }
  }
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + a);
  rhs.head(n) = f;
  const bool lagrange = r.settings.algorithm == ContactAlgorithm::LagrangeMultiplier;
  for (int q = 0; q < a; ++q) {
    const int j = active_rows[q];
    const double k = r.settings.fkn * set.rows[j].stiffness_scale();
    std::vector<std::pair<int, double>> row;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(set.B, j); e; ++e) {
      const int eq = dofs.equation(static_cast<int>(e.col()));
      if (eq >= 0)
        row.emplace_back(eq, e.value());
    }
    if (lagrange) {  // [K -B^T; B 0] [u; lambda] = [f; -g0]
      for (auto [eq, v] : row) {
        t.emplace_back(eq, n + q, -v);
        t.emplace_back(n + q, eq, v);
      }
      rhs[n + q] = -set.g0[j];
    } else {  // (K + k B^T B) u = f - k B^T g0
      for (auto [i1, v1] : row) {
        for (auto [i2, v2] : row)
          t.emplace_back(i1, i2, k * v1 * v2);
        rhs[i1] -= k * v1 * set.g0[j];
      }
      t.emplace_back(n + q, n + q, 1.0);
    }
  }
  Eigen::SparseMatrix<double> A(n + a, n + a);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
  const Eigen::VectorXd x = lu.solve(rhs);
  return elastic.expand(x.head(n));
}

class ContactCondensedVsDirect
    : public ::testing::TestWithParam<std::tuple<ContactDiscretization, ContactAlgorithm>> {};

TEST_P(ContactCondensedVsDirect, SameDisplacement) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);  // the block floats: K is singular
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  const auto [d, a] = GetParam();
  const ContactResult r = contact.solve(contact_test::settings(d, a));
  ASSERT_TRUE(r.converged()) << r.reason;
  const Eigen::VectorXd u_direct = direct_solve(elastic, contact, r);
  const double error = (r.displacement - u_direct).norm() / u_direct.norm();
  std::printf("[ info     ] H_p %s %s: |u_condensed - u_direct| / |u| = %.2e\n", to_string(d),
              to_string(a), error);
  EXPECT_LE(error, 1e-10);  // round-off of two different factorizations
}

INSTANTIATE_TEST_SUITE_P(
    NodalRows, ContactCondensedVsDirect,
    ::testing::Values(
        std::make_tuple(ContactDiscretization::NodeToSurface, ContactAlgorithm::LagrangeMultiplier),
        std::make_tuple(ContactDiscretization::NodeToSurface, ContactAlgorithm::Penalty),
        std::make_tuple(ContactDiscretization::Mortar, ContactAlgorithm::LagrangeMultiplier),
        std::make_tuple(ContactDiscretization::Mortar, ContactAlgorithm::Penalty)),
    [](const auto& info) {
      return std::string(to_string(std::get<0>(info.param))) + "_" +
             to_string(std::get<1>(info.param));
    });

TEST(ContactCondensation, OneFactorizationServesEveryDiscretizationAndAlgorithm) {
  HertzSpec spec;
  spec.n = 16;
  const Model model = contact_test::hertz_model(spec);
  LinearStaticAnalysis elastic(model);
  ContactAnalysis contact(elastic, contact_test::hertz_pair(spec));
  int factorizations = 0;
  for (ContactDiscretization d :
       {ContactDiscretization::NodeToSurface, ContactDiscretization::SurfaceToSurface,
        ContactDiscretization::Mortar}) {
    for (ContactAlgorithm a :
         {ContactAlgorithm::Penalty, ContactAlgorithm::AugmentedLagrangian,
          ContactAlgorithm::LagrangeMultiplier, ContactAlgorithm::MultipointConstraint}) {
      const ContactResult r = contact.solve(contact_test::settings(d, a));
      EXPECT_TRUE(r.converged()) << to_string(d) << " " << to_string(a) << ": " << r.reason;
      if (!r.timings.condensation_reused)
        ++factorizations;
    }
  }
  EXPECT_EQ(factorizations, 1);
}

/// H_p on Q8 with a meshed indenter, n elements across.
Model meshed_hertz_q8(int n) {
  HertzSpec spec;
  spec.n = n;
  spec.type = ElementType::Q8;
  spec.meshed_indenter = true;
  return contact_test::hertz_model(spec);
}

/// The free equations of the nodes of `sets`, increasing.
std::vector<int> free_equations(const Model& model, const DofMap& dofs,
                                std::initializer_list<const char*> sets) {
  std::vector<int> out;
  for (const char* set : sets) {
    for (int node : model.mesh.node_sets.at(set)) {
      for (int k = 0; k < 2; ++k) {
        if (dofs.equation(2 * node + k) >= 0)
          out.push_back(dofs.equation(2 * node + k));
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The node of every free equation.
std::vector<int> node_of_equations(const DofMap& dofs) {
  std::vector<int> out(dofs.n_free());
  for (int eq = 0; eq < dofs.n_free(); ++eq)
    out[eq] = dofs.free_dofs()[eq] / 2;
  return out;
}

/// A Hertz Q8 model's elastic system, its contact DOFs (both bodies' surfaces), the block's far
/// side (wanted) and a contact displacement u_c, for the condensation tests.
struct CondensedHertz {
  Model model;
  LinearStaticAnalysis elastic;
  std::vector<int> c, wanted, node_of;
  Eigen::VectorXd f, u_c;

  explicit CondensedHertz(int divisions) : model(meshed_hertz_q8(divisions)), elastic(model) {
    elastic.assemble();
    c = free_equations(model, dofs(), {"block.bottom", "indenter.contact"});
    wanted = free_equations(model, dofs(), {"block.top"});
    node_of = node_of_equations(dofs());
    f = elastic.reduced_load(model.loads);
    u_c = Eigen::VectorXd::LinSpaced(static_cast<Eigen::Index>(c.size()), -1e-3, 2e-3);
  }
  CondensedHertz(const CondensedHertz&) = delete;  // elastic refers to model
  CondensedHertz& operator=(const CondensedHertz&) = delete;

  const DofMap& dofs() const { return elastic.dof_map(); }
  DofCondensationInput input() const { return {elastic.stiffness().K_ff, f, c, node_of}; }
};

/// The trailing-block condensation of K onto `contact` with METIS, as one factor
/// (substructure_from = int max) or as two sides (1); `spare` cores lent while it runs.
SolveOutcome condense_metis(const CondensedHertz& h, const Eigen::SparseMatrix<double>& K,
                            const std::vector<int>& contact, int substructure_from,
                            DofCondensation& out, int spare = 0) {
  const CoreLoan loan(spare);
  DofCondensationInput in{K, h.f, contact, h.node_of};
  in.ordering = FillReducingOrdering::Metis;
  in.substructure_from = substructure_from;
  return out.compute(in);
}

/// A subset recovery `part` equals the whole recovery at every equation the subset gives, gives
/// the wanted and contact equations, and is NaN everywhere else.
void expect_the_whole_there(const CondensedHertz& h, const RecoverySubset& subset,
                            const Eigen::VectorXd& part, const Eigen::VectorXd& whole) {
  ASSERT_EQ(part.size(), whole.size());
  std::vector<char> given(part.size(), 0);
  for (int eq : subset.equations) {
    given[eq] = 1;
    EXPECT_EQ(part[eq], whole[eq]) << "equation " << eq;
  }
  for (const std::vector<int>* set : {&h.wanted, &h.c}) {
    for (int eq : *set)
      EXPECT_TRUE(given[eq]) << "equation " << eq << " left out";
  }
  int nan = 0;
  for (Eigen::Index eq = 0; eq < part.size(); ++eq)
    nan += given[eq] ? 0 : (std::isnan(part[eq]) ? 1 : 0);
  EXPECT_EQ(nan, static_cast<int>(part.size() - subset.equations.size()));
}

constexpr int kOneFactor = std::numeric_limits<int>::max();
constexpr int kTwoSides = 1;

TEST(ContactCondensation, SchurComplementIsTheSameForEveryOrderingAndMethod) {
  // The Schur complement onto the block's contact-surface DOFs (the block floats: K is
  // singular, K_ii is not) from the reference (multiple right-hand sides) and from the trailing
  // factor block with CAMD and with METIS orderings.
  const CondensedHertz h(16);
  DofCondensation reference(CondensationMethod::MultipleRightHandSides);
  ASSERT_TRUE(reference.compute(h.input()).ok());
  const Eigen::VectorXd u_ref = reference.recover(h.u_c);
  for (FillReducingOrdering ordering : {FillReducingOrdering::Amd, FillReducingOrdering::Metis,
                                        FillReducingOrdering::CholmodDefault}) {
    DofCondensation fast(CondensationMethod::TrailingFactorBlock);
    DofCondensationInput in = h.input();
    in.ordering = ordering;
    ASSERT_TRUE(fast.compute(in).ok());
    // Round-off, amplified by the E ratio 1e6 between the two bodies' stiffness blocks.
    const double scale = reference.schur().cwiseAbs().maxCoeff();
    EXPECT_LE((fast.schur() - reference.schur()).cwiseAbs().maxCoeff(), 1e-10 * scale);
    EXPECT_LE((fast.condensed_load() - reference.condensed_load()).norm(),
              1e-10 * reference.condensed_load().norm() + 1e-12 * h.f.norm());
    EXPECT_LE((fast.recover(h.u_c) - u_ref).norm(), 1e-10 * u_ref.norm());
  }
}

// Requirement (issue 27): the displacement at some equations costs a backward solve over the
// supernodes they need, and equals the whole recovery there in every bit. Fails if an entry
// differs, a wanted or contact equation is missing, the subset is the whole factor (no saving),
// or an entry outside it is not NaN (a stale value read as an answer).
TEST(ContactCondensation, RecoveryOfSomeEquationsIsTheWholeRecoveryThere) {
  const CondensedHertz h(32);
  for (FillReducingOrdering ordering : {FillReducingOrdering::Amd, FillReducingOrdering::Metis}) {
    DofCondensation fast(CondensationMethod::TrailingFactorBlock);
    DofCondensationInput in = h.input();
    in.ordering = ordering;
    ASSERT_TRUE(fast.compute(in).ok());
    const Eigen::VectorXd whole = fast.recover(h.u_c);
    const RecoverySubset subset = fast.subset(h.wanted);
    ASSERT_FALSE(subset.whole_field());
    expect_the_whole_there(h, subset, fast.recover(h.u_c, subset), whole);
    std::printf("[ info     ] ordering %d: %zu of %d equations recovered\n",
                static_cast<int>(ordering), subset.equations.size(), h.dofs().n_free());
    EXPECT_LT(subset.equations.size(), static_cast<std::size_t>(h.dofs().n_free()) / 2);
    EXPECT_THROW(fast.subset({h.dofs().n_free()}), std::invalid_argument);
  }
  // The reference method has no factor to prune: its subset is the whole field.
  DofCondensation reference(CondensationMethod::MultipleRightHandSides);
  ASSERT_TRUE(reference.compute(h.input()).ok());
  const RecoverySubset none = reference.subset(h.wanted);
  EXPECT_TRUE(none.whole_field());
  EXPECT_TRUE(reference.recover(h.u_c, none) == reference.recover(h.u_c));
}

// Requirement (issue 27): from DofCondensationInput::substructure_from vertices the two sides of
// a separator are condensed apart (at once on a spare core) and the separator is eliminated in
// a dense border block. Fails if the sides' Schur complement, condensed load or recovered field
// differ from the one factor's beyond round-off, if the values depend on whether a core was
// idle, or if a subset recovery differs from the whole one, leaves a wanted equation out or
// leaves a stale value (not NaN) outside it.
TEST(ContactCondensation, TwoSidesGiveTheOneFactorValuesOnOneCoreOrTwo) {
  const CondensedHertz h(32);
  const auto condense = [&](int substructure_from, int spare) {
    DofCondensation out(CondensationMethod::TrailingFactorBlock);
    EXPECT_TRUE(
        condense_metis(h, h.elastic.stiffness().K_ff, h.c, substructure_from, out, spare).ok());
    return out;
  };
  const DofCondensation one = condense(kOneFactor, 0);
  const DofCondensation alone = condense(kTwoSides, 0);
  const DofCondensation at_once = condense(kTwoSides, 1);
  ASSERT_FALSE(one.subset(h.wanted).sides.size() == 2);
  const double scale = one.schur().cwiseAbs().maxCoeff();
  EXPECT_LE((alone.schur() - one.schur()).cwiseAbs().maxCoeff(), 1e-10 * scale);
  EXPECT_LE((alone.condensed_load() - one.condensed_load()).norm(),
            1e-10 * one.condensed_load().norm() + 1e-12 * h.f.norm());
  const Eigen::VectorXd u = alone.recover(h.u_c);
  EXPECT_LE((u - one.recover(h.u_c)).norm(), 1e-10 * u.norm());
  EXPECT_TRUE(at_once.schur() == alone.schur());
  EXPECT_TRUE(at_once.condensed_load() == alone.condensed_load());
  EXPECT_TRUE(at_once.recover(h.u_c) == u);
  const RecoverySubset subset = alone.subset(h.wanted);
  ASSERT_EQ(subset.sides.size(), 2u);
  expect_the_whole_there(h, subset, alone.recover(h.u_c, subset), u);
  EXPECT_LT(subset.equations.size(), static_cast<std::size_t>(h.dofs().n_free()) / 2);
  EXPECT_THROW(alone.subset({h.dofs().n_free()}), std::invalid_argument);
}

// Requirement: a body that nothing holds (here the block, its contact DOFs left out of c) is a
// status with its reason, on one factor and on two sides alike. Fails on a crash or an Ok.
TEST(ContactCondensation, ABodyNothingHoldsIsAStatusOnOneFactorOrTwoSides) {
  const CondensedHertz h(16);
  const std::vector<int> indenter_only = free_equations(h.model, h.dofs(), {"indenter.contact"});
  for (int substructure_from : {kOneFactor, kTwoSides}) {
    DofCondensation condensation(CondensationMethod::TrailingFactorBlock);
    const SolveOutcome out = condense_metis(h, h.elastic.stiffness().K_ff, indenter_only,
                                            substructure_from, condensation);
    EXPECT_TRUE(out.status == SolveStatus::NotPositiveDefinite ||
                out.status == SolveStatus::Singular)
        << to_string(out.status);
    EXPECT_NE(out.reason.find("held neither"), std::string::npos) << out.reason;
  }
}

// Requirement: a negative pivot is named by its equation of the whole system, on one factor and
// on two sides (where it fails inside a side's factor, in the side's own numbering). The
// stiffness gets a strongly negative diagonal at one equation of the block's far side, where
// Cholesky must stop. Fails if a side reports its local equation, or another equation.
TEST(ContactCondensation, ANegativePivotIsNamedByItsEquationOnOneFactorOrTwoSides) {
  const CondensedHertz h(16);
  Eigen::SparseMatrix<double> K = h.elastic.stiffness().K_ff;
  const int bad = h.wanted[h.wanted.size() / 2];
  K.coeffRef(bad, bad) = -10.0 * std::abs(K.coeff(bad, bad));
  for (int substructure_from : {kOneFactor, kTwoSides}) {
    DofCondensation condensation(CondensationMethod::TrailingFactorBlock);
    const SolveOutcome out = condense_metis(h, K, h.c, substructure_from, condensation);
    EXPECT_EQ(out.status, SolveStatus::NotPositiveDefinite) << to_string(out.status);
    EXPECT_EQ(out.failed_equation, bad);
    EXPECT_NE(out.reason.find("pivot at equation " + std::to_string(bad)), std::string::npos)
        << out.reason;
  }
}

TEST(ContactCondensation, BothMethodsAgree) {
  for (bool meshed : {false, true}) {
    HertzSpec spec;
    spec.n = 16;
    spec.type = ElementType::Q8;
    spec.meshed_indenter = meshed;
    const Model model = contact_test::hertz_model(spec);
    ContactSettings s = contact_test::settings(ContactDiscretization::SurfaceToSurface,
                                               ContactAlgorithm::LagrangeMultiplier);
    const ContactResult fast = solve_contact(model, contact_test::hertz_pair(spec), s);
    s.condensation = CondensationMethod::MultipleRightHandSides;
    const ContactResult reference = solve_contact(model, contact_test::hertz_pair(spec), s);
    ASSERT_TRUE(fast.converged() && reference.converged());
    const double error =
        (fast.displacement - reference.displacement).norm() / reference.displacement.norm();
    std::printf("[ info     ] H_p Q8 ss LM %s target: trailing block vs multiple RHS %.2e\n",
                meshed ? "meshed" : "rigid", error);
    EXPECT_LE(error, 1e-10);  // round-off (E ratio 1e6 included)
    EXPECT_EQ(fast.active_set_iterations, reference.active_set_iterations);
  }
}

}  // namespace
}  // namespace cs::solver
