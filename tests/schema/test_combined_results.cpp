// Requirement: a report can draw on several results files (the main job, sweeps, another
// solver's battery) read as one document. Cases and rows are kept in order, problems united,
// the first file's run is the run. A case or row in two files must be the same analysis run
// twice (a refinement run repeats the main job's C, M, F cases): with other values it is refused
// with one line naming it and both files; with the same values it is kept once, and the row takes
// the refinement record (M-F-VF) of the file that has one. One file given twice is refused.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "schema/combined_results.hpp"
#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

ResultsDocument one_case(const std::string& source, ProblemId problem, MeshLevel mesh,
                         double wall_seconds) {
  ResultsDocument doc;
  doc.source = source;
  doc.run.wall_seconds = wall_seconds;
  ProblemRecord p;
  p.id = problem;
  p.title = std::string(to_string(problem));
  doc.problems.push_back(p);
  CaseResult c;
  c.spec.problem = problem;
  c.spec.mesh = mesh;
  c.status = CaseStatus::converged;
  QuantityResult q;
  q.quantity = Quantity::sigma_c;
  q.value = 1.25;
  c.quantities.push_back(q);
  doc.cases.push_back(c);
  RowVerdict row;
  row.spec = c.spec;
  row.spec.mesh = MeshLevel::C;
  row.id = case_key(row.spec) + "/sigma_c";
  row.values = {1.25, 1.25, 1.25};
  doc.rows.push_back(row);
  return doc;
}

TEST(CombinedResults, KeepsEveryCaseAndTheFirstRun) {
  const ResultsDocument all =
      combine_results({one_case("main.json", ProblemId::H_p, MeshLevel::C, 10),
                       one_case("sweep.json", ProblemId::F_p, MeshLevel::M, 3),
                       one_case("more.json", ProblemId::P_p, MeshLevel::F, 4)});
  ASSERT_EQ(all.cases.size(), 3u);
  EXPECT_EQ(all.cases[0].spec.problem, ProblemId::H_p);
  EXPECT_EQ(all.cases[2].spec.problem, ProblemId::P_p);
  EXPECT_EQ(all.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(all.run.wall_seconds, 10.0);
  ASSERT_EQ(all.added_runs.size(), 2u);
  EXPECT_EQ(all.added_runs[0].first, "sweep.json");
  EXPECT_DOUBLE_EQ(all.added_runs[1].second.wall_seconds, 4.0);
  ASSERT_EQ(all.problems.size(), 3u);
  EXPECT_EQ(all.problems[0].id, ProblemId::P_p);  // battery order, not file order
  EXPECT_NE(all.problem(ProblemId::F_p), nullptr);
}

TEST(CombinedResults, OneProblemInTwoFilesIsOneRecord) {
  ResultsDocument b = one_case("b.json", ProblemId::H_p, MeshLevel::M, 1);
  b.cases[0].spec.algorithm = Algorithm::AL;
  b.rows[0].spec.algorithm = Algorithm::AL;
  b.rows[0].id = case_key(b.rows[0].spec) + "/sigma_c";
  const ResultsDocument all =
      combine_results({one_case("a.json", ProblemId::H_p, MeshLevel::C, 1), std::move(b)});
  EXPECT_EQ(all.problems.size(), 1u);
  EXPECT_EQ(all.cases.size(), 2u);
}

TEST(CombinedResults, ACaseInTwoFilesWithOtherValuesIsRefusedByName) {
  ResultsDocument b = one_case("b.json", ProblemId::H_p, MeshLevel::C, 1);
  b.cases[0].quantities[0].value = 1.25 * (1.0 + 1e-7);  // not round-off: another analysis
  try {
    combine_results({one_case("a.json", ProblemId::H_p, MeshLevel::C, 1), std::move(b)});
    ADD_FAILURE() << "accepted a case with two values";
  } catch (const SchemaError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("H_p/C/"), std::string::npos) << m;
    EXPECT_NE(m.find("a.json"), std::string::npos) << m;
    EXPECT_NE(m.find("b.json"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  EXPECT_THROW(combine_results({}), SchemaError);
  EXPECT_THROW(combine_results({one_case("a.json", ProblemId::H_p, MeshLevel::C, 1),
                                one_case("a.json", ProblemId::P_p, MeshLevel::C, 1)}),
               SchemaError);
}

// Requirement: a failed case (no value: NaN) in both files is the same analysis run twice, as a
// refinement run repeats the main job's cases, not "two values". Fails if NaN != NaN refuses it.
TEST(CombinedResults, AFailedCaseInTwoFilesIsOneCase) {
  const auto failed = [](const std::string& source) {
    ResultsDocument d = one_case(source, ProblemId::H_p, MeshLevel::C, 1);
    d.cases[0].status = CaseStatus::failed;
    d.cases[0].quantities[0].value = std::nan("");
    d.rows[0].values = {std::nullopt, std::nullopt, std::nullopt};
    return d;
  };
  const ResultsDocument both = combine_results({failed("a.json"), failed("b.json")});
  EXPECT_EQ(both.cases.size(), 1u);
  ResultsDocument valued = one_case("c.json", ProblemId::H_p, MeshLevel::C, 1);
  valued.rows[0].values = {std::nullopt, std::nullopt, std::nullopt};
  EXPECT_THROW(combine_results({failed("a.json"), valued}), SchemaError);  // NaN against 1.25
}

TEST(CombinedResults, TheSameAnalysesTwiceAreKeptOnceWithTheRefinementRecord) {
  ResultsDocument refine = one_case("refine.json", ProblemId::H_p, MeshLevel::C, 1);
  refine.cases[0].quantities[0].value = 1.25 * (1.0 + 1e-12);  // round-off of another run
  refine.rows[0].refinement = RefinementVerdict{};
  refine.rows[0].refinement->value = 1.2501;  // the VF value
  CaseResult vf = refine.cases[0];
  vf.spec.mesh = MeshLevel::VF;
  refine.cases.push_back(vf);
  const ResultsDocument all =
      combine_results({one_case("main.json", ProblemId::H_p, MeshLevel::C, 1), std::move(refine)});
  ASSERT_EQ(all.cases.size(), 2u);  // C once, and VF
  EXPECT_EQ(all.cases[1].spec.mesh, MeshLevel::VF);
  ASSERT_EQ(all.rows.size(), 1u);
  ASSERT_TRUE(all.rows[0].refinement.has_value());
  EXPECT_DOUBLE_EQ(*all.rows[0].refinement->value, 1.2501);
}

}  // namespace
}  // namespace cs::schema
