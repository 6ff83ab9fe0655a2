#include "suites/results_merge.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "suites/problem_catalog.hpp"
#include "suites/row_verdict.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

/// Puts a case's quantities back in its problem's order (results.json keys them by name, so a
/// file read back has them alphabetically): the rows then come out in the unsharded run's order.
void order_quantities(CaseResult& c) {
  const auto& defined = problem_descriptor(c.spec.problem).record.quantities;
  auto rank = [&defined](const QuantityResult& q) {
    const auto it = std::find_if(defined.begin(), defined.end(),
                                 [&q](const auto& d) { return d.quantity == q.quantity; });
    return it - defined.begin();
  };
  std::stable_sort(
      c.quantities.begin(), c.quantities.end(),
      [&rank](const QuantityResult& a, const QuantityResult& b) { return rank(a) < rank(b); });
}

std::string version_of(const schema::ResultsDocument& d) {
  return d.run.build().value_or("unknown");
}

void check_versions(const std::vector<schema::ResultsDocument>& parts) {
  for (const auto& p : parts) {
    if (version_of(p) != version_of(parts.front())) {
      throw SuiteInputError(fmt::format(
          "merge: {} comes from contact-suite {} but {} from {}: results of different builds "
          "(--mixed-builds merges them and records each build)",
          p.source, version_of(p), parts.front().source, version_of(parts.front())));
    }
  }
}

/// "0.1.0+25580ed" for files of one build; else every build with its number of files, in order
/// of first appearance: "mixed: 0.1.0+25580ed (128 files), 0.1.0+d76f56f (2 files)".
std::string builds_of(const std::vector<schema::ResultsDocument>& parts) {
  std::vector<std::pair<std::string, int>> builds;
  for (const auto& p : parts) {
    const std::string v = version_of(p);
    const auto it =
        std::find_if(builds.begin(), builds.end(), [&v](const auto& b) { return b.first == v; });
    if (it == builds.end())
      builds.emplace_back(v, 1);
    else
      ++it->second;
  }
  if (builds.size() == 1)
    return builds.front().first;
  std::string out = "mixed: ";
  for (std::size_t i = 0; i < builds.size(); ++i) {
    out += fmt::format("{}{} ({} file{})", i == 0 ? "" : ", ", builds[i].first, builds[i].second,
                       builds[i].second == 1 ? "" : "s");
  }
  return out;
}

/// All or none sharded; one run key and count; every slice exactly once.
void check_slices(const std::vector<schema::ResultsDocument>& parts) {
  const auto& first = parts.front().run.shard;
  std::set<int> seen;
  for (const auto& p : parts) {
    const auto& s = p.run.shard;
    if (s.has_value() != first.has_value()) {
      throw SuiteInputError(fmt::format("merge: {} and {} mix a slice with unsharded results",
                                        parts.front().source, p.source));
    }
    if (!s)
      continue;
    if (s->run_key != first->run_key || s->count != first->count) {
      throw SuiteInputError(fmt::format(
          "merge: {} (slice {}/{}, run {}) and {} (slice {}/{}, run {}) are slices of different "
          "runs (different selections, settings or versions)",
          parts.front().source, first->index, first->count, first->run_key, p.source, s->index,
          s->count, s->run_key));
    }
    if (!seen.insert(s->index).second) {
      throw SuiteInputError(
          fmt::format("merge: slice {}/{} is given twice ({})", s->index, s->count, p.source));
    }
  }
  if (!first)
    return;
  for (int k = 1; k <= first->count; ++k) {
    if (!seen.count(k))
      throw SuiteInputError(fmt::format("merge: slice {}/{} is missing", k, first->count));
  }
}

/// The union of the parts' sweeps: keys in order of first appearance, each key's values in
/// order of first appearance (the slices of one run have one sweep; separate runs their own).
std::vector<schema::SweepAxis> merged_sweep(const std::vector<schema::ResultsDocument>& parts) {
  std::vector<schema::SweepAxis> axes;
  for (const auto& p : parts) {
    for (const auto& axis : p.run.sweep) {
      auto it = std::find_if(axes.begin(), axes.end(),
                             [&](const schema::SweepAxis& a) { return a.key == axis.key; });
      if (it == axes.end()) {
        axes.push_back({axis.key, {}});
        it = axes.end() - 1;
      }
      for (double v : axis.values) {
        if (std::find(it->values.begin(), it->values.end(), v) == it->values.end())
          it->values.push_back(v);
      }
    }
  }
  return axes;
}

auto order_key(const schema::CaseResult& c) {
  const auto& s = c.spec;
  return std::make_tuple(s.problem, s.mesh, s.element, s.algorithm, s.contact, s.recovery, s.target,
                         s.solver, s.solver_name, s.overrides);
}

}  // namespace

void sort_cases(std::vector<schema::CaseResult>& cases) {
  std::stable_sort(cases.begin(), cases.end(),
                   [](const auto& a, const auto& b) { return order_key(a) < order_key(b); });
}

schema::ResultsDocument merge_results(const std::vector<schema::ResultsDocument>& parts,
                                      const std::string& command_line, BuildMix builds) {
  if (parts.empty())
    throw SuiteInputError("merge: no results files given");
  if (builds == BuildMix::refuse)
    check_versions(parts);
  check_slices(parts);
  schema::ResultsDocument out;
  out.run = parts.front().run;
  if (const std::string builds = builds_of(parts); builds != version_of(parts.front()))
    out.run.environment["contact_suite_version"] = builds;  // several builds, each named
  out.run.shard.reset();
  out.run.sweep = merged_sweep(parts);
  out.run.command_line = command_line;
  out.run.wall_seconds = 0.0;
  out.run.jobs = 1;
  long long merged_files = 0;  // each at most kMaxMergedFiles (the reader's bound): no overflow
  std::set<std::string> ids;
  for (const auto& p : parts) {
    out.run.started_utc = std::min(out.run.started_utc, p.run.started_utc);
    out.run.wall_seconds += p.run.wall_seconds;  // summed over the parts: machine time
    out.run.jobs = std::max(out.run.jobs, p.run.jobs);
    merged_files += std::max(p.run.merged_files, 1);
    out.run.peak_rss_mb = std::max(out.run.peak_rss_mb, p.run.peak_rss_mb);
    for (const auto& c : p.cases) {
      if (!ids.insert(schema::case_id(c.spec)).second) {
        throw SuiteInputError(fmt::format("merge: case {} is in more than one file (again in {})",
                                          schema::case_id(c.spec), p.source));
      }
      out.cases.push_back(c);
    }
  }
  if (merged_files > schema::kMaxMergedFiles)
    throw SuiteInputError(
        fmt::format("merge: the files merge {} results files in all, more than {}", merged_files,
                    schema::kMaxMergedFiles));
  out.run.merged_files = static_cast<int>(merged_files);
  const auto& shard = parts.front().run.shard;
  if (shard && static_cast<long long>(out.cases.size()) != shard->total_cases) {
    throw SuiteInputError(fmt::format("merge: the slices hold {} cases but the run had {}",
                                      out.cases.size(), shard->total_cases));
  }
  sort_cases(out.cases);
  for (auto& c : out.cases)
    order_quantities(c);
  out.problems = problem_records(out.cases);
  out.parameter_defaults = parameter_defaults(out.cases);
  out.rows = make_row_verdicts(out.cases);
  return out;
}

}  // namespace cs::suites
