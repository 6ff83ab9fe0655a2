#include "apps/junit_xml.hpp"

#include <algorithm>
#include <cstdint>
#include <sstream>

#include <fmt/format.h>
#include <pugixml.hpp>

#include "platform/replaceable_file.hpp"

namespace cs::apps {
namespace {

using schema::RowOutcome;
using schema::RowOutcomeKind;

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

/// The length of the valid UTF-8 sequence at `text[i]` that XML 1.0 allows, or 0.
std::size_t allowed_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t lead = byte(i);
  if (lead < 0x80)
    return lead >= 0x20 || lead == '\t' || lead == '\n' || lead == '\r' ? 1 : 0;
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if ((lead & 0xE0) == 0xC0) {
    n = 2;
    cp = lead & 0x1F;
  } else if ((lead & 0xF0) == 0xE0) {
    n = 3;
    cp = lead & 0x0F;
  } else if ((lead & 0xF8) == 0xF0) {
    n = 4;
    cp = lead & 0x07;
  } else {
    return 0;
  }
  if (i + n > text.size())
    return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80)
      return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  constexpr std::uint32_t kMinimum[] = {0, 0, 0x80, 0x800, 0x10000};
  const bool overlong = cp < kMinimum[n];
  const bool surrogate = cp >= 0xD800 && cp <= 0xDFFF;
  const bool non_character = cp == 0xFFFE || cp == 0xFFFF || cp > 0x10FFFF;
  return overlong || surrogate || non_character ? 0 : n;
}

std::string seconds_text(double seconds) {
  return fmt::format("{:.3f}", seconds);
}

struct Counts {
  int tests = 0, failures = 0, errors = 0, skipped = 0;
  double seconds = 0.0;
  void add(const RowOutcome& row) {
    ++tests;
    failures += row.kind == RowOutcomeKind::failed;
    errors += row.kind == RowOutcomeKind::error;
    skipped += row.kind == RowOutcomeKind::skipped;
    seconds += row.wall_seconds;
  }
};

void set_attribute(pugi::xml_node node, const char* name, std::string_view value) {
  node.append_attribute(name).set_value(xml_safe_text(value).c_str());
}

void set_counts(pugi::xml_node node, const Counts& c) {
  set_attribute(node, "tests", std::to_string(c.tests));
  set_attribute(node, "failures", std::to_string(c.failures));
  set_attribute(node, "errors", std::to_string(c.errors));
  set_attribute(node, "time", seconds_text(c.seconds));
}

/// One <failure>, <error> or <skipped> element per reason.
void append_reasons(pugi::xml_node testcase, const RowOutcome& row) {
  const char* element = nullptr;
  const char* type = nullptr;
  switch (row.kind) {
    case RowOutcomeKind::passed:
      return;
    case RowOutcomeKind::failed:
      element = "failure";
      type = "check failed";
      break;
    case RowOutcomeKind::error:
      element = "error";
      type = "not converged";
      break;
    case RowOutcomeKind::skipped:
      element = "skipped";
      break;
  }
  for (const auto& reason : row.reasons) {
    auto node = testcase.append_child(element);
    set_attribute(node, "message", reason);
    if (type != nullptr) {
      set_attribute(node, "type", type);
      node.append_child(pugi::node_pcdata).set_value(xml_safe_text(reason).c_str());
    }
    if (row.kind == RowOutcomeKind::skipped)
      break;  // the schema allows one <skipped> per testcase
  }
}

void append_testcase(pugi::xml_node suite, const RowOutcome& row) {
  auto testcase = suite.append_child("testcase");
  set_attribute(testcase, "name", row.row_id);
  set_attribute(testcase, "classname", schema::to_string(row.problem));
  set_attribute(testcase, "time", seconds_text(row.wall_seconds));
  append_reasons(testcase, row);
  std::string out = row.summary;
  if (!row.movement.empty())
    out += "\nagainst the baseline: " + row.movement;
  if (!out.empty()) {
    testcase.append_child("system-out")
        .append_child(pugi::node_pcdata)
        .set_value(xml_safe_text(out).c_str());
  }
}

}  // namespace

std::string xml_safe_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = allowed_sequence_length(text, i);
    if (n == 0) {
      out += kReplacement;
      ++i;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  return out;
}

std::string junit_xml(const std::vector<RowOutcome>& rows, std::string_view name) {
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version").set_value("1.0");
  decl.append_attribute("encoding").set_value("UTF-8");
  doc.append_child(pugi::node_comment)
      .set_value(std::string(platform::kWrittenMarkText).c_str());  // ours to replace
  auto root = doc.append_child("testsuites");
  set_attribute(root, "name", name);

  std::vector<schema::ProblemId> problems;  // first-seen order
  for (const auto& row : rows) {
    if (std::find(problems.begin(), problems.end(), row.problem) == problems.end())
      problems.push_back(row.problem);
  }
  Counts total;
  for (const auto& row : rows)
    total.add(row);
  set_counts(root, total);
  for (const auto problem : problems) {
    auto suite = root.append_child("testsuite");
    set_attribute(suite, "name", schema::to_string(problem));
    Counts counts;
    for (const auto& row : rows) {
      if (row.problem == problem)
        counts.add(row);
    }
    set_counts(suite, counts);
    set_attribute(suite, "skipped", std::to_string(counts.skipped));
    for (const auto& row : rows) {
      if (row.problem == problem)
        append_testcase(suite, row);
    }
  }
  std::ostringstream text;
  doc.save(text, "  ", pugi::format_default, pugi::encoding_utf8);
  return text.str();
}

}  // namespace cs::apps
