// Section 7: patch-recovered beside extrapolated nodal stresses, for runs that asked for both.
// The sample (tests/reports/data/make_small_results.py) has H_p Q4 LMP ss both ways: on the
// fine mesh sigma_c is +0.45 % (e) patch-recovered and +1.25 % (g) extrapolated; sigma_h is
// +2.10 % (g) and -0.51 % (e).

#include <fstream>
#include <string>

#include <algorithm>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/findings/recovery_section.hpp"
#include "reports/report_writer.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::Element;
using schema::ProblemId;
using schema::Quantity;
using testing::Loaded;
using testing::sample_json;

// Requirement: an extrapolated row is the twin of its baseline row, not a variant.
TEST(RecoverySection, ExtrapolatedRowsAreTwinsNotVariants) {
  const Loaded data(sample_json());
  EXPECT_TRUE(data.index.has_extrapolated_twins());
  const schema::RowVerdict* base = data.index.row(ProblemId::H_p, Quantity::sigma_c, Element::Q4,
                                                  {Algorithm::LMP, ContactKind::ss});
  ASSERT_NE(base, nullptr);
  const schema::RowVerdict* twin = data.index.extrapolated_twin(*base);
  ASSERT_NE(twin, nullptr);
  EXPECT_EQ(twin->spec.recovery, schema::Recovery::extrapolated);
  EXPECT_EQ(data.index.extrapolated_twin(*data.index.row(
                ProblemId::H_p, Quantity::sigma_c, Element::Q4, {Algorithm::AL, ContactKind::ss})),
            nullptr);
  for (const schema::RowVerdict* v : data.index.variant_rows())
    EXPECT_NE(v->spec.recovery, schema::Recovery::extrapolated) << v->id;
  EXPECT_EQ(variants_section(data.index).find("extrapolated"), std::string::npos);
}

// Requirement: the variants appendix shows a row's fourth mesh VF where its case ran and
// converged (S(1/3) Q4 MPC ss rigid reads +0.69 % on F and +91 % on VF), not graded, and "—"
// where no VF case converged.
TEST(VariantsSection, ShowsTheFourthMeshWhereItRan) {
  auto doc = sample_json();
  nlohmann::json vf;
  for (const auto& c : doc["cases"]) {
    if (c["id"] == "H_p/F/Q4/AL/ss/rigid")
      vf = c;
  }
  ASSERT_FALSE(vf.is_null());
  vf["id"] = "H_p/VF/Q4/AL/ss/rigid";
  vf["mesh"] = "VF";
  doc["cases"].push_back(vf);
  testing::set_value(doc, "H_p/VF/Q4/AL/ss/rigid", "sigma_c", 1.2732395 * 1.91);
  const Loaded data(doc);
  const std::string md = variants_section(data.index);
  EXPECT_NE(md.find("| VF | Grade |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2.4319 (+91.0 %) |"), std::string::npos) << md;
  EXPECT_EQ(variants_section(Loaded(sample_json()).index).find("| VF |"), std::string::npos);
}

// Requirement: the flat punch's Eq. 47 is compared both ways on rows that are evidence only: a
// row whose F case fails an interface check has no verdict to compare and is counted apart.
TEST(RecoverySection, FlatPunchComparesRowsThatAreEvidence) {
  const auto section = [](nlohmann::json doc) {
    const Loaded data(doc);
    return recovery_section(data.index);
  };
  std::ifstream in(testing::source_dir() / "tests" / "reports" / "data" / "battery_results.json");
  const auto battery = nlohmann::json::parse(in);
  const std::string md = section(battery);
  const auto at = md.find("Flat punch (Eq. 47): the divergence verdict is the same both ways on ");
  ASSERT_NE(at, std::string::npos) << md;
  // One more F_p case pulling: its rows (both bases share the solve) leave the comparison.
  auto pulling = battery;
  for (auto& c : pulling["cases"]) {
    const std::string id = c["id"];
    if (id == "F_p/F/Q4/AL/ss" || id == "F_p/F/Q4/AL/ss/extrapolated")
      c["interface"]["max_tensile_over_p"] = 5.0;
  }
  const std::string md2 = section(pulling);
  const auto count = [](const std::string& text, const std::string& lead) {
    const auto i = text.find(lead) + lead.size();
    return std::stoi(text.substr(text.find(" of ", i) + 4));
  };
  const std::string lead = "the same both ways on ";
  EXPECT_EQ(count(md2, lead), count(md, lead) - 1) << md2;
  EXPECT_NE(md2.find("rows whose F case fails an interface check or did not converge are left out"),
            std::string::npos)
      << md2;
}

// Requirement: the section counts the option sets graded both ways, and lists those whose grade
// differs with both errors, their grades and the contact pressure's error.
TEST(RecoverySection, ListsTheOptionSetsWhoseGradeDiffers) {
  const Loaded data(sample_json());
  const std::string md = recovery_section(data.index);
  EXPECT_EQ(md.rfind("## Nodal stress recovery", 0), 0u) << md;
  EXPECT_NE(md.find("| +0.45 % (e) | +1.25 % (g) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| +2.10 % (g) | −0.51 % (e) |"), std::string::npos) << md;
  EXPECT_EQ(md.find("Q8:"), std::string::npos);  // no Q8 twins in the sample
}

// Requirement: the comparison counts, per element, the rows whose value depends on the
// recovery, judged against the exact value: sigma_c +0.45 % against +1.25 % (closer, better
// grade), sigma_h +2.10 % against -0.51 % (farther, worse grade).
TEST(RecoverySection, ComparesAgainstTheExactValue) {
  const Loaded data(sample_json());
  const auto comparisons = compare_recoveries(data.index);
  ASSERT_EQ(comparisons.size(), 1u);
  const RecoveryComparison& c = comparisons[0];
  EXPECT_EQ(c.element, Element::Q4);
  EXPECT_EQ(c.compared, 2);
  EXPECT_EQ(c.unaffected, 0);
  EXPECT_EQ(c.better, 1);
  EXPECT_EQ(c.worse, 1);
  EXPECT_EQ(c.closer, 1);
  EXPECT_EQ(c.farther, 1);
  EXPECT_NEAR(c.median_spr, 0.5 * (0.45 + 2.10), 0.005);  // printed to two decimals
}

// Requirement: a row that reads alike both ways (its quantity is not a recovered stress) and a
// row that is not evidence do not enter the medians or the counts; they are counted apart.
TEST(RecoverySection, LeavesOutRowsTheRecoveryDoesNotChange) {
  Loaded data(sample_json());
  for (auto& r : data.file.rows) {
    if (r.spec.recovery == schema::Recovery::extrapolated && r.quantity == Quantity::sigma_h)
      r.errors = data.index
                     .row(ProblemId::H_p, Quantity::sigma_h, Element::Q4,
                          {Algorithm::LMP, ContactKind::ss})
                     ->errors;
  }
  const auto c = compare_recoveries(ResultsIndex(data.file)).at(0);
  EXPECT_EQ(c.compared, 1);
  EXPECT_EQ(c.unaffected, 1);
  EXPECT_NEAR(c.median_spr, 0.45, 0.005);
}

// Requirement: without extrapolated rows the section is one line saying how to get it.
TEST(RecoverySection, AbsentWithoutExtrapolatedRows) {
  auto doc = sample_json();
  for (const char* key : {"cases", "rows"}) {
    auto& list = doc[key];
    for (auto it = list.begin(); it != list.end();) {
      it = (*it)["recovery"] == "extrapolated" ? list.erase(it) : it + 1;
    }
  }
  const Loaded data(doc);
  EXPECT_FALSE(data.index.has_extrapolated_twins());
  const std::string md = recovery_section(data.index);
  EXPECT_NE(md.find("--recovery spr,extrapolated"), std::string::npos) << md;
  EXPECT_EQ(md.find('|'), std::string::npos) << md;  // no table
}

}  // namespace
}  // namespace cs::reports
