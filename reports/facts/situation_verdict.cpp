#include "reports/facts/situation_verdict.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include "grading/accuracy.hpp"
#include "grading/convergence.hpp"
#include "reports/facts/solvers.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {
namespace {

using schema::ProblemId;

/// The situations in the report's order: the study's, then those beyond it.
constexpr std::array kSituationOrder = {schema::Situation::matched_patch,
                                        schema::Situation::mismatched_patch,
                                        schema::Situation::mismatched_patch_equal_moduli,
                                        schema::Situation::smooth_curved,
                                        schema::Situation::rounded_punch,
                                        schema::Situation::conformal_fit,
                                        schema::Situation::frictional,
                                        schema::Situation::flat_punch};

/// The problems of a situation, as their records say (a record without one is in none).
std::vector<ProblemId> problems_of(const ResultsIndex& index, schema::Situation situation) {
  std::vector<ProblemId> out;
  for (const schema::ProblemRecord* p : index.problems()) {
    if (p->situation == situation)
      out.push_back(p->id);
  }
  return out;
}

/// Table 2's quantities of a problem, or all of them when the study has no row for it.
bool graded_in_verdict(const ResultsIndex& index, ProblemId problem, schema::Quantity q) {
  const schema::ProblemRecord* record = index.problem(problem);
  if (!record)
    return false;
  const bool has_study_rows = std::any_of(record->quantities.begin(), record->quantities.end(),
                                          [](const auto& d) { return !d.study_row.empty(); });
  const schema::QuantityDefinition* d = record->definition(q);
  return d && (!has_study_rows || !d->study_row.empty()) &&
         q != schema::Quantity::contact_half_width;
}

using CellKey = std::tuple<std::string, OptionFamily, std::optional<schema::Algorithm>,
                           schema::ContactKind, schema::Element>;

/// Our families whose two members do not coincide (compare_options, the problem pages' rule)
/// on some row of the situation's problems, e.g. AL and PM with friction, or where one member
/// has rows the other lacks (AL run on H_p only, PM on H_p and H_a): their cells there are
/// split by algorithm, so that no cell shows one member's error under both names.
std::set<OptionFamily> split_families(const ResultsIndex& index, const std::vector<RowFacts>& rows,
                                      const std::vector<DivergenceFacts>& singular,
                                      const std::vector<ProblemId>& problems) {
  std::set<std::tuple<ProblemId, schema::Quantity, schema::Element>> keys;
  const auto in_situation = [&](ProblemId p) {
    return std::find(problems.begin(), problems.end(), p) != problems.end();
  };
  for (const auto& f : rows) {
    if (f.code.empty() && in_situation(f.problem))
      keys.insert({f.problem, f.quantity, f.element});
  }
  for (const auto& d : singular) {
    if (d.code.empty() && in_situation(d.problem))
      keys.insert({d.problem, d.row->quantity, d.element});
  }
  std::vector<Slot> slots;
  for (const auto& [problem, quantity, element] : keys)
    slots.push_back({problem, quantity, element});
  std::set<OptionFamily> out;
  for (const auto& [a, b] : {std::pair{schema::Algorithm::AL, schema::Algorithm::PM},
                             std::pair{schema::Algorithm::LMP, schema::Algorithm::PLM}}) {
    for (const auto contact : schema::values<schema::ContactKind>()) {
      const OptionComparison c = compare_options(index, {a, contact}, {b, contact}, slots);
      if (c.compared > 0 && (!c.coincide() || c.only_one > 0))
        out.insert(family_of(a));
    }
  }
  return out;
}

void add_row(OptionCell& cell, const RowFacts& f) {
  cell.rows.push_back(&f);
  const double e = *f.errors[2];
  if (!cell.worst_error || std::abs(e) > std::abs(*cell.worst_error))
    cell.worst_error = e;
  cell.min_error = cell.min_error ? std::min(*cell.min_error, e) : e;
  cell.max_error = cell.max_error ? std::max(*cell.max_error, e) : e;
  cell.largest_m_to_f_change = std::max(cell.largest_m_to_f_change, f.m_to_f_change());
  cell.problems.insert(f.problem);
  cell.n_not_credible += f.credible ? 0 : 1;
  for (const auto& failure : f.failures)
    cell.failed_checks.insert(failure.check);
  cell.n_luck += f.luck ? 1 : 0;
  cell.n_not_converged += f.fine_converged ? 0 : 1;
}

/// A read that leaves its grade open still bounds the cell's grade: at its best reading it is
/// no better than grading::best_reading_grade, so a cell never shows a grade better than every
/// reading of one of its rows (CM_p c/a +8.28 +- 2.21 % beside stresses of g: the cell is s).
void cap_by_open_reads(OptionCell& c) {
  for (const RowFacts* f : c.open_reads) {
    const double e = *f->errors[2];
    const schema::Grade best = grading::best_reading_grade(e, f->read_resolution_on_f);
    if (!schema::is_worse(best, *c.worst_grade))
      continue;
    c.worst_grade = best;
    c.worst_error = e;
    c.worst_resolution = f->read_resolution_on_f;
    c.min_error = std::min(*c.min_error, e);
    c.max_error = std::max(*c.max_error, e);
    c.largest_m_to_f_change = std::max(c.largest_m_to_f_change, f->m_to_f_change());
  }
}

/// Rows of the same solvers and targets as `rows` and `singular`, on the common basis, with C
/// and M cases but no F value: an F case that failed or timed out (n_failed), or none at all
/// (n_missing, e.g. a battery part not run). They have no row facts, but their option's cell
/// must say so, and an option none of whose F cases ran still gets one.
void add_failed_rows(
    const ResultsIndex& index, const std::vector<ProblemId>& problems,
    const std::vector<RowFacts>& rows, const std::vector<DivergenceFacts>& singular,
    const std::function<OptionCell&(const std::string&, const Option&, schema::Element)>& cell_of) {
  std::set<std::pair<std::string, schema::TargetKind>> populations;  // solver, target
  for (const auto& f : rows) {
    if (f.row != nullptr)  // a fact without its row names no population
      populations.insert({code_of(f.row->spec), f.row->spec.target});
  }
  for (const auto& d : singular) {
    if (d.row != nullptr)
      populations.insert({code_of(d.row->spec), d.row->spec.target});
  }
  for (const auto& r : index.results().rows) {
    const ProblemId p = r.spec.problem;
    const MeshState fine_state = index.state(r, schema::MeshLevel::F);
    if (!on_common_basis(r.spec) || !populations.contains({code_of(r.spec), r.spec.target}) ||
        std::find(problems.begin(), problems.end(), p) == problems.end() ||
        (!index.singular(p) && !graded_in_verdict(index, p, r.quantity)) ||
        (fine_state != MeshState::failed && fine_state != MeshState::missing) ||
        index.state(r, schema::MeshLevel::C) == MeshState::missing)
      continue;
    OptionCell& c = cell_of(code_label(r.spec), {r.spec.algorithm, r.spec.contact}, r.spec.element);
    c.problems.insert(p);
    if (fine_state == MeshState::missing) {
      ++c.n_missing;
      continue;
    }
    ++c.n_failed;
    const schema::CaseResult* fine = index.case_of(r, schema::MeshLevel::F);
    if (c.failed_reason.empty() && fine != nullptr)
      c.failed_reason = fine->reason;
  }
}

std::vector<OptionCell> make_cells(const ResultsIndex& index,
                                   const std::vector<ProblemId>& problems,
                                   const std::vector<RowFacts>& rows,
                                   const std::vector<DivergenceFacts>& singular) {
  std::map<CellKey, OptionCell> cells;
  const std::set<OptionFamily> split = split_families(index, rows, singular, problems);
  const auto cell_of = [&](const std::string& code, const Option& o,
                           schema::Element el) -> OptionCell& {
    const OptionFamily family = family_of(o.algorithm);
    std::optional<schema::Algorithm> algorithm;
    if (code.empty() && split.contains(family))
      algorithm = o.algorithm;
    OptionCell& c = cells[{code, family, algorithm, o.contact, el}];
    if (code.empty())
      c.members.insert(o.algorithm);
    c.code = code;
    c.family = family;
    c.algorithm = algorithm;
    c.contact = o.contact;
    c.element = el;
    return c;
  };
  for (const ProblemId p : problems) {
    for (const auto& f : rows) {
      if (f.problem != p || !graded_in_verdict(index, p, f.quantity))
        continue;
      // A read whose resolution leaves its grade open (a stick-zone edge half a node off) is not
      // graded as it reads; it counts only at its best reading (cap_by_open_reads).
      if (!f.read_leaves_grade_open())
        add_row(cell_of(f.code, f.option, f.element), f);
      else if (f.evidence()) {
        OptionCell& c = cell_of(f.code, f.option, f.element);
        c.open_reads.push_back(&f);
        c.problems.insert(f.problem);  // run on it, graded or not
      }
    }
    for (const auto& d : singular) {
      if (d.problem != p)
        continue;
      OptionCell& c = cell_of(d.code, d.option, d.element);
      c.singular_rows.push_back(&d);
      c.problems.insert(d.problem);
      c.n_eq47 += d.eq47 ? 1 : 0;
      c.n_strict += d.strict ? 1 : 0;
      c.n_not_converged += d.fine_converged ? 0 : 1;
      c.n_not_credible += d.credible ? 0 : 1;
      for (const auto& failure : d.failures)
        c.failed_checks.insert(failure.check);
    }
  }
  add_failed_rows(index, problems, rows, singular, cell_of);
  std::set<ProblemId> run;  // the situation's problems some option was run on
  for (const auto& [key, c] : cells)
    run.insert(c.problems.begin(), c.problems.end());
  std::vector<OptionCell> out;
  for (auto& [key, c] : cells) {
    if (c.rows.empty() && c.singular_rows.empty() && c.n_failed == 0 && c.n_missing == 0)
      continue;  // open reads alone: nothing graded, no cell
    std::ranges::set_difference(run, c.problems, std::back_inserter(c.not_run_on));
    // No grade from a solve that failed, nor from part of the situation's problems.
    const bool whole =
        c.n_not_converged == 0 && c.n_failed == 0 && c.n_missing == 0 && c.not_run_on.empty();
    if (c.worst_error && whole) {
      c.worst_grade = grading::grade_of_error(*c.worst_error);
      cap_by_open_reads(c);
    }
    c.evidence = c.n_not_credible == 0 && c.n_luck == 0 && whole;
    out.push_back(std::move(c));
  }
  return out;
}

/// The checks every cell fails (none for the flat punch, graded by divergence). Only cells of
/// more than one option family can show that a failure is not the option's: a lone family's
/// failure stays its own.
std::vector<std::string> common_failures(const SituationVerdict& v) {
  const bool several_families =
      std::any_of(v.cells.begin(), v.cells.end(),
                  [&](const OptionCell& c) { return c.family != v.cells.front().family; });
  if (v.singular || !several_families)
    return {};
  std::set<std::string> common = v.cells.front().failed_checks;
  for (const auto& c : v.cells) {
    std::erase_if(common,
                  [&](const std::string& check) { return !c.failed_checks.contains(check); });
  }
  return {common.begin(), common.end()};
}

/// A cell to avoid: graded u, an F case that did not converge, or failing an interface check
/// that some other option passes.
bool fails_on_its_own(const OptionCell& c, const std::vector<std::string>& common) {
  const bool own_failure =
      std::any_of(c.failed_checks.begin(), c.failed_checks.end(), [&](const std::string& check) {
        return std::find(common.begin(), common.end(), check) == common.end();
      });
  return own_failure || c.worst_grade == schema::Grade::u || c.n_not_converged > 0 ||
         c.n_failed > 0;
}

void rank(SituationVerdict& v) {
  v.common_failures = common_failures(v);
  for (const auto& c : v.cells) {
    const bool fails = v.singular ? c.n_eq47 < static_cast<int>(c.singular_rows.size()) ||
                                        c.n_failed > 0 || c.n_not_credible > 0
                                  : fails_on_its_own(c, v.common_failures);
    if (fails)
      v.avoid.push_back(&c);
    if (!c.evidence || v.singular || !c.worst_grade)
      continue;
    if (!v.best_grade || schema::is_worse(*v.best_grade, *c.worst_grade))
      v.best_grade = c.worst_grade;
  }
  double lowest = INFINITY, highest = 0.0;  // of the best cells' |worst error|
  for (const auto& c : v.cells) {
    if (v.singular) {
      if (c.n_strict == static_cast<int>(c.singular_rows.size()) && c.n_not_converged == 0 &&
          c.n_failed == 0 && c.n_missing == 0 && c.n_not_credible == 0 && c.not_run_on.empty())
        v.best.push_back(&c);
      continue;
    }
    if (!c.evidence || c.worst_grade != v.best_grade)
      continue;
    v.best.push_back(&c);
    const double a = std::abs(*c.worst_error);
    lowest = std::min(lowest, a);
    highest = std::max(highest, a);
    v.best_abs_spread = highest - lowest;
    v.best_min = v.best_min ? std::min(*v.best_min, *c.min_error) : *c.min_error;
    v.best_max = v.best_max ? std::max(*v.best_max, *c.max_error) : *c.max_error;
    v.best_noise =
        std::max({v.best_noise, c.largest_m_to_f_change, grading::kErrorResolutionPercent});
  }
  if (v.best.empty() || v.singular || v.best_abs_spread <= v.best_noise)
    return;
  const OptionCell* most = *std::ranges::min_element(
      v.best, {}, [](const OptionCell* c) { return std::abs(*c->worst_error); });
  // The most accurate cell's own resolution: what one refinement changes in it (at least 0.01
  // points). Not the tie's tolerance: an option exact on every mesh would otherwise share the
  // lead with options 0.3 points off that move by 0.44 (bodies of one modulus).
  // No cut falls within the study's resolution: a cell within 0.01 points of a leader leads too
  // (ss Q8 +0.0392 % and ns Q8 +0.0443 % print alike), so the bound is extended over such steps.
  v.leaders_noise = std::max(most->largest_m_to_f_change, grading::kErrorResolutionPercent);
  std::vector<const OptionCell*> by_error = v.best;
  std::ranges::stable_sort(by_error, {},
                           [](const OptionCell* c) { return std::abs(*c->worst_error); });
  const double first_bound = std::abs(*most->worst_error) + v.leaders_noise;
  double bound = first_bound;
  for (const OptionCell* c : by_error) {
    const double a = std::abs(*c->worst_error);
    if (a > bound)
      break;
    v.leaders.push_back(c);
    v.leaders_max_abs = a;
    v.leaders_extended = v.leaders_extended || a > first_bound;
    bound = std::max(bound, a + grading::kErrorResolutionPercent);
  }
  // `best`'s order, as the advice lists options.
  std::ranges::sort(v.leaders, {}, [&](const OptionCell* c) {
    return std::ranges::find(v.best, c) - v.best.begin();
  });
}

}  // namespace

std::vector<SituationVerdict> situation_verdicts(const ResultsIndex& index,
                                                 const std::vector<RowFacts>& rows,
                                                 const std::vector<DivergenceFacts>& singular) {
  std::vector<SituationVerdict> out;
  for (const schema::Situation s : kSituationOrder) {
    SituationVerdict v;
    v.key = std::string(schema::to_string(s));
    v.title = std::string(schema::label(s));
    v.title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(v.title[0])));
    v.problems = problems_of(index, s);
    v.singular = !v.problems.empty() && index.singular(v.problems.front());
    v.cells = make_cells(index, v.problems, rows, singular);
    if (v.cells.empty())
      continue;
    out.push_back(std::move(v));
    rank(out.back());
  }
  return out;
}

namespace {

/// "AL, PM", "LMP, PLM" or "MPC".
std::string family_label(OptionFamily family) {
  switch (family) {
    case OptionFamily::penalty:
      return "AL, PM";
    case OptionFamily::multiplier:
      return "LMP, PLM";
    case OptionFamily::mpc:
      return "MPC";
  }
  return {};
}

}  // namespace

std::string members_label(OptionFamily family, const std::set<schema::Algorithm>& members) {
  return members.empty() ? family_label(family) : join_words(names_of(members), ", ");
}

std::string option_label(const OptionCell& cell) {
  return cell.code.empty()
             ? members_label(cell.family, cell.members) + " " + std::string(to_string(cell.contact))
             : cell.code;
}

std::string cells_label(const std::vector<const OptionCell*>& cells) {
  // Ours by family (its discretizations listed), then each other code's option (its label names
  // the discretization).
  using Key = std::tuple<std::string, OptionFamily, std::optional<schema::Algorithm>>;
  std::map<Key, std::map<schema::Element, std::string>> by;
  std::map<Key, std::set<schema::Algorithm>> members;
  for (const OptionCell* c : cells) {
    members[{c->code, c->family, c->algorithm}].insert(c->members.begin(), c->members.end());
    std::string& contacts = by[{c->code, c->family, c->algorithm}][c->element];
    if (c->code.empty())
      contacts += (contacts.empty() ? "" : "/") + std::string(schema::to_string(c->contact));
  }
  std::string out;
  for (const auto& [key, elements] : by) {
    // Elements with the same discretizations share one entry: "ss/ns Q4/Q8".
    std::map<std::string, std::string> by_contacts;
    for (const auto& [element, contacts] : elements) {
      std::string& els = by_contacts[contacts];
      els += (els.empty() ? "" : "/") + std::string(schema::to_string(element));
    }
    std::string part;
    for (const auto& [contacts, els] : by_contacts)
      part += (part.empty() ? " " : ", ") + (contacts.empty() ? "" : contacts + " ") + els;
    const auto& [code, family, algorithm] = key;
    out += (out.empty() ? "" : "; ") +
           (code.empty() ? members_label(family, members.at(key)) : code) + part;
  }
  return out;
}

}  // namespace cs::reports
