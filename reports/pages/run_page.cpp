#include "reports/pages/run_page.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// Every run of the set: the document's own (its source) and those combined into it.
std::vector<std::pair<std::string, const schema::RunInfo*>> runs_of(
    const schema::ResultsDocument& doc) {
  // A combined document's source names every file ("first, second, ..."); its own run is the
  // first file's.
  std::string added;
  for (const auto& [source, run] : doc.added_runs)
    added += ", " + source;
  const std::string first = doc.source.ends_with(added)
                                ? doc.source.substr(0, doc.source.size() - added.size())
                                : doc.source;
  std::vector<std::pair<std::string, const schema::RunInfo*>> out{{first, &doc.run}};
  for (const auto& [source, run] : doc.added_runs)
    out.emplace_back(source, &run);
  return out;
}

/// The analyses behind the cases: a case graded on another stress basis (extrapolated, a
/// code's own) shares the solve of its patch-recovered twin.
std::size_t analysis_count(const schema::ResultsDocument& doc) {
  std::set<std::string> solves;
  for (const auto& c : doc.cases) {
    schema::CaseSpec spec = c.spec;
    spec.recovery = schema::Recovery::spr;
    solves.insert(schema::case_id(spec));
  }
  return solves.size();
}

/// Files behind the set: each run counts once, a merged one as its parts.
int file_count(const schema::ResultsDocument& doc) {
  int n = 0;
  for (const auto& [source, run] : runs_of(doc))
    n += std::max(1, run->merged_files);
  return n;
}

double machine_seconds(const schema::ResultsDocument& doc) {
  double s = 0.0;
  for (const auto& [source, run] : runs_of(doc))
    s += std::isfinite(run->wall_seconds) ? run->wall_seconds : 0.0;
  return s;
}

void flatten(const nlohmann::json& j, const std::string& prefix, TemplateData& list) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items())
      flatten(v, prefix.empty() ? k : prefix + "." + k, list);
    return;
  }
  TemplateData d;
  d.set("key", prefix.empty() ? std::string("(value)") : prefix);
  d.set("value", j.is_string() ? j.get<std::string>() : j.dump());
  list.push_back(d);
}

}  // namespace

std::string run_line(const schema::ResultsDocument& doc) {
  int converged = 0, not_converged = 0, other = 0;
  for (const auto& c : doc.cases) {
    if (c.status == schema::CaseStatus::converged)
      ++converged;
    else if (c.status == schema::CaseStatus::not_converged)
      ++not_converged;
    else
      ++other;
  }
  TemplateData d;
  d.set("n_cases", std::to_string(doc.cases.size()));
  const std::size_t analyses = analysis_count(doc);
  d.set("analyses",
        analyses < doc.cases.size() ? TemplateData(std::to_string(analyses)) : TemplateData(false));
  d.set("converged", std::to_string(converged));
  d.set("not_converged", std::to_string(not_converged));
  d.set("failed", std::to_string(other));
  d.set("files", std::to_string(file_count(doc)));
  d.set("several_files", file_count(doc) > 1);
  d.set("minutes", fmt::format("{:.1f}", machine_seconds(doc) / 60.0));
  return render_template(templates::run_line, d);
}

std::string run_page(const schema::ResultsDocument& doc) {
  TemplateData d;
  d.set("line", run_line(doc));
  d.set("runs", template_list(runs_of(doc), [](const auto& source_run) {
          const schema::RunInfo& r = *source_run.second;
          TemplateData rd;
          rd.set("source", source_run.first.empty() ? std::string("(this run)") : source_run.first);
          rd.set("started", r.started_utc.empty() ? std::string("not recorded") : r.started_utc);
          rd.set("minutes", std::isfinite(r.wall_seconds)
                                ? fmt::format("{:.1f}", r.wall_seconds / 60.0)
                                : std::string("—"));
          rd.set("parts", std::to_string(std::max(1, r.merged_files)));
          rd.set("jobs", std::to_string(r.jobs));
          rd.set("peak", std::isfinite(r.peak_rss_mb) ? fmt::format("{:.0f}", r.peak_rss_mb)
                                                      : std::string("—"));
          rd.set("command", r.command_line);
          rd.set("build", r.build().value_or(kMissing));
          return rd;
        }));
  TemplateData env{TemplateData::type::list};
  flatten(doc.run.environment, "", env);
  d.set("environment", env);
  return render_template(templates::run_page, d);
}

}  // namespace cs::reports
