// The engine on real problems: one and two workers give bit-identical graded values, and the
// patch tests are exact with mortar (the study's P and P' rows on the coarse mesh).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "schema/results_file.hpp"
#include "suites/case_matrix.hpp"
#include "suites/problem_executor.hpp"
#include "support/tolerance.hpp"

namespace cs::suites {
namespace {

TEST(EngineDeterminism, OneAndTwoWorkersGiveIdenticalValuesOnRealProblems) {
  CaseSelection sel;
  sel.problems = {ProblemId::P_p, ProblemId::Pprime_a, ProblemId::H_p, ProblemId::F_a};
  sel.meshes = {MeshLevel::C};
  sel.algorithms = {Algorithm::AL, Algorithm::LMP, Algorithm::MPC};
  sel.contacts = {ContactKind::ss, ContactKind::ns, ContactKind::mortar};
  const auto cases = make_case_matrix(sel);
  RunnerOptions one, two;
  one.jobs = 1;
  two.jobs = 2;
  const auto a = run_cases(cases, make_problem_executor, one);
  const auto b = run_cases(cases, make_problem_executor, two);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].status, CaseStatus::converged) << case_id(a[i].spec) << ": " << a[i].reason;
    EXPECT_EQ(a[i].status, b[i].status);
    ASSERT_EQ(a[i].quantities.size(), b[i].quantities.size());
    for (std::size_t q = 0; q < a[i].quantities.size(); ++q) {
      // Bit-identical: the same arithmetic in the same order, whatever the worker count.
      EXPECT_EQ(a[i].quantities[q].value, b[i].quantities[q].value) << case_id(a[i].spec);
    }
  }
}

// Requirement (issue 27): a case recovers the displacement only where its grading reads it (the
// sampled surface's patches, the contact rows, the support under load control), by a backward
// solve over part of the factor, and grades exactly as with the whole field. Fails if any value,
// profile point or interface check of a case differs in any bit, e.g. a node the grading reads
// left out of the subset (NaN) or a subset solved in another order than CHOLMOD's.
TEST(EngineDeterminism, CasesRecoveringOnlyWhatTheyReadGradeAsWithTheWholeField) {
  CaseSelection sel;
  sel.problems = {ProblemId::H_p, ProblemId::S_1, ProblemId::F_a, ProblemId::IF_p};
  sel.meshes = {MeshLevel::C};
  sel.elements = {Element::Q4, Element::Q8};
  sel.algorithms = {Algorithm::AL, Algorithm::LMP, Algorithm::MPC};
  sel.contacts = {ContactKind::ss, ContactKind::ns, ContactKind::mortar};
  sel.recoveries = {Recovery::spr, Recovery::extrapolated};
  auto cases = make_case_matrix(sel);
  // The frictional problems: load steps, the slips read through the tangential rows.
  CaseSelection friction;
  friction.problems = {ProblemId::FP_p, ProblemId::CM_p};
  friction.meshes = {MeshLevel::C};
  friction.elements = {Element::Q4};
  friction.algorithms = {Algorithm::AL, Algorithm::LMP};
  friction.contacts = {ContactKind::ss, ContactKind::ns, ContactKind::mortar};
  const auto frictional = make_case_matrix(friction);
  cases.insert(cases.end(), frictional.begin(), frictional.end());
  RunnerOptions options;
  options.jobs = 1;
  const auto part = run_cases(cases, make_problem_executor, options);
  const auto whole = run_cases(
      cases,
      [](const CaseSpec& s) {
        auto executor = std::make_unique<ProblemExecutor>(s);
        executor->recover_whole_field();
        return executor;
      },
      options);
  ASSERT_EQ(part.size(), whole.size());
  for (std::size_t i = 0; i < part.size(); ++i) {
    ASSERT_EQ(part[i].status, CaseStatus::converged)
        << case_id(part[i].spec) << ": " << part[i].reason;
    nlohmann::json a = schema::to_json(part[i]), b = schema::to_json(whole[i]);
    for (auto* j : {&a, &b}) {
      j->erase("wall_seconds");
      j->erase("peak_rss_mb");
    }
    EXPECT_EQ(a, b) << case_id(part[i].spec);
  }
  // The two runs did differ in what they recovered: the default leaves most of the field
  // unknown (NaN) and refuses whole-mesh stresses; the whole field is finite everywhere.
  for (const CaseSpec& spec : {cases.front(), frictional.front()}) {
    ProblemExecutor partial(spec), full(spec);
    full.recover_whole_field();
    ASSERT_EQ(partial.run(spec).status, CaseStatus::converged) << case_id(spec);
    ASSERT_EQ(full.run(spec).status, CaseStatus::converged) << case_id(spec);
    const Eigen::VectorXd& u = partial.last_displacement();
    const auto unknown = std::count_if(u.begin(), u.end(), [](double v) { return std::isnan(v); });
    EXPECT_GT(unknown, 0) << case_id(spec);
    EXPECT_LT(unknown, u.size()) << case_id(spec);
    EXPECT_THROW(partial.last_stresses(), std::logic_error) << case_id(spec);
    EXPECT_TRUE(full.last_displacement().allFinite()) << case_id(spec);
    EXPECT_TRUE(full.last_stresses().has_value()) << case_id(spec);
  }
}

/// A case's JSON but for what only its clock gives.
nlohmann::json graded(const CaseResult& r) {
  nlohmann::json j = schema::to_json(r);
  j.erase("wall_seconds");
  j.erase("peak_rss_mb");
  return j;
}

// Requirement (issue 27): a model's cases add little to the factorization they share; a case
// whose solve would repeat a recent one's step for step (PLM after LMP without friction, PM after
// an AL that needed no augmentation: solver::repeats_solve) takes that result. Every case must
// grade exactly as when solved alone, on plain, load-controlled (rigid Steuermann punch) and
// load-stepped frictional models. Fails if a case took a result it would not have solved to, or
// if no case is spared a solve.
TEST(EngineDeterminism, CasesThatRepeatASolveGradeAsIfSolvedAlone) {
  CaseSelection sel;
  sel.problems = {ProblemId::H_p, ProblemId::Pprime_a};
  sel.meshes = {MeshLevel::C};
  sel.elements = {Element::Q4};
  sel.contacts = {ContactKind::ss, ContactKind::ns, ContactKind::mortar};
  sel.recoveries = {Recovery::spr, Recovery::extrapolated};
  std::vector<std::vector<CaseSpec>> models{make_case_matrix(sel)};
  sel.problems = {ProblemId::S_1};
  sel.target = TargetKind::Rigid;
  models.push_back(make_case_matrix(sel));
  sel.problems = {ProblemId::FP_p};
  sel.target = TargetKind::Discretized;
  models.push_back(make_case_matrix(sel));
  for (const auto& cases : models) {
    std::map<std::string, std::vector<CaseSpec>> by_model;
    for (const CaseSpec& spec : cases)
      by_model[fmt::format("{} {}", to_string(spec.problem), to_string(spec.element))].push_back(
          spec);
    for (const auto& [name, specs] : by_model) {
      ProblemExecutor shared(specs.front());
      for (const CaseSpec& spec : specs) {
        const CaseResult in_model = shared.run(spec);
        if (spec.algorithm != Algorithm::PM && spec.algorithm != Algorithm::PLM)
          continue;  // the ones that may repeat an earlier solve
        ProblemExecutor alone(spec);
        EXPECT_EQ(graded(in_model), graded(alone.run(spec))) << case_id(spec);
      }
      // Two recoveries of three discretizations per algorithm: without friction PLM repeats LMP
      // and, where AL needs no augmentation (FKN = 1 on these meshes), PM repeats AL.
      std::printf("[ info     ] %s: %zu cases, %d contact solves\n", name.c_str(), specs.size(),
                  shared.contact_solves());
      const bool frictional = specs.front().problem == ProblemId::FP_p;
      EXPECT_EQ(shared.contact_solves(), frictional ? 12 : 9) << name;
    }
  }
}

TEST(EngineDeterminism, MortarPatchTestsAreExact) {
  for (ProblemId p : {ProblemId::P_p, ProblemId::Pprime_p, ProblemId::P_a, ProblemId::Pprime_a}) {
    for (Element e : {Element::Q4, Element::Q8}) {
      CaseSpec spec{.problem = p,
                    .mesh = MeshLevel::C,
                    .element = e,
                    .algorithm = Algorithm::LMP,
                    .contact = ContactKind::mortar,
                    .overrides = {}};
      ProblemExecutor executor(spec);
      const CaseResult r = executor.run(spec);
      ASSERT_EQ(r.status, CaseStatus::converged) << case_id(spec) << ": " << r.reason;
      // Uniform sigma_z = -p is in the discrete space: exact up to round-off amplified by the
      // 1e6 stiffness ratio of the meshed indenter.
      EXPECT_TRUE(cs::testing::Near(r.quantities[0].value, 1.0, {1e-8, 0.0})) << case_id(spec);
      ASSERT_TRUE(r.quantities[0].contact_pressure.has_value());
      EXPECT_TRUE(cs::testing::Near(*r.quantities[0].contact_pressure, 1.0, {1e-8, 0.0}))
          << case_id(spec);
    }
  }
}

}  // namespace
}  // namespace cs::suites
