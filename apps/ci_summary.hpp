#pragma once
// The Markdown summary of a run or a gate for a CI job's summary page (GitHub Actions'
// $GITHUB_STEP_SUMMARY, a GitLab or Buildkite annotation): the counts of rows passed, failed,
// errored and skipped, the rows that did not pass with their reasons, and, against a baseline,
// the rows whose values or grades moved.

#include <string>
#include <string_view>
#include <vector>

#include "schema/row_outcome.hpp"

namespace cs::apps {

/// The summary of `rows` under the heading `title` (e.g. "contact-suite gate against
/// ci/baseline.json"). Ends with a newline.
std::string ci_summary_markdown(const std::vector<schema::RowOutcome>& rows,
                                std::string_view title);

}  // namespace cs::apps
