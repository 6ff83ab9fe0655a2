#include "schema/combined_results.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

std::string source_name(const ResultsDocument& doc) {
  return doc.source.empty() ? std::string("(unnamed results)") : doc.source;
}

/// Relative agreement of two values of the same analysis run twice (a refinement run repeats
/// the C, M and F cases of the main job): well above round-off, far below any error of interest.
constexpr double kSameAnalysis = 1e-9;

/// Whether two values (absent or NaN: no value, as a failed case's) are the same.
bool same_value(std::optional<double> a, std::optional<double> b) {
  if (a && std::isnan(*a))
    a.reset();
  if (b && std::isnan(*b))
    b.reset();
  if (!a || !b)
    return a.has_value() == b.has_value();
  return std::abs(*a - *b) <= kSameAnalysis * std::max({std::abs(*a), std::abs(*b), 1e-300});
}

bool same_case(const CaseResult& a, const CaseResult& b) {
  if (a.status != b.status || a.quantities.size() != b.quantities.size())
    return false;
  for (std::size_t q = 0; q < a.quantities.size(); ++q) {
    if (a.quantities[q].quantity != b.quantities[q].quantity ||
        !same_value(a.quantities[q].value, b.quantities[q].value))
      return false;
  }
  return true;
}

bool same_row(const RowVerdict& a, const RowVerdict& b) {
  for (std::size_t m = 0; m < a.values.size(); ++m) {
    if (!same_value(a.values[m], b.values[m]))
      return false;
  }
  return true;
}

std::string twice_message(const char* what, const std::string& id, const std::string& first,
                          const std::string& second) {
  return fmt::format(
      "{} {} is in both {} and {} with different values: combine results of different cases, "
      "or of the same analyses run twice",
      what, id, first, second);
}

/// What the combined document holds so far, by id, with the file each came from.
struct Owners {
  std::map<std::string, std::pair<std::size_t, std::string>> cases;  // index in out.cases
  std::map<std::string, std::pair<std::size_t, std::string>> rows;   // index in out.rows
};

/// Adds `c` unless the same analysis is there already; throws if it is there with other values.
void add_case(ResultsDocument& out, Owners& owners, CaseResult c, const std::string& source) {
  const std::string id = case_id(c.spec);
  const auto it = owners.cases.find(id);
  if (it == owners.cases.end()) {
    owners.cases.emplace(id, std::make_pair(out.cases.size(), source));
    out.cases.push_back(std::move(c));
  } else if (!same_case(out.cases[it->second.first], c)) {
    throw SchemaError(twice_message("case", id, it->second.second, source));
  }
}

/// Adds `r` unless its row is there already with the same values, in which case the row kept
/// takes `r`'s refinement record (M-F-VF) if it has none; throws for other values.
void add_row(ResultsDocument& out, Owners& owners, RowVerdict r, const std::string& source) {
  const auto it = owners.rows.find(r.id);
  if (it == owners.rows.end()) {
    owners.rows.emplace(r.id, std::make_pair(out.rows.size(), source));
    out.rows.push_back(std::move(r));
    return;
  }
  RowVerdict& kept = out.rows[it->second.first];
  if (!same_row(kept, r))
    throw SchemaError(twice_message("row", r.id, it->second.second, source));
  if (!kept.refinement)
    kept.refinement = std::move(r.refinement);
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
  Owners owners;
  ResultsDocument out;
  out.source = documents.front().source;
  out.run = documents.front().run;
  for (std::size_t i = 0; i < documents.size(); ++i) {
    ResultsDocument& doc = documents[i];
    const std::string source = source_name(doc);
    for (std::size_t j = 0; j < i && !doc.source.empty(); ++j) {
      if (documents[j].source == doc.source)
        throw SchemaError(fmt::format("results file {} is given twice", source));
    }
    if (i > 0) {
      out.source += ", " + source;
      out.added_runs.emplace_back(source, doc.run);
    }
    add_problems(out.problems, doc.problems);
    out.parameter_defaults.insert(doc.parameter_defaults.begin(), doc.parameter_defaults.end());
    for (auto& c : doc.cases)
      add_case(out, owners, std::move(c), source);
    for (auto& r : doc.rows)
      add_row(out, owners, std::move(r), source);
  }
  return out;
}

}  // namespace cs::schema
