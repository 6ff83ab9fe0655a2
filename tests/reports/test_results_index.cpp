// The results the reports read: the sample through the one reader (schema::read_results_file),
// the index over it (problems in the study's order, row kinds, variants, the case behind a
// row), a document built in memory (as `run` hands it over) reported without a file, and bad
// names and records rejected by the schema with a one-line message naming the record.

#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/facts/row_facts.hpp"
#include "reports/results/results_index.hpp"
#include "schema/schema_error.hpp"

namespace cs::reports {
namespace {

using schema::MeshLevel;
using schema::ProblemId;
using schema::Quantity;

TEST(ResultsIndex, ReadsTheHandMadeSample) {
  const schema::ResultsDocument r = schema::read_results_file(testing::sample_path());
  ASSERT_EQ(r.cases.size(), 59u);
  ASSERT_EQ(r.rows.size(), 32u);
  EXPECT_EQ(r.run.jobs, 2);
  EXPECT_EQ(r.run.environment["solver"]["factorization"], "CHOLMOD supernodal");
  const schema::CaseResult* punch = nullptr;
  for (const auto& c : r.cases) {
    if (schema::case_id(c.spec) == "F_p/F/Q4/MPC/ss")
      punch = &c;
  }
  ASSERT_NE(punch, nullptr);
  const auto* q = punch->quantity(Quantity::sigma_c_star);
  ASSERT_NE(q, nullptr);
  EXPECT_TRUE(q->singular());
  EXPECT_FALSE(finite(q->exact).has_value());
  EXPECT_EQ(variant_of(r.rows.back().spec), "extrapolated");
  EXPECT_EQ(r.rows.back().spec.recovery, schema::Recovery::extrapolated);
  EXPECT_EQ(schema::case_key(r.rows.back().spec), "H_p/Q4/LMP/ss/extrapolated");
  EXPECT_EQ(variant_of(r.rows[r.rows.size() - 3].spec), "fkn=10");
  EXPECT_EQ(variant_of(r.rows[r.rows.size() - 5].spec), "rigid");
  EXPECT_EQ(r.rows[0].spec.recovery, schema::Recovery::spr);
  EXPECT_EQ(variant_of(r.rows[0].spec), "");
}

// Requirement: the report's problems are the results' records, in the study's appendix order
// (P'_p, Table 4, before H_p, Table 7), not a list of the report's own.
TEST(ResultsIndex, ProblemsComeFromTheResultsInTheStudysOrder) {
  const testing::Loaded data(testing::sample_json());
  std::vector<ProblemId> ids;
  for (const auto* p : data.index.problems())
    ids.push_back(p->id);
  EXPECT_EQ(ids, (std::vector<ProblemId>{ProblemId::P_p, ProblemId::Pprime_p, ProblemId::H_p,
                                         ProblemId::S_1_3, ProblemId::F_p}));
  EXPECT_TRUE(data.index.singular(ProblemId::F_p));
  EXPECT_FALSE(data.index.singular(ProblemId::H_p));
  EXPECT_EQ(data.index.problem(ProblemId::H_a), nullptr);
  const auto* d = data.index.definition(ProblemId::H_p, Quantity::sigma_h);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->study_row, "horizontal");
  // Reordered in the file, the same order in the report.
  auto doc = testing::sample_json();
  std::reverse(doc["problems"].begin(), doc["problems"].end());
  const testing::Loaded reversed(doc);
  std::vector<ProblemId> again;
  for (const auto* p : reversed.index.problems())
    again.push_back(p->id);
  EXPECT_EQ(again, ids);
}

TEST(ResultsIndex, NullValuesOfAFailedCaseAreEmpty) {
  const testing::Loaded data(testing::sample_json());
  const auto* row = data.index.row(ProblemId::H_p, Quantity::sigma_c, schema::Element::Q8,
                                   {schema::Algorithm::PM, schema::ContactKind::ss});
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(data.index.state(*row, MeshLevel::F), MeshState::failed);
  const schema::CaseResult* c = data.index.case_of(*row, MeshLevel::F);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, schema::CaseStatus::failed);
  EXPECT_FALSE(finite(c->quantity(Quantity::sigma_c)->value).has_value());
  EXPECT_FALSE(row->values[mesh_index(MeshLevel::F)].has_value());
  // The AL row of the same option set has no F case at all.
  const auto* al = data.index.row(ProblemId::H_p, Quantity::sigma_c, schema::Element::Q8,
                                  {schema::Algorithm::AL, schema::ContactKind::ss});
  ASSERT_NE(al, nullptr);
  EXPECT_EQ(data.index.state(*al, MeshLevel::F), MeshState::missing);
}

// Requirement: a document built in memory (what `run` hands to the report) is indexed as read;
// another solver's rows are variants, named by their solver.
TEST(ResultsIndex, IndexesADocumentBuiltInMemory) {
  schema::ResultsDocument doc;
  doc.problems.push_back({ProblemId::S_1_3,
                          "Steuermann punch, r_e/b = 1/3",
                          "",
                          false,
                          false,
                          "11",
                          "Eq. 31",
                          {{Quantity::sigma_c, "", "", "11", "main"}}});
  schema::CaseResult c;
  c.spec.problem = ProblemId::S_1_3;
  c.spec.mesh = MeshLevel::M;
  c.spec.algorithm = schema::Algorithm::MPC;
  c.spec.contact = schema::ContactKind::mortar;
  c.spec.target = schema::TargetKind::Rigid;
  c.status = schema::CaseStatus::not_converged;
  c.quantities.push_back(
      {Quantity::sigma_c, 11.0, 11.2424, -2.16, schema::Grade::g, 11.1, 10.9571});
  doc.cases.push_back(c);
  schema::RowVerdict row;
  row.spec = c.spec;
  row.spec.mesh = MeshLevel::C;
  row.quantity = Quantity::sigma_c;
  row.id = schema::case_key(row.spec) + "/sigma_c";
  row.values[1] = 11.0;
  row.grade = schema::Grade::g;
  row.graded_mesh = MeshLevel::M;
  doc.rows.push_back(row);
  schema::RowVerdict ccx = row;
  ccx.spec.target = schema::TargetKind::Discretized;
  ccx.spec.solver = schema::SolverKind::external;
  ccx.spec.solver_name = "calculix";
  ccx.spec.solver_option = "hard-ss";
  ccx.id = schema::case_key(ccx.spec) + "/sigma_c";
  doc.rows.push_back(ccx);

  const ResultsIndex index(doc);
  EXPECT_TRUE(index.baseline_rows().empty());
  ASSERT_EQ(index.variant_rows().size(), 2u);
  EXPECT_EQ(variant_of(index.variant_rows()[0]->spec), "rigid");
  EXPECT_EQ(variant_of(index.variant_rows()[1]->spec), "@calculix:hard-ss");
  EXPECT_EQ(index.state(row, MeshLevel::M), MeshState::not_converged);
  EXPECT_EQ(index.state(row, MeshLevel::F), MeshState::missing);
  EXPECT_EQ(index.quantity_of(row, MeshLevel::M)->study_exact, 10.9571);
  // The same document through the writer and the reader indexes alike.
  const auto back = schema::results_from_json(schema::to_json(doc), "memory");
  const ResultsIndex again(back);
  EXPECT_EQ(again.variant_rows().size(), 2u);
}

/// The message of the SchemaError that reading `doc` throws ("" if none).
std::string read_error(const nlohmann::json& doc) {
  try {
    schema::results_from_json(doc, "r.json");
  } catch (const schema::SchemaError& e) {
    return e.what();
  }
  return {};
}

// Requirement: names the vocabulary does not know, malformed records and duplicates are
// rejected by the one reader with one line naming the record and the cause.
TEST(ResultsIndex, BadNamesAndRecordsAreRejectedByTheSchema) {
  auto doc = testing::sample_json();
  doc["rows"][2]["converging"] = "yes";
  std::string e = read_error(doc);
  EXPECT_EQ(e.rfind("r.json", 0), 0u) << e;
  EXPECT_NE(e.find("rows[2].converging: is a string"), std::string::npos) << e;
  doc = testing::sample_json();
  doc["cases"][3]["algorithm"] = "LM";
  e = read_error(doc);
  EXPECT_NE(e.find("cases[3].algorithm: unknown algorithm \"LM\" (expected one of: AL, PM, "
                   "LMP, PLM, MPC)"),
            std::string::npos)
      << e;
  doc = testing::sample_json();
  doc["rows"][0]["contact"] = "nts";
  e = read_error(doc);
  EXPECT_NE(e.find("unknown contact \"nts\""), std::string::npos) << e;
  doc = testing::sample_json();
  doc["cases"][0]["quantities"]["sigma_z_max"]["grade"] = "x";
  EXPECT_NE(read_error(doc).find("unknown grade \"x\""), std::string::npos);
  doc = testing::sample_json();
  doc["problems"][0]["id"] = "Q_p";
  EXPECT_NE(read_error(doc).find("unknown problem \"Q_p\""), std::string::npos);
  doc = testing::sample_json();
  doc["cases"][0]["quantities"]["sigma_z_max"]["value"] = "1.0";
  EXPECT_NE(read_error(doc).find("cases[0].quantities.sigma_z_max.value"), std::string::npos);
  doc = testing::sample_json();
  doc["cases"][12]["profile"]["x_over_a"] = {0.0};  // an H_p case: 13 points
  EXPECT_NE(read_error(doc).find("differ in length"), std::string::npos);
  doc = testing::sample_json();
  doc["cases"].push_back(doc["cases"][5]);
  EXPECT_NE(read_error(doc).find("duplicate case id \"P_p/F/Q4/LMP/ss\""), std::string::npos);
  doc = testing::sample_json();
  doc["problems"].erase(0);
  EXPECT_NE(read_error(doc).find("has no entry in 'problems'"), std::string::npos);
  doc = testing::sample_json();
  doc.erase("run");
  EXPECT_NE(read_error(doc).find("missing 'run'"), std::string::npos);
  for (const std::string& message : {e, read_error(doc)})
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Requirement: a quantity read between two nodes (a_FE) is judged against half the node spacing
// on C (Q8: its mid-side nodes halve it), so a move by less than that is settled, not
// "converging" with an order; a quantity read at a point keeps the 0.01-point floor.
TEST(ResultsIndex, AValueReadBetweenNodesIsJudgedAgainstHalfANodeSpacing) {
  auto doc = testing::sample_json();
  const std::map<std::string, double> a_fe{{"C", 1.09}, {"M", 1.08}, {"F", 1.07}};
  for (auto& c : doc["cases"]) {
    const std::string id = c["id"];
    if (id.starts_with("H_p/") && id.ends_with("/Q4/LMP/ss")) {
      const double v = a_fe.at(std::string(c["mesh"]));
      c["quantities"]["contact_half_width"] = {
          {"value", v}, {"exact", 1.0}, {"error_percent", 100.0 * (v - 1.0)}, {"grade", "g"}};
    }
    if (id == "H_p/C/Q8/AL/ss")  // Q8, and an exact value other than 1
      c["quantities"]["contact_half_width"] = {
          {"value", 0.85}, {"exact", 0.8}, {"error_percent", 6.25}, {"grade", "s"}};
  }
  nlohmann::json row = doc["rows"][0];
  row["id"] = "H_p/Q4/LMP/ss/contact_half_width";
  row["problem"] = "H_p";
  row["algorithm"] = "LMP";
  row["quantity"] = "contact_half_width";
  row["values"] = a_fe;
  row["error_percent"] = {{"C", 9.0}, {"M", 8.0}, {"F", 7.0}};
  doc["rows"].push_back(row);
  row["id"] = "H_p/Q8/AL/ss/contact_half_width";
  row["element"] = "Q8";
  row["algorithm"] = "AL";
  row["values"] = {{"C", 0.85}};
  row["error_percent"] = {{"C", 6.25}};
  doc["rows"].push_back(row);
  const testing::Loaded data(doc);
  const auto* r = data.index.row(ProblemId::H_p, Quantity::contact_half_width, schema::Element::Q4,
                                 {schema::Algorithm::LMP, schema::ContactKind::ss});
  ASSERT_NE(r, nullptr);
  // Nodes 0.125 a apart on C: half of that is 6.25 % of a; on F, 1.5625 %.
  EXPECT_DOUBLE_EQ(data.index.read_resolution_percent(*r, MeshLevel::C), 6.25);
  EXPECT_DOUBLE_EQ(data.index.read_resolution_percent(*r, MeshLevel::F), 1.5625);
  const RowFacts f = facts_of_row(data.index, *r);
  ASSERT_TRUE(f.trend.has_value());
  // 9 -> 8 -> 7 % moves by 1 < 6.25 points (read at a point: converging, order 0.18).
  EXPECT_EQ(f.trend->trend, schema::Trend::settled);
  EXPECT_FALSE(f.order.has_value());
  // Q8's mid-side nodes halve the spacing, and the resolution is relative to the exact value:
  // nodes 0.0625 apart on C, half of that over 0.8 is 3.90625 %.
  const auto* q8 = data.index.row(ProblemId::H_p, Quantity::contact_half_width, schema::Element::Q8,
                                  {schema::Algorithm::AL, schema::ContactKind::ss});
  ASSERT_NE(q8, nullptr);
  EXPECT_DOUBLE_EQ(data.index.read_resolution_percent(*q8, MeshLevel::C), 3.90625);
  // A quantity read at a point has no such floor.
  const auto* sigma = data.index.row(ProblemId::H_p, Quantity::sigma_c, schema::Element::Q4,
                                     {schema::Algorithm::LMP, schema::ContactKind::ss});
  ASSERT_NE(sigma, nullptr);
  EXPECT_EQ(data.index.read_resolution_percent(*sigma, MeshLevel::C), 0.0);
}

}  // namespace
}  // namespace cs::reports
