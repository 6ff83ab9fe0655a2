#pragma once
// JUnit XML of a run or a gate, the test-report format every CI system reads (GitLab, Jenkins,
// GitHub Actions through its test-report actions, Buildkite): one <testsuite> per problem, one
// <testcase> per row (name = row id, classname = problem, time = the row's cases' wall time),
// <failure> per failed check, <error> per case that did not converge, <skipped> for a row not
// compared. The layout follows the common JUnit schema (Jenkins' junit-10; tests/ci/junit.xsd
// is its structure, written for the tests).
//
// Written with pugixml, which escapes markup characters. Text that XML 1.0 cannot carry at all
// (C0 control characters other than tab, line feed and carriage return; bytes that are not
// UTF-8) is replaced by U+FFFD, so that any row id gives a well-formed file.

#include <string>
#include <string_view>
#include <vector>

#include "schema/row_outcome.hpp"

namespace cs::apps {

/// The JUnit document of `rows` (in their order; testsuites in the order their problem first
/// appears), its root <testsuites> named `name` (e.g. "contact-suite gate"). Deterministic:
/// no timestamp and no host name, so that equal input gives equal bytes.
std::string junit_xml(const std::vector<schema::RowOutcome>& rows, std::string_view name);

/// `text` with every character XML 1.0 cannot hold replaced by U+FFFD (see above).
std::string xml_safe_text(std::string_view text);

}  // namespace cs::apps
