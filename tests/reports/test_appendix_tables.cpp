// Appendix tables (the study's Tables 3-14 layout): our value and error beside the study's
// printed ANSYS value, exact values above each group, missing and failed cases marked.

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/report_error.hpp"
#include "reports/tables/appendix_tables.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::Element;
using schema::MeshLevel;
using schema::ProblemId;
using schema::Quantity;
using testing::Loaded;
using testing::sample_json;
using testing::study;

constexpr MeshLevel C = MeshLevel::C, M = MeshLevel::M, F = MeshLevel::F;

std::optional<std::string> cell(const AppendixTableFacts& t, MeshLevel mesh,
                                const std::string& column) {
  return t.table.cell(std::string(schema::to_string(mesh)), column);
}

const AppendixTableFacts* find_table(const std::vector<AppendixTableFacts>& tables,
                                     ProblemId problem, Quantity quantity, Element element,
                                     ContactKind contact) {
  for (const auto& t : tables) {
    if (t.problem == problem && t.quantity == quantity && t.element == element &&
        t.contact == contact)
      return &t;
  }
  return nullptr;
}

TEST(AppendixTables, OurValueBesideTheStudysValue) {
  const Loaded data(sample_json());
  const auto tables = build_appendix_tables(data.index, study());
  const AppendixTableFacts* t =
      find_table(tables, ProblemId::H_p, Quantity::sigma_c, Element::Q4, ContactKind::ss);
  ASSERT_NE(t, nullptr);
  // Ours 1.2730 against 4/pi = 1.27324: -0.02 %; the study's Table 7a F row: 1.2737.
  EXPECT_EQ(cell(*t, F, "AL = PM"), "1.2730 (−0.02 %)");
  EXPECT_EQ(cell(*t, F, "ANSYS AL, PM"), "1.2737");
  EXPECT_EQ(cell(*t, C, "ANSYS LMP, PLM"), "1.3124");
  // MPC is the study's IMC; its fine case did not converge ("!").
  EXPECT_EQ(cell(*t, F, "MPC"), "1.5200 (+19.4 %)!");
  EXPECT_EQ(cell(*t, F, "ANSYS IMC"), "1.7387");
  EXPECT_EQ(cell(*t, M, "h"), "0.0625");
  EXPECT_EQ(t->study_tables, (std::set<std::string>{"7a"}));
}

// Requirement: our values stand beside ANSYS's on its basis, extrapolated nodal stresses, where
// that case ran (H_p Q4 LMP ss: +1.25 % extrapolated, against the patch-recovered value the
// rest of the report grades), and the table says so; where it did not, the patch-recovered one.
TEST(AppendixTables, OurValuesAreOnAnsysBasisWhereThatCaseRan) {
  const Loaded data(sample_json());
  const auto tables = build_appendix_tables(data.index, study());
  const AppendixTableFacts* t =
      find_table(tables, ProblemId::H_p, Quantity::sigma_c, Element::Q4, ContactKind::ss);
  ASSERT_NE(t, nullptr);
  EXPECT_TRUE(t->extrapolated);
  EXPECT_EQ(cell(*t, F, "LMP = PLM"), "1.2892 (+1.25 %)");
  const AppendixTableFacts* q8 =
      find_table(tables, ProblemId::H_p, Quantity::sigma_c, Element::Q8, ContactKind::ss);
  ASSERT_NE(q8, nullptr);
  EXPECT_FALSE(q8->extrapolated);
}

TEST(AppendixTables, TheStudysEitherColumnsAndTheSurfaceToSurfaceTable) {
  const Loaded data(sample_json());
  const auto tables = build_appendix_tables(data.index, study());
  // P_p ss: the study's AL, PM ss values are in the sentence above Table 3a (1.0000), its
  // LMP, PLM column is "either node-to-surface or surface-to-surface" (Table 3a).
  const AppendixTableFacts* t =
      find_table(tables, ProblemId::P_p, Quantity::sigma_z_max, Element::Q4, ContactKind::ss);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(cell(*t, F, "ANSYS AL, PM"), "1.0000");
  EXPECT_EQ(cell(*t, F, "LMP"), "1.0019 (+0.19 %)");
  EXPECT_EQ(cell(*t, F, "ANSYS LMP, PLM"), "1.0019");
  EXPECT_EQ(cell(*t, F, "ANSYS IMC"), "2.7767");
  EXPECT_EQ(t->study_tables, (std::set<std::string>{"3a", "3text"}));
}

TEST(AppendixTables, MissingAndFailedCasesAreMarkedNotDropped) {
  const Loaded data(sample_json());
  const auto tables = build_appendix_tables(data.index, study());
  const AppendixTableFacts* t =
      find_table(tables, ProblemId::H_p, Quantity::sigma_c, Element::Q8, ContactKind::ss);
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->table.n_rows(), 3u);  // C, M and F all shown
  EXPECT_EQ(cell(*t, F, "AL"), "—");
  EXPECT_EQ(cell(*t, F, "PM"), "failed");
  EXPECT_EQ(cell(*t, M, "AL"), "1.2810 (+0.61 %)");
  EXPECT_EQ(cell(*t, F, "ANSYS AL, PM"), "1.2761");
  EXPECT_TRUE(t->missing);
  EXPECT_TRUE(t->failed);
  // Problems not run have no table at all.
  EXPECT_EQ(find_table(tables, ProblemId::H_a, Quantity::sigma_c, Element::Q4, ContactKind::ss),
            nullptr);
  // Mortar: ours only.
  const AppendixTableFacts* m =
      find_table(tables, ProblemId::H_p, Quantity::sigma_c, Element::Q4, ContactKind::mortar);
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(std::count_if(m->table.header().begin(), m->table.header().end(),
                          [](const std::string& c) { return c.rfind("ANSYS", 0) == 0; }),
            0);
  EXPECT_TRUE(m->study_tables.empty());
}

// Requirement: above each group the exact value is ours, beside the study's printed one and
// its signed shift from ours; a singular quantity has none.
TEST(AppendixTables, ExactValueIsOursBesideTheStudysPrintedValue) {
  const Loaded data(sample_json());
  const auto s = exact_value_facts(data.index, study(), ProblemId::S_1_3, Quantity::sigma_c);
  ASSERT_TRUE(s.exact && s.printed && s.printed_shift);
  EXPECT_NEAR(*s.exact, 11.2424, 5e-5);  // the study's 4 printed decimals
  EXPECT_DOUBLE_EQ(*s.printed, 10.9571);
  EXPECT_NEAR(*s.printed_shift, (10.9571 - *s.exact) / *s.exact * 100, 1e-12);
  EXPECT_LT(*s.printed_shift, 0.0);  // −2.54 %: signed
  const auto h = exact_value_facts(data.index, study(), ProblemId::H_p, Quantity::sigma_c);
  ASSERT_TRUE(h.exact);
  EXPECT_NEAR(*h.exact, 1.2732, 5e-5);
  const auto f = exact_value_facts(data.index, study(), ProblemId::F_p, Quantity::sigma_c_star);
  EXPECT_TRUE(f.singular);
  const std::string md = appendix_section(data.index, study());
  EXPECT_NE(md.find("−2.54 %"), std::string::npos);
}

TEST(StudyReference, MapsOurOptionsOntoTheStudysKeys) {
  const auto& s = study();
  EXPECT_EQ(s.values().size(), 354u);
  EXPECT_EQ(s.grades().size(), 80u);
  // PM maps to AL_PM; ns AL, PM in Table 7b.
  auto m = s.find_value(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::PM,
                        ContactKind::ns, F);
  ASSERT_NE(m.value, nullptr);
  EXPECT_EQ(m.value->printed, "1.4104");
  EXPECT_EQ(m.value->table, "7b");
  // Table 7d prints no LMP, PLM column ("same results as surface-to-surface"): Table 7c's.
  m = s.find_value(ProblemId::H_p, Quantity::sigma_c, Element::Q8, Algorithm::PLM, ContactKind::ns,
                   F);
  ASSERT_NE(m.value, nullptr);
  EXPECT_TRUE(m.via_ss_note);
  EXPECT_EQ(m.value->printed, "1.3121");
  // MPC is the study's IMC.
  m = s.find_value(ProblemId::F_a, Quantity::sigma_c_star, Element::Q8, Algorithm::MPC,
                   ContactKind::ns, F);
  ASSERT_NE(m.value, nullptr);
  EXPECT_EQ(m.value->printed, "2.7352");
  EXPECT_EQ(s.find_value(ProblemId::H_p, Quantity::sigma_c, Element::Q4, Algorithm::LMP,
                         ContactKind::mortar, F)
                .value,
            nullptr);
  const schema::StudyGrade* g =
      s.find_grade(ProblemId::H_a, "main", Element::Q8, Algorithm::MPC, ContactKind::ns);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->cell(), "u, c");
  EXPECT_EQ(g->column_label(), "IMC");
  EXPECT_EQ(s.find_grade(ProblemId::H_a, "main", Element::Q8, Algorithm::AL, ContactKind::mortar),
            nullptr);
  // AL, PM has a column per contact type in Table 2; LMP, PLM one for both.
  const schema::StudyGrade* al =
      s.find_grade(ProblemId::P_p, "main", Element::Q4, Algorithm::PM, ContactKind::ns);
  ASSERT_NE(al, nullptr);
  EXPECT_EQ(al->column_label(), "AL, PM ns");
  EXPECT_EQ(al->cell(), "s");
  EXPECT_TRUE(s.separates_contacts(Algorithm::AL));
  EXPECT_FALSE(s.separates_contacts(Algorithm::PLM));
  EXPECT_EQ(s.grade_table(Element::Q8), "2b");
  EXPECT_EQ(s.singular_problems(), (std::vector<ProblemId>{ProblemId::F_p, ProblemId::F_a}));
}

// Requirement: the study's names (4Q, IMC, AL_PM, either) are read with the vocabulary; a name
// it does not know is rejected with the file and line.
TEST(StudyReference, NamesTheVocabularyDoesNotKnowAreRejected) {
  EXPECT_EQ(schema::study_name(Element::Q4), "4Q");
  EXPECT_EQ(schema::study_name(Algorithm::MPC), "IMC");
  EXPECT_EQ(schema::study_name(Algorithm::LMP), "LMP");
  EXPECT_EQ(schema::study_column_label(Algorithm::PLM), "LMP, PLM");
  EXPECT_EQ(schema::study_columns(),
            (std::vector<Algorithm>{Algorithm::AL, Algorithm::LMP, Algorithm::MPC}));
  testing::TempDir tmp;
  const std::string grades = testing::read_text(testing::study_dir() / "ansys_grades.csv");
  std::string results = testing::read_text(testing::study_dir() / "ansys_results.csv");
  results.replace(results.find(",H_p,"), 5, ",H_x,");
  testing::write_text(tmp.path() / "ansys_results.csv", results);
  testing::write_text(tmp.path() / "ansys_grades.csv", grades);
  try {
    schema::load_study_reference(tmp.path());
    FAIL() << "an unknown problem was accepted";
  } catch (const schema::SchemaError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("ansys_results.csv' line "), std::string::npos) << what;
    EXPECT_NE(what.find("unknown problem 'H_x'"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace cs::reports
