#include "reports/findings/recommendation_section.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "reports/tables/cross_code_rows.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

using schema::ProblemId;

/// Largest number of option labels a cell lists before "and N more".
constexpr std::size_t kListed = 6;

void add_nonsingular(const ResultsIndex& index, const schema::RowVerdict& row,
                     OptionAssessment& a) {
  for (std::size_t m = 0; m < kMeshes.size(); ++m) {
    if (!row.errors[m]) {
      a.failures = true;
      continue;
    }
    a.worst_error = std::max(a.worst_error, std::abs(*row.errors[m]));
  }
  if (row.errors[2])
    a.fine_error = std::max(a.fine_error, std::abs(*row.errors[2]));
  a.converging += row.converging.value_or(false) ? 1 : 0;
  a.failures = a.failures || index.any_not_converged(row);
}

void add_row(const ResultsIndex& index, const schema::RowVerdict& row, bool singular,
             OptionAssessment& a) {
  ++a.rows;
  if (singular) {
    a.converging += row.divergence && row.divergence->diverges ? 1 : 0;
    a.failures = a.failures || !row.divergence || index.any_not_converged(row);
  } else {
    add_nonsingular(index, row, a);
  }
  if (const schema::CaseResult* c = index.case_of(row, kFinestMesh))
    a.iterations = std::max(a.iterations, c->iterations);
}

OptionVerdict verdict_of(const OptionAssessment& a, bool singular) {
  if (a.failures)
    return OptionVerdict::avoid;
  if (singular)
    return a.converging == a.rows ? OptionVerdict::trust : OptionVerdict::avoid;
  if (a.fine_error < 1.0 && a.worst_error < 5.0 && a.converging == a.rows)
    return OptionVerdict::trust;
  return a.fine_error < 5.0 ? OptionVerdict::usable : OptionVerdict::avoid;
}

std::string list_labels(const std::vector<const OptionAssessment*>& options, bool with_error) {
  if (options.empty())
    return kMissing;
  std::string out;
  for (std::size_t i = 0; i < options.size() && i < kListed; ++i) {
    out += (i == 0 ? "" : ", ") + options[i]->label();
    if (with_error)
      out += fmt::format(" ({})", format_percent(options[i]->worst_error));
  }
  if (options.size() > kListed)
    out += fmt::format(" and {} more", options.size() - kListed);
  return out;
}

std::string verdict_word(OptionVerdict v) {
  switch (v) {
    case OptionVerdict::trust:
      return "trust";
    case OptionVerdict::usable:
      return "usable";
    case OptionVerdict::avoid:
      return "avoid";
  }
  return {};
}

std::vector<std::string> situation_row(const Situation& s,
                                       const std::vector<OptionAssessment>& all) {
  const OptionAssessment& best = all.front();
  std::vector<const OptionAssessment*> trusted, avoided;
  for (std::size_t i = 1; i < all.size(); ++i) {
    if (all[i].verdict == OptionVerdict::trust)
      trusted.push_back(&all[i]);
  }
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    if (it->verdict == OptionVerdict::avoid)
      avoided.push_back(&*it);
  }
  std::string use = fmt::format("**{}** ({})", best.label(), verdict_word(best.verdict));
  if (best.verdict == OptionVerdict::avoid)
    use = fmt::format("none to trust; least bad {}", best.label());
  const std::string rows = fmt::format("{} of {}", best.converging, best.rows);
  if (s.singular) {
    return {s.name,
            use,
            kMissing,
            kMissing,
            rows + " diverge",
            std::to_string(best.iterations),
            list_labels(trusted, false),
            list_labels(avoided, false)};
  }
  return {s.name,
          use,
          format_percent(best.fine_error),
          format_percent(best.worst_error),
          rows,
          std::to_string(best.iterations),
          list_labels(trusted, false),
          list_labels(avoided, true)};
}

}  // namespace

std::string OptionAssessment::label() const {
  return fmt::format("{} {}", option.label(), schema::to_string(element));
}

const std::vector<Situation>& situations() {
  using S = schema::Situation;
  static const std::vector<Situation> all{
      {"Flat contact, nodes aligned (P<sub>p</sub>, P<sub>a</sub>)", S::matched_patch, false},
      {"Flat contact, nodes not aligned, stiff indenter (P′<sub>p</sub>, P′<sub>a</sub>)",
       S::mismatched_patch, false},
      {"Flat contact, nodes not aligned, bodies of one modulus (P′ E<sub>1</sub>)",
       S::mismatched_patch_equal_moduli, false},
      {"Smooth curved contact (Hertz: H<sub>p</sub> both stresses, H<sub>a</sub>)",
       S::smooth_curved, false},
      {"Punch with rounded edges (Steuermann S(1), S(1/3), S(1/7))", S::rounded_punch, false},
      {"Sharp punch edge: a singularity the analyst must be alerted to (F<sub>p</sub>, "
       "F<sub>a</sub>)",
       S::flat_punch, true},
  };
  return all;
}

std::vector<OptionAssessment> assess_situation(const ResultsIndex& index, const Situation& s,
                                               const std::string& solver) {
  std::vector<OptionAssessment> out;
  for (const auto element : schema::values<schema::Element>()) {
    for (const Option& option : all_options()) {
      OptionAssessment a{option, element};
      for (const schema::ProblemRecord* p : index.problems()) {
        if (p->situation != s.situation)
          continue;
        const ProblemId id = p->id;
        for (const auto& q : p->quantities) {
          // The stresses an analyst checks against strength; the contact half-width is graded
          // apart (its error is bounded by the mesh, half an element).
          if (q.quantity == schema::Quantity::contact_half_width)
            continue;
          if (const auto* row = solver_row(index, solver, id, q.quantity, element, option))
            add_row(index, *row, s.singular, a);
        }
      }
      if (a.rows == 0)
        continue;
      a.verdict = verdict_of(a, s.singular);
      out.push_back(a);
    }
  }
  std::stable_sort(out.begin(), out.end(), [&](const auto& x, const auto& y) {
    if (x.verdict != y.verdict)
      return x.verdict < y.verdict;
    if (s.singular)
      return x.converging > y.converging;
    if (x.fine_error != y.fine_error)
      return x.fine_error < y.fine_error;
    if (x.worst_error != y.worst_error)
      return x.worst_error < y.worst_error;
    return x.iterations < y.iterations;
  });
  return out;
}

std::string recommendation_section(const ResultsIndex& index) {
  const bool cross_code = is_cross_code(index);
  std::vector<std::string> header{"Situation",        "Use",
                                  "F error",          "worst C/M/F",
                                  "converging",       "iterations (F)",
                                  "Also trustworthy", "Avoid (worst error)"};
  if (cross_code)
    header.insert(header.begin() + 1, "Solver");
  MarkdownTable table(header);
  for (const Situation& s : situations()) {
    for (const std::string& solver : solvers_in(index)) {
      const auto all = assess_situation(index, s, solver);
      if (all.empty())
        continue;
      auto cells = situation_row(s, all);
      if (cross_code)
        cells.insert(cells.begin() + 1, solver_display_name(solver));
      table.add_row(std::move(cells));
    }
  }
  if (table.n_rows() == 0)
    return {};
  const std::string per_solver =
      cross_code
          ? "- Each solver's options are ranked among themselves: an analyst chooses "
            "within the code they run. A solver's option is its own mapping of the "
            "study's option (see the cross-code section); a case that timed out counts "
            "as not converged. Another solver's **iterations** are its own count (CalculiX: the "
            "Newton iterations of all increments in its .sta file), not ours.\n"
          : "";
  return "## Which contact option to use\n\n" + table.render() +
         "\n- Per situation, every option (algorithm, contact discretization, element) over all "
         "the situation's graded rows: **F error** is the largest error on the fine mesh, "
         "**worst C/M/F** the largest on any mesh, **converging** how many rows converge by the "
         "study's rule (for the flat punch: diverge by the strict verdict), **iterations** the "
         "most contact iterations on F, each one solve with the factorized stiffness.\n"
         "- **trust**: every fine-mesh error below 1 % (the study's e), every row converging, no "
         "mesh worse than 5 %. **usable**: every fine-mesh error below 5 % (g or better). "
         "**avoid**: anything else, or a case that did not converge. For the flat punch, "
         "**trust** means every row diverges as the singularity demands. Options are ranked by "
         "verdict, then fine-mesh error, worst error and iterations; the first is under "
         "**Use**.\n" +
         per_solver +
         "- Option sets that coincide (AL and PM, LMP and PLM where the augmentation or the "
         "tangent plays no part) rank side by side; the per-row evidence is in the tables "
         "that follow.\n\n";
}

}  // namespace cs::reports
