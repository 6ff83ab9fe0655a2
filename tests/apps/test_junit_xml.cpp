// The JUnit writer: counts per testsuite and in the root, one element per reason, and row ids
// with markup characters, control characters and bytes that are not UTF-8 still giving a
// well-formed file whose names read back (the unrepresentable characters as U+FFFD).

#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <pugixml.hpp>

#include "apps/ci_summary.hpp"
#include "apps/junit_xml.hpp"

namespace cs::apps {
namespace {

using schema::ProblemId;
using schema::RowOutcome;
using schema::RowOutcomeKind;

RowOutcome row(std::string id, ProblemId problem, RowOutcomeKind kind,
               std::vector<std::string> reasons = {}) {
  return {std::move(id), problem, 0.25, kind, std::move(reasons), "grade e on F", ""};
}

pugi::xml_document parse(const std::string& xml) {
  pugi::xml_document doc;
  const auto result = doc.load_string(xml.c_str());
  EXPECT_TRUE(result) << result.description() << "\n" << xml;
  return doc;
}

// Requirement: every character of any row id survives as itself when XML can hold it; the
// others (C0 controls, invalid UTF-8) become U+FFFD, and the file stays well-formed.
TEST(JunitXml, AnyRowIdGivesAWellFormedFile) {
  const std::string id = "H_p/Q4/AL/ss/k=<1>&\"'\x01\xff/\xCE\xBD\xE2\x80\xB2";
  const std::string reason = "value drift of ]]> <b>x</b>\x02";
  const auto xml = junit_xml({row(id, ProblemId::H_p, RowOutcomeKind::failed, {reason})}, "t");
  const auto doc = parse(xml);
  const auto tc = doc.child("testsuites").child("testsuite").child("testcase");
  EXPECT_EQ(std::string(tc.attribute("name").value()),
            "H_p/Q4/AL/ss/k=<1>&\"'\xEF\xBF\xBD\xEF\xBF\xBD/\xCE\xBD\xE2\x80\xB2");
  EXPECT_EQ(std::string(tc.child("failure").attribute("message").value()),
            "value drift of ]]> <b>x</b>\xEF\xBF\xBD");
  EXPECT_EQ(std::string(tc.child("failure").text().get()),
            "value drift of ]]> <b>x</b>\xEF\xBF\xBD");
}

// Requirement: truncated and overlong UTF-8 sequences and surrogates are replaced byte by byte.
TEST(JunitXml, InvalidUtf8IsReplaced) {
  EXPECT_EQ(xml_safe_text("a\xC3"), "a\xEF\xBF\xBD");                // truncated
  EXPECT_EQ(xml_safe_text("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // overlong '/'
  EXPECT_EQ(xml_safe_text("\xED\xA0\x80").size(), 9u);               // a surrogate: 3 x U+FFFD
  EXPECT_EQ(xml_safe_text("tab\tnl\ncr\r"), "tab\tnl\ncr\r");        // allowed as they are
  EXPECT_EQ(xml_safe_text("\xF0\x9F\x98\x80"), "\xF0\x9F\x98\x80");  // U+1F600 kept
}

// Requirement: suites follow the problems in first-seen order, with their own counts, and the
// root carries the totals; a failure per reason, one skipped element at most.
TEST(JunitXml, CountsAndElements) {
  const auto xml = junit_xml({row("a", ProblemId::H_p, RowOutcomeKind::failed, {"r1", "r2"}),
                              row("b", ProblemId::P_p, RowOutcomeKind::error, {"not converged"}),
                              row("c", ProblemId::H_p, RowOutcomeKind::skipped, {"s"}),
                              row("d", ProblemId::H_p, RowOutcomeKind::passed)},
                             "contact-suite gate");
  const auto doc = parse(xml);
  const auto root = doc.child("testsuites");
  EXPECT_EQ(root.attribute("tests").as_int(), 4);
  EXPECT_EQ(root.attribute("failures").as_int(), 1);
  EXPECT_EQ(root.attribute("errors").as_int(), 1);
  EXPECT_DOUBLE_EQ(root.attribute("time").as_double(), 1.0);
  const auto h = root.child("testsuite");
  EXPECT_STREQ(h.attribute("name").value(), "H_p");
  EXPECT_EQ(h.attribute("tests").as_int(), 3);
  EXPECT_EQ(h.attribute("skipped").as_int(), 1);
  EXPECT_STREQ(h.next_sibling("testsuite").attribute("name").value(), "P_p");
  const auto a = h.child("testcase");
  EXPECT_EQ(std::distance(a.children("failure").begin(), a.children("failure").end()), 2);
  EXPECT_STREQ(a.attribute("classname").value(), "H_p");
  EXPECT_STREQ(a.attribute("time").value(), "0.250");
}

// Requirement: the summary states pass or fail, and lists each row that did not pass.
TEST(CiSummary, ListsRowsThatDidNotPass) {
  const auto md = ci_summary_markdown({row("a|b", ProblemId::H_p, RowOutcomeKind::failed, {"r1"}),
                                       row("c", ProblemId::H_p, RowOutcomeKind::passed)},
                                      "contact-suite gate");
  EXPECT_NE(md.find("## contact-suite gate: FAILED"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2 | 1 | 1 | 0 | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("`a\\|b`"), std::string::npos) << md;
  EXPECT_EQ(md.find("`c`"), std::string::npos) << md;
}

}  // namespace
}  // namespace cs::apps
