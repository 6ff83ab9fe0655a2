// Tables 2a/2b from the hand-made results file: our grade beside the study's, option sets
// merged only when their results coincide, missing cells and absent rows marked.

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/tables/grade_tables.hpp"

namespace cs::reports {
namespace {

using schema::Element;
using testing::Loaded;
using testing::sample_json;
using testing::study;

TEST(GradeTables, OurGradeBesideTheStudysTable2aGrade) {
  const Loaded data(sample_json());
  const auto table = build_grade_table(data.index, study(), Element::Q4);
  ASSERT_TRUE(table.has_value());
  // Study Table 2a: P_p AL, PM (ss) "e, c"; H_p contact AL, PM (ns) "u"; S(1/3) "u, c".
  EXPECT_EQ(table->cell("P<sub>p</sub>", "AL = PM (ss)"), "e, c │ ANSYS e, c");
  EXPECT_EQ(table->cell("H<sub>p</sub> (contact)", "AL (ns)"), "g, c │ ANSYS u");
  EXPECT_EQ(table->cell("H<sub>p</sub> (horizontal)", "AL (ns)"), "s │ ANSYS u");
  // The study graded S(1/3) against its printed 10.9571; ANSYS's F value 9.5320 re-graded
  // against the physical 11.2424 (−15.2 %) is still u.
  EXPECT_EQ(table->cell("S(1/3)", "AL = PM (ss)"), "u, c │ ANSYS u, c (phys. u)");
  // LMP ss on P_p: excellent but not converging, as the study's LMP, PLM "e".
  EXPECT_EQ(table->cell("P<sub>p</sub>", "LMP = PLM (ss)"), "e │ ANSYS e");
  // MPC's fine mesh did not converge: marked "!"; the study's IMC column is "u".
  EXPECT_EQ(table->cell("H<sub>p</sub> (contact)", "MPC (ss)"), "u! │ ANSYS u");
  // Mortar: no study counterpart.
  EXPECT_EQ(table->cell("H<sub>p</sub> (contact)", "LMP (mortar)"), "e, c");
}

TEST(GradeTables, SubsetHasNoEmptyShellsAndMarksMissingCells) {
  const Loaded data(sample_json());
  const auto table = build_grade_table(data.index, study(), Element::Q4);
  ASSERT_TRUE(table.has_value());
  // Rows not run are left out of the table ...
  EXPECT_FALSE(table->cell("H<sub>a</sub>", "AL = PM (ss)").has_value());
  EXPECT_FALSE(table->cell("P<sub>a</sub>", "AL = PM (ss)").has_value());
  // ... and named in a note.
  bool named = false;
  for (const auto& n : table->notes) {
    named = named ||
            (n.find("not in this results file") != std::string::npos &&
             n.find("H<sub>a</sub>") != std::string::npos && n.find("S(1/7)") != std::string::npos);
  }
  EXPECT_TRUE(named);
  // A cell of a present row and column that was not run is marked, beside the study's grade.
  EXPECT_EQ(table->cell("P<sub>p</sub>", "MPC (ss)"), "— │ ANSYS u");
  EXPECT_EQ(table->cell("P<sub>p</sub>", "AL (ns)"), "— │ ANSYS s");
}

TEST(GradeTables, FineMeshMissingOrFailedIsGradedOnMediumAndMarked) {
  const Loaded data(sample_json());
  const auto table = build_grade_table(data.index, study(), Element::Q8);
  ASSERT_TRUE(table.has_value());
  // AL's F case is missing and PM's failed: they did not end alike, so two columns.
  EXPECT_EQ(table->cell("H<sub>p</sub> (contact)", "AL (ss)"), "e (M)* │ ANSYS e, c");
  EXPECT_EQ(table->cell("H<sub>p</sub> (contact)", "PM (ss)"), "e (M)* │ ANSYS e, c");
  EXPECT_FALSE(table->cell("H<sub>p</sub> (contact)", "AL = PM (ss)").has_value());
  // An element with no case has no table.
  auto q4_only = sample_json();
  for (const char* key : {"cases", "rows"}) {
    auto& list = q4_only[key];
    for (auto it = list.begin(); it != list.end();)
      it = (*it)["element"] == "Q8" ? list.erase(it) : it + 1;
  }
  const Loaded q4(q4_only);
  EXPECT_FALSE(build_grade_table(q4.index, study(), Element::Q8).has_value());
  EXPECT_TRUE(build_grade_table(q4.index, study(), Element::Q4).has_value());
}

// Requirement: the rows of Table 2 come from the problems' quantity definitions (`study_row`) in
// battery order; the study's rows of problems not in the results are named as absent.
TEST(GradeTables, RowsComeFromTheProblemsQuantityDefinitions) {
  const Loaded data(sample_json());
  std::vector<std::string> labels;
  for (const auto& r : grade_table_rows(data.index, study()))
    labels.push_back(r.label_md + (r.quantity ? "" : " (absent)"));
  EXPECT_EQ(labels,
            (std::vector<std::string>{"P<sub>p</sub>", "P<sub>a</sub> (absent)", "P′<sub>p</sub>",
                                      "P′<sub>a</sub> (absent)", "H<sub>p</sub> (contact)",
                                      "H<sub>p</sub> (horizontal)", "H<sub>a</sub> (absent)",
                                      "S(1) (absent)", "S(1/3)", "S(1/7) (absent)"}));
  // A problem whose descriptor gives no Table 2 row has none (F_p, singular, and here S(1/3)).
  auto doc = sample_json();
  for (auto& p : doc["problems"]) {
    if (p["id"] == "S_1_3")
      p["quantities"][0]["study_row"] = "";
  }
  const Loaded edited(doc);
  const auto table = build_grade_table(edited.index, study(), Element::Q4);
  ASSERT_TRUE(table.has_value());
  EXPECT_FALSE(table->cell("S(1/3)", "AL = PM (ss)").has_value());
  EXPECT_TRUE(table->cell("P<sub>p</sub>", "AL = PM (ss)").has_value());
}

TEST(GradeTables, AlgorithmsAreMergedOnlyWhenTheirResultsCoincide) {
  auto doc = sample_json();
  {
    const Loaded data(doc);
    const auto table = build_grade_table(data.index, study(), Element::Q4);
    ASSERT_TRUE(table.has_value());
    EXPECT_TRUE(table->cell("H<sub>p</sub> (contact)", "AL = PM (ss)").has_value());
    bool stated = false;
    for (const auto& n : table->notes) {
      stated =
          stated || n.rfind("LMP and PLM (ss), the same method without friction, coincide", 0) == 0;
    }
    EXPECT_TRUE(stated);
  }
  // PM's coarse value moves by 0.5 %: AL and PM now get a column each, and a note says so.
  testing::set_value(doc, "H_p/C/Q4/PM/ss", "sigma_c", 1.2650 * 1.005);
  testing::set_value(doc, "H_p/C/Q4/LMP/ss", "sigma_c", 1.3100 * 1.002);
  const Loaded data(doc);
  const auto table = build_grade_table(data.index, study(), Element::Q4);
  ASSERT_TRUE(table.has_value());
  EXPECT_FALSE(table->cell("H<sub>p</sub> (contact)", "AL = PM (ss)").has_value());
  EXPECT_EQ(table->cell("H<sub>p</sub> (contact)", "AL (ss)"), "e, c │ ANSYS e, c");
  EXPECT_EQ(table->cell("H<sub>p</sub> (contact)", "PM (ss)"), "e, c │ ANSYS e, c");
  EXPECT_TRUE(table->cell("H<sub>p</sub> (contact)", "PLM (ss)").has_value());
  bool al_pm = false, lmp_plm_same_method = false;
  for (const auto& n : table->notes) {
    al_pm = al_pm || n.rfind("AL and PM (ss) differ on 1 of 2 rows", 0) == 0;
    lmp_plm_same_method = lmp_plm_same_method || n.find("same method") != std::string::npos;
  }
  EXPECT_TRUE(al_pm);
  EXPECT_FALSE(lmp_plm_same_method);
}

TEST(GradeTables, CountsAgreementWithTheStudy) {
  const Loaded data(sample_json());
  const auto table = build_grade_table(data.index, study(), Element::Q4);
  ASSERT_TRUE(table.has_value());
  // Graded by both: P_p (AL=PM ss e/e, LMP=PLM e/e), P'_p (AL=PM ss g/g), H_p contact
  // (e/e, g/u, e/g, u/u), H_p horizontal (g/g, s/u, g/s, u/u), S(1/3) (u/u, e/g).
  EXPECT_EQ(table->cells_compared, 13);
  EXPECT_EQ(table->cells_same, 8);
  EXPECT_EQ(table->cells_better, 5);
  EXPECT_EQ(table->cells_worse, 0);
}

TEST(GradeTables, MarkdownHasTheTitleAndLegend) {
  const Loaded data(sample_json());
  const std::string md = grade_tables_section(data.index, study());
  EXPECT_NE(md.find("Table 2a′"), std::string::npos);
  EXPECT_NE(md.find("Table 2b′"), std::string::npos);
  EXPECT_NE(md.find("| P<sub>p</sub> | e, c │ ANSYS e, c |"), std::string::npos);
}

}  // namespace
}  // namespace cs::reports
