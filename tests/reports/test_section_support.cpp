// The helpers the table sections share (reports/tables/section_support): the slots they walk,
// and counts, lists and tables as template values.

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

// Requirement: the slots are every (problem, quantity, element) of the results' problems, in
// the report's problem order, each problem's quantities in order, Q4 before Q8.
TEST(SectionSupport, SlotsFollowTheReportsOrder) {
  const testing::Loaded data(testing::sample_json());
  const auto slots = slots_of(data.index);
  std::size_t expected = 0;
  for (const schema::ProblemRecord* p : data.index.problems())
    expected += p->quantities.size() * schema::values<schema::Element>().size();
  ASSERT_EQ(slots.size(), expected);
  const schema::ProblemRecord& first = *data.index.problems().front();
  EXPECT_EQ(slots[0].problem, first.id);
  EXPECT_EQ(slots[0].quantity, first.quantities.front().quantity);
  EXPECT_EQ(slots[0].element, schema::Element::Q4);
  EXPECT_EQ(slots[1].element, schema::Element::Q8);
}

// Requirement: an empty count, list or table is false (or empty), so that a template's
// "{{#key}}…{{/key}}" leaves it out; otherwise it is the text.
TEST(SectionSupport, EmptyValuesAreLeftOut) {
  const auto shown = [](const TemplateData& d) {
    return render_template("{{#k}}[{{k}}]{{/k}}", TemplateData("k", d));
  };
  EXPECT_EQ(shown(count_or_false(0)), "");
  EXPECT_EQ(shown(count_or_false(12)), "[12]");
  EXPECT_EQ(shown(joined_or_false(std::vector<std::string>{}, "; ")), "");
  EXPECT_EQ(shown(joined_or_false(std::vector<std::string>{"a", "b"}, "; ")), "[a; b]");
  MarkdownTable table({"A", "B"});
  EXPECT_EQ(rendered_if_any(table), "");
  table.add_row({"1", "2"});
  EXPECT_EQ(rendered_if_any(table), table.render());
}

}  // namespace
}  // namespace cs::reports
