// Section 7: patch-recovered beside extrapolated nodal stresses, for runs that asked for both.
// The sample (tests/reports/data/make_small_results.py) has H_p Q4 LMP ss both ways: on the
// fine mesh sigma_c is +0.45 % (e) patch-recovered and +1.25 % (g) extrapolated; sigma_h is
// +2.10 % (g) and -0.51 % (e).

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

// Requirement: the comparison counts, per element, the grades that change and in how many of
// those the patch-recovered value is the closer to the contact pressure (the sample's contact
// pressures are 0.995 times the patch-recovered values: closer in both).
TEST(RecoverySection, ComparesWithTheContactPressureAsWitness) {
  const Loaded data(sample_json());
  const auto comparisons = compare_recoveries(data.index);
  ASSERT_EQ(comparisons.size(), 1u);
  const RecoveryComparison& c = comparisons[0];
  EXPECT_EQ(c.element, Element::Q4);
  EXPECT_EQ(c.compared, 2);
  EXPECT_EQ(c.better, 1);
  EXPECT_EQ(c.worse, 1);
  EXPECT_EQ(c.differing_with_pressure, 2);
  EXPECT_EQ(c.spr_closer_to_pressure, 2);
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
