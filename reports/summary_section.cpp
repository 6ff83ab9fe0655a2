#include "reports/summary_section.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "reports/markdown_table.hpp"
#include "reports/problem_catalog.hpp"

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

/// The distinct values of a case field, ordered by `order` (then by name).
template <class Field, class Order>
std::string distinct(const std::vector<CaseRecord>& cases, Field field, Order order) {
  std::vector<std::string> names;
  for (const auto& c : cases)
    names.push_back(field(c));
  std::sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
    return std::pair(order(a), a) < std::pair(order(b), b);
  });
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out;
}

int problem_order(const std::string& id) {
  const auto& all = all_problem_infos();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].id == id)
      return static_cast<int>(i);
  }
  return 99;
}

int mesh_order(const std::string& mesh) {
  return mesh == "C" ? 0 : mesh == "M" ? 1 : 2;
}

std::string problem_names(const std::vector<CaseRecord>& cases) {
  std::vector<std::string> ids;
  for (const auto& c : cases)
    ids.push_back(c.problem);
  std::sort(ids.begin(), ids.end(), [](const std::string& a, const std::string& b) {
    return problem_order(a) < problem_order(b);
  });
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::string out;
  for (const auto& id : ids) {
    const ProblemInfo* p = find_problem_info(id);
    out += (out.empty() ? "" : ", ") + (p != nullptr ? p->name_md : id);
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

std::string run_paragraph(const ResultsFile& r) {
  std::string out = "**Run.** ";
  out += r.run.started_utc.empty() ? "Start time not recorded" : "Started " + r.run.started_utc;
  out += fmt::format("; {} wall time with {} parallel worker(s)", seconds(r.run.wall_seconds),
                     r.run.jobs);
  if (r.run.peak_rss_mb)
    out += fmt::format(", peak memory {:.0f} MB", *r.run.peak_rss_mb);
  if (!r.run.command_line.empty())
    out += fmt::format("; command `{}`", r.run.command_line);
  return out + fmt::format(". Results file: `{}`.\n\n", r.source);
}

std::string cases_paragraph(const ResultsFile& r) {
  const auto& cs = r.cases;
  auto self = [](const std::string&) { return 0; };
  std::string out = fmt::format(
      "**What was run.** {} case(s): problems {}; meshes {}; elements {}; algorithms {}; contact "
      "{}; target {}; nodal stresses {}",
      cs.size(), problem_names(cs),
      distinct(
          cs, [](const CaseRecord& c) { return c.mesh; }, mesh_order),
      distinct(
          cs, [](const CaseRecord& c) { return c.element; }, self),
      distinct(
          cs, [](const CaseRecord& c) { return c.algorithm; }, algorithm_order),
      distinct(
          cs, [](const CaseRecord& c) { return c.contact; }, contact_order),
      distinct(
          cs, [](const CaseRecord& c) { return c.target; }, self),
      distinct(
          cs, [](const CaseRecord& c) { return c.recovery; },
          [](const std::string& r) { return r == "spr" ? 0 : 1; }));
  std::map<std::string, int> overrides;
  for (const auto& c : cs) {
    for (const auto& [k, v] : c.overrides)
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

std::string outcome_paragraph(const ResultsFile& r) {
  const StatusCounts n = count_statuses(r);
  std::string out = fmt::format("**Outcome.** {} converged, {} did not converge, {} failed.",
                                n.converged, n.not_converged, n.failed);
  double total = 0;
  const CaseRecord* slowest = nullptr;
  for (const auto& c : r.cases) {
    if (!c.wall_seconds)
      continue;
    total += *c.wall_seconds;
    if (slowest == nullptr || *c.wall_seconds > *slowest->wall_seconds)
      slowest = &c;
  }
  if (slowest != nullptr) {
    out += fmt::format(" Time in the cases: {} in total; the slowest, `{}`, took {}.",
                       seconds(total), slowest->id, seconds(slowest->wall_seconds));
  }
  out += "\n\n";
  if (n.not_converged + n.failed > 0) {
    MarkdownTable table({"Case", "Status", "Reason"});
    for (const auto& c : r.cases) {
      if (c.status != "converged")
        table.add_row({"`" + c.id + "`", c.status, c.reason});
    }
    out += fmt::format(
        "<details><summary>Cases that did not converge or failed ({})</summary>\n\n"
        "{}\n</details>\n\n",
        n.not_converged + n.failed, table.render());
  }
  return out;
}

std::string environment_paragraph(const ResultsFile& r) {
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

StatusCounts count_statuses(const ResultsFile& results) {
  StatusCounts n;
  for (const auto& c : results.cases) {
    if (c.status == "converged")
      ++n.converged;
    if (c.status == "not_converged")
      ++n.not_converged;
    if (c.status == "failed")
      ++n.failed;
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
  const ResultsFile& r = index.results();
  std::string out = "## 1. Summary\n\n";
  out += run_paragraph(r) + cases_paragraph(r) + outcome_paragraph(r);
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
