#include "reports/findings/summary_section.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

void flatten_into(const nlohmann::json& j, const std::string& prefix,
                  std::vector<std::pair<std::string, std::string>>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items())
      flatten_into(v, prefix.empty() ? k : prefix + "." + k, out);
    return;
  }
  out.emplace_back(prefix.empty() ? "(value)" : prefix,
                   j.is_string() ? j.get<std::string>() : j.dump());
}

/// The distinct values of a case field, in the vocabulary's order.
template <class Field>
std::string distinct(const std::vector<schema::CaseResult>& cases, Field field) {
  using E = decltype(field(cases.front()));
  std::vector<E> values;
  for (const auto& c : cases)
    values.push_back(field(c));
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::string out;
  for (const E v : values)
    out += fmt::format("{}{}", out.empty() ? "" : ", ", schema::to_string(v));
  return out;
}

/// The problems of the cases, as labels in the report's order (the study's appendix order).
std::string problem_names(const ResultsIndex& index) {
  std::string out;
  for (const schema::ProblemRecord* p : index.problems()) {
    const auto& cases = index.results().cases;
    const bool run = std::any_of(cases.begin(), cases.end(), [&](const schema::CaseResult& c) {
      return c.spec.problem == p->id;
    });
    if (run)
      out += fmt::format("{}{}", out.empty() ? "" : ", ", schema::label(p->id));
  }
  return out;
}

std::string seconds(const std::optional<double>& s) {
  if (!s)
    return "unknown";
  if (*s >= 120)
    return fmt::format("{:.1f} min", *s / 60);
  return fmt::format("{:.1f} s", *s);
}

/// The first `n` words of a command line, with " …" when there were more.
std::string first_words(const std::string& command, std::size_t n) {
  std::size_t end = 0;
  for (std::size_t k = 0; k < n && end != std::string::npos; ++k) {
    end = command.find_first_not_of(' ', end);
    end = end == std::string::npos ? end : command.find(' ', end);
  }
  return end == std::string::npos ? command : command.substr(0, end) + " …";
}

/// A merged run: its parts' machine time and the command without its list of files.
std::string merged_run_text(const schema::RunInfo& run) {
  std::string out = fmt::format(
      "Merged from {} results files, the earliest started {}; {} of wall time summed over "
      "them (machine time: parts may have run one after another or side by side), each part "
      "with at most {} parallel worker(s)",
      run.merged_files, run.started_utc.empty() ? "at a time not recorded" : run.started_utc,
      seconds(finite(run.wall_seconds)), run.jobs);
  if (finite(run.peak_rss_mb))
    out +=
        fmt::format(", peak memory {:.0f} MB (the largest of the parts' contact-suite processes)",
                    run.peak_rss_mb);
  if (!run.command_line.empty())
    out += fmt::format("; command `{}`", first_words(run.command_line, 3));
  return out;
}

std::string run_paragraph(const schema::ResultsDocument& r) {
  std::string out = "**Run.** ";
  if (r.run.merged_files > 0) {
    out += merged_run_text(r.run);
  } else {
    out += r.run.started_utc.empty() ? "Start time not recorded" : "Started " + r.run.started_utc;
    out += fmt::format("; {} wall time with {} parallel worker(s)",
                       seconds(finite(r.run.wall_seconds)), r.run.jobs);
    if (finite(r.run.peak_rss_mb))
      out += fmt::format(", peak memory {:.0f} MB", r.run.peak_rss_mb);
    if (!r.run.command_line.empty())
      out += fmt::format("; command `{}`", r.run.command_line);
  }
  out += ".";
  if (!r.source.empty())
    out += fmt::format(" Results file: `{}`.", r.source);
  return out + "\n\n";
}

std::string cases_paragraph(const ResultsIndex& index) {
  const auto& cs = index.results().cases;
  using schema::CaseResult;
  std::string out = fmt::format(
      "**What was run.** {} case(s): problems {}; meshes {}; elements {}; algorithms {}; contact "
      "{}; target {}; nodal stresses {}",
      cs.size(), problem_names(index),
      distinct(cs, [](const CaseResult& c) { return c.spec.mesh; }),
      distinct(cs, [](const CaseResult& c) { return c.spec.element; }),
      distinct(cs, [](const CaseResult& c) { return c.spec.algorithm; }),
      distinct(cs, [](const CaseResult& c) { return c.spec.contact; }),
      distinct(cs, [](const CaseResult& c) { return c.spec.target; }),
      distinct(cs, [](const CaseResult& c) { return c.spec.recovery; }));
  std::map<std::string, int> overrides;
  for (const auto& c : cs) {
    for (const auto& [k, v] : c.spec.overrides)
      ++overrides[fmt::format("{}={}", k, v)];
  }
  if (!overrides.empty()) {
    std::string list;
    for (const auto& [kv, n] : overrides)
      list += fmt::format("{}{} ({} cases)", list.empty() ? "" : ", ", kv, n);
    out += "; parameter overrides " + list;
  }
  return out + ".\n\n";
}

std::string outcome_paragraph(const schema::ResultsDocument& r) {
  const StatusCounts n = count_statuses(r);
  std::string out = fmt::format("**Outcome.** {} converged, {} did not converge, {} failed.",
                                n.converged, n.not_converged, n.failed);
  double total = 0;
  const schema::CaseResult* slowest = nullptr;
  for (const auto& c : r.cases) {
    if (!finite(c.wall_seconds))
      continue;
    total += c.wall_seconds;
    if (slowest == nullptr || c.wall_seconds > slowest->wall_seconds)
      slowest = &c;
  }
  if (slowest != nullptr) {
    out +=
        fmt::format(" Time in the cases: {} in total; the slowest, `{}`, took {}.", seconds(total),
                    schema::case_id(slowest->spec), seconds(slowest->wall_seconds));
  }
  out += "\n\n";
  if (n.not_converged + n.failed > 0) {
    MarkdownTable table({"Case", "Status", "Reason"});
    for (const auto& c : r.cases) {
      if (c.status != schema::CaseStatus::converged) {
        table.add_row({fmt::format("`{}`", schema::case_id(c.spec)),
                       std::string(schema::to_string(c.status)), c.reason});
      }
    }
    out += fmt::format(
        "<details><summary>Cases that did not converge or failed ({})</summary>\n\n"
        "{}\n</details>\n\n",
        n.not_converged + n.failed, table.render());
  }
  return out;
}

std::string environment_paragraph(const schema::ResultsDocument& r) {
  const auto pairs = flatten_environment(r.run.environment);
  if (pairs.empty())
    return "**Environment.** Not recorded in the results file.\n\n";
  MarkdownTable table({"Environment", "Value"});
  for (const auto& [k, v] : pairs)
    table.add_row({k, v});
  return "**Environment** (machine, versions, solver settings, from the results file):\n\n" +
         table.render() + "\n";
}

}  // namespace

StatusCounts count_statuses(const schema::ResultsDocument& results) {
  StatusCounts n;
  for (const auto& c : results.cases) {
    switch (c.status) {
      case schema::CaseStatus::converged:
        ++n.converged;
        break;
      case schema::CaseStatus::not_converged:
        ++n.not_converged;
        break;
      case schema::CaseStatus::failed:
      case schema::CaseStatus::timeout:
        ++n.failed;
        break;
    }
  }
  return n;
}

std::vector<std::pair<std::string, std::string>> flatten_environment(const nlohmann::json& env) {
  std::vector<std::pair<std::string, std::string>> out;
  if (!env.is_null())
    flatten_into(env, "", out);
  return out;
}

std::string summary_section(const ResultsIndex& index, const std::vector<Finding>& findings) {
  const schema::ResultsDocument& r = index.results();
  std::string out = "## Summary\n\n";
  out += run_paragraph(r) + cases_paragraph(index) + outcome_paragraph(r);
  out += "**Findings** (generated from the data):\n\n";
  if (findings.empty())
    out += "- None: no graded row in this results file.\n";
  for (const auto& f : findings)
    out += "- " + f.sentence + "\n";
  out += '\n';
  out += environment_paragraph(r);
  return out;
}

}  // namespace cs::reports
