#include "apps/ci_summary.hpp"

#include <fmt/format.h>

#include "reports/tables/markdown_table.hpp"

namespace cs::apps {

using reports::MarkdownTable;
namespace {

using schema::RowOutcome;
using schema::RowOutcomeKind;

/// Reasons joined for one table cell.
std::string joined(const std::vector<std::string>& reasons) {
  std::string out;
  for (const auto& r : reasons)
    out += (out.empty() ? "" : "; ") + r;
  return out;
}

/// `text` with the characters Markdown would read as markup in a table cell made literal.
std::string code(const std::string& text) {
  std::string out;
  for (const char c : text)
    out += c == '`' ? '\'' : (c == '\n' || c == '\r') ? ' ' : c;
  return "`" + out + "`";
}

std::string counts_table(const std::vector<RowOutcome>& rows) {
  int n[4] = {0, 0, 0, 0};
  for (const auto& r : rows)
    ++n[static_cast<int>(r.kind)];
  MarkdownTable table({"rows", "passed", "failed", "errors", "skipped"});
  table.add_row({std::to_string(rows.size()), std::to_string(n[0]), std::to_string(n[1]),
                 std::to_string(n[2]), std::to_string(n[3])});
  return table.render();
}

}  // namespace

std::string ci_summary_markdown(const std::vector<RowOutcome>& rows, std::string_view title) {
  bool passed = true;
  for (const auto& r : rows)
    passed = passed && (r.kind == RowOutcomeKind::passed || r.kind == RowOutcomeKind::skipped);
  std::string out = fmt::format("## {}: {}\n\n", title, passed ? "passed" : "FAILED");
  out += counts_table(rows);

  MarkdownTable not_passed({"row", "outcome", "reason"});
  for (const auto& r : rows) {
    if (r.kind == RowOutcomeKind::failed || r.kind == RowOutcomeKind::error)
      not_passed.add_row(
          {code(r.row_id), std::string(schema::to_string(r.kind)), joined(r.reasons)});
  }
  if (not_passed.n_rows() > 0)
    out += fmt::format("\n### Rows that did not pass ({})\n\n{}", not_passed.n_rows(),
                       not_passed.render());

  MarkdownTable moved({"row", "outcome", "movement", "now"});
  for (const auto& r : rows) {
    if (!r.movement.empty())
      moved.add_row(
          {code(r.row_id), std::string(schema::to_string(r.kind)), r.movement, r.summary});
  }
  if (moved.n_rows() > 0)
    out += fmt::format("\n### Rows that moved against the baseline ({})\n\n{}", moved.n_rows(),
                       moved.render());
  return out;
}

}  // namespace cs::apps
