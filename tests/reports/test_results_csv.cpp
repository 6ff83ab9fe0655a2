// results.csv: one row per case and quantity, with the study's value where it printed one.

#include <sstream>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace cs::reports
