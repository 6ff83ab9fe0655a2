// results.csv: one row per case and quantity, with the study's value where it printed one.

#include <algorithm>
#include <sstream>

#include <gtest/gtest.h>

#include "grading/convergence.hpp"
#include "grading/divergence.hpp"
#include "report_test_support.hpp"
#include "reports/results/results_csv.hpp"

namespace cs::reports {
namespace {

using testing::Loaded;
using testing::sample_json;
using testing::study;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}

TEST(ResultsCsv, OneRowPerCaseAndQuantity) {
  auto doc = sample_json();
  std::size_t expected = 0;
  for (const auto& c : doc["cases"])
    expected += c["quantities"].size();
  const Loaded data(doc);
  const auto lines = lines_of(results_csv(data.index, study()));
  ASSERT_EQ(lines.size(), expected + 1);
  EXPECT_EQ(
      lines[0].rfind(
          "case_id,problem,mesh,element,algorithm,contact,target,recovery,overrides,status,", 0),
      0u);
  // The H_p fine AL ss contact stress, beside the study's Table 7a value.
  bool found = false;
  for (const auto& l : lines) {
    if (l.rfind("H_p/F/Q4/AL/ss,", 0) == 0 && l.find(",sigma_c,") != std::string::npos) {
      found = true;
      EXPECT_NE(l.find(",1.273,1.273239545,"), std::string::npos) << l;
      EXPECT_NE(l.find(",1.2737,7a"), std::string::npos) << l;
    }
  }
  EXPECT_TRUE(found);
}

TEST(ResultsCsv, CasesWithoutQuantitiesKeepARowAndReasonsAreQuoted) {
  auto doc = sample_json();
  for (auto& c : doc["cases"]) {
    if (c["id"] == "H_p/F/Q8/PM/ss") {
      c["quantities"] = nlohmann::json::object();
      c["reason"] = "singular matrix, \"pivot\" 12";
    }
  }
  const Loaded data(doc);
  const auto lines = lines_of(results_csv(data.index, study()));
  int rows = 0;
  for (const auto& l : lines) {
    if (l.rfind("H_p/F/Q8/PM/ss,", 0) == 0) {
      ++rows;
      EXPECT_NE(l.find(",failed,\"singular matrix, \"\"pivot\"\" 12\","), std::string::npos) << l;
    }
  }
  EXPECT_EQ(rows, 1);
}

/// The fields of a CSV line (no quoted commas in the lines this test reads).
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');)
    out.push_back(f);
  if (!line.empty() && line.back() == ',')
    out.emplace_back();
  return out;
}

// Requirement: every line repeats the verdicts of the row its case belongs to, computed by the
// grading layer: the study's c and the noise-aware trend for a nonsingular row, Eq. 47 and the
// strict verdict for a singular one; none for a row with a case that did not converge.
TEST(ResultsCsv, CarriesTheRowsVerdicts) {
  const Loaded data(sample_json());
  const auto lines = lines_of(results_csv(data.index, study()));
  const auto header = fields_of(lines[0]);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(column("strict_divergence"), header.size());
  int nonsingular = 0, singular = 0, not_converged = 0;
  for (const schema::RowVerdict* r : data.index.baseline_rows()) {
    const schema::CaseResult* c = data.index.case_of(*r, schema::MeshLevel::F);
    if (c == nullptr || !ResultsIndex::complete(*r))
      continue;
    const std::string prefix = schema::case_id(c->spec) + ",";
    for (const auto& l : lines) {
      const auto f = fields_of(l);
      if (l.rfind(prefix, 0) != 0 || f[column("quantity")] != schema::to_string(r->quantity))
        continue;
      if (data.index.any_not_converged(*r)) {  // last iterates: no verdict
        EXPECT_EQ(f[column("converging")] + f[column("trend")] + f[column("eq47")], "") << l;
        ++not_converged;
      } else if (data.index.singular(r->spec.problem)) {
        const auto d = grading::divergence_verdict(*r->values[0], *r->values[1], *r->values[2]);
        EXPECT_EQ(f[column("eq47")], d.eq47 ? "true" : "false") << l;
        EXPECT_EQ(f[column("strict_divergence")], d.diverges ? "true" : "false") << l;
        EXPECT_EQ(f[column("trend")], "") << l;
        ++singular;
      } else {
        const auto t = grading::assess_convergence(*r->errors[0], *r->errors[1], *r->errors[2]);
        EXPECT_EQ(f[column("trend")], schema::to_string(t.trend)) << l;
        EXPECT_EQ(f[column("converging")], r->converging.value_or(false) ? "true" : "false") << l;
        EXPECT_EQ(f[column("eq47")], "") << l;
        ++nonsingular;
      }
    }
  }
  EXPECT_GT(nonsingular, 0);
  EXPECT_GT(singular, 0);
  EXPECT_GT(not_converged, 0);
}

// Requirement: a case that did not converge has no grade, and the row it belongs to no verdicts
// on any of its meshes (its values are last iterates): status and error stay, to be read.
TEST(ResultsCsv, NoGradeOrVerdictFromACaseThatDidNotConverge) {
  auto doc = sample_json();
  for (auto& c : doc["cases"]) {
    if (c["id"] == "H_p/F/Q4/AL/ss")
      c["status"] = "not_converged";
  }
  const Loaded data(doc);
  const auto lines = lines_of(results_csv(data.index, study()));
  const auto header = fields_of(lines[0]);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  int fine = 0, coarser = 0;
  for (const auto& l : lines) {
    const auto f = fields_of(l);
    if (f[column("quantity")] != "sigma_c")
      continue;
    if (l.rfind("H_p/F/Q4/AL/ss,", 0) == 0) {
      ++fine;
      EXPECT_EQ(f[column("status")], "not_converged") << l;
      EXPECT_EQ(f[column("grade")], "") << l;
      EXPECT_NE(f[column("error_percent")], "") << l;
    }
    if (l.rfind("H_p/F/Q4/AL/ss,", 0) == 0 || l.rfind("H_p/M/Q4/AL/ss,", 0) == 0) {
      coarser += l.rfind("H_p/M/", 0) == 0 ? 1 : 0;
      EXPECT_EQ(f[column("converging")], "") << l;
      EXPECT_EQ(f[column("trend")], "") << l;
    }
    if (l.rfind("H_p/F/Q4/AL/ns,", 0) == 0) {  // its twin converged: graded as before
      EXPECT_NE(f[column("converging")], "") << l;
    }
  }
  EXPECT_EQ(fine, 1);
  EXPECT_EQ(coarser, 1);
}

}  // namespace
}  // namespace cs::reports
