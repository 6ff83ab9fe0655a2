#pragma once
// What the table sections share: the slots they walk, the parts per problem, and the small
// conversions of counts, lists and tables into template values.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {

/// Every (problem, quantity, element) of the results' problems, in the report's order.
std::vector<Slot> slots_of(const ResultsIndex& index);

/// The table as Markdown, or "" when it has no body row.
std::string rendered_if_any(const MarkdownTable& table);

/// `n` as text, or false when it is 0 (for "{{#key}}…{{/key}}").
TemplateData count_or_false(std::size_t n);

/// `items` joined by `separator`, or false when there are none.
template <class Items>
TemplateData joined_or_false(const Items& items, std::string_view separator) {
  return text_or_false(fmt::format("{}", fmt::join(items, separator)));
}

/// The section `text` with one part ("problems") per problem of the results that grades
/// `quantity`, its label, title and source set; `fill` adds the rest, or returns false to leave
/// the problem out. Empty without any part.
std::string per_problem_section(
    const ResultsIndex& index, schema::Quantity quantity, std::string_view text,
    const std::function<bool(const schema::ProblemRecord&, TemplateData&)>& fill);

}  // namespace cs::reports
