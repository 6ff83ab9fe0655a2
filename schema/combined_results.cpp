#include "schema/combined_results.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

std::string source_name(const ResultsDocument& doc) {
  return doc.source.empty() ? std::string("(unnamed results)") : doc.source;
}

/// Records `id` as coming from `source`; throws if another document had it.
void claim(std::map<std::string, std::string>& owners, const std::string& id,
           const std::string& source, const char* what) {
  const auto [it, inserted] = owners.emplace(id, source);
  if (!inserted) {
    throw SchemaError(
        fmt::format("{} {} is in both {} and {}: combine results of different "
                    "cases only",
                    what, id, it->second, source));
  }
}

void add_problems(std::vector<ProblemRecord>& into, const std::vector<ProblemRecord>& from) {
  for (const auto& p : from) {
    const bool known =
        std::any_of(into.begin(), into.end(), [&](const ProblemRecord& q) { return q.id == p.id; });
    if (!known)
      into.push_back(p);
  }
  std::stable_sort(into.begin(), into.end(),
                   [](const ProblemRecord& a, const ProblemRecord& b) { return a.id < b.id; });
}

}  // namespace

ResultsDocument combine_results(std::vector<ResultsDocument> documents) {
  if (documents.empty())
    throw SchemaError("combine_results: no results to combine");
  std::map<std::string, std::string> case_owner;
  std::map<std::string, std::string> row_owner;
  ResultsDocument out;
  out.source = documents.front().source;
  out.run = documents.front().run;
  for (std::size_t i = 0; i < documents.size(); ++i) {
    ResultsDocument& doc = documents[i];
    const std::string source = source_name(doc);
    for (const auto& c : doc.cases)
      claim(case_owner, case_id(c.spec), source, "case");
    for (const auto& r : doc.rows)
      claim(row_owner, r.id, source, "row");
    if (i > 0) {
      out.source += ", " + source;
      out.added_runs.emplace_back(source, doc.run);
    }
    add_problems(out.problems, doc.problems);
    std::move(doc.cases.begin(), doc.cases.end(), std::back_inserter(out.cases));
    std::move(doc.rows.begin(), doc.rows.end(), std::back_inserter(out.rows));
  }
  return out;
}

}  // namespace cs::schema
