#include "reports/facts/row_facts.hpp"

#include <algorithm>
#include <cmath>

#include "grading/accuracy.hpp"
#include "grading/convergence.hpp"
#include "grading/credibility.hpp"
#include "grading/divergence.hpp"
#include "grading/richardson.hpp"
#include "reports/facts/solvers.hpp"

namespace cs::reports {
namespace {

using schema::MeshLevel;

/// The measure behind a failed interface check, for the evidence a page quotes.
std::optional<double> measure_of(const schema::InterfaceChecks& c, const std::string& check) {
  if (check == "force balance" && c.force_balance)
    return std::abs(*c.force_balance);
  if (check == "tensile pressure")
    return c.max_tensile_over_p;
  if (check == "pressure outside the patch")
    return c.max_outside_over_p;
  return std::nullopt;
}

/// Whether a row's F case converged and passes the interface checks, and the checks it fails:
/// into the facts of a row, nonsingular or singular alike.
template <typename Facts>
void add_credibility(const ResultsIndex& index, const schema::RowVerdict& row, Facts& f) {
  const schema::CaseResult* fine = index.case_of(row, MeshLevel::F);
  f.fine_converged = fine && fine->status == schema::CaseStatus::converged;
  if (!fine || !fine->interface)
    return;
  const grading::Credibility c = grading::credibility(*fine->interface);
  f.credible = c.credible;
  for (const auto& name : c.failures)
    f.failures.push_back({name, measure_of(*fine->interface, name)});
}

/// An order of the errors assumes the values converge to the exact value. Where the values' own
/// trusted estimate converges elsewhere (the exact value outside its GCI band, the limit's error
/// beyond the study's resolution and beyond the extrapolation's own step from F), the row
/// converges to a bias: no order of the errors, and the
/// limit is kept (H_p Q8 sigma_x AL ss: -0.35 %, where VF reads -0.35 %). A row whose F case did
/// not converge or fails an interface check says nothing of how the option converges.
void note_biased_limit(const ResultsIndex& index, RowFacts& f) {
  if (!f.fine_converged || !f.credible)
    return;
  const grading::TrustedEstimate t = grading::trusted_estimate(*f.row);
  const auto exact = index.exact_of(*f.row);
  if (!t.estimate || !t.estimate->richardson || !exact || *exact == 0.0 ||
      grading::gci_bounds_error(*f.row, *exact).value_or(true))
    return;
  // The bias must also exceed what the extrapolation itself adds (|e_F - e_limit|), or the
  // limit is no firmer than the F value it was drawn from.
  const double limit_error = grading::error_percent(*t.estimate->richardson, *exact);
  const double step = std::abs(*f.errors[2] - limit_error);
  if (std::abs(limit_error) <= std::max(grading::kErrorResolutionPercent, step))
    return;
  f.order.reset();
  f.biased_limit = BiasedLimit{limit_error, *t.estimate->observed_order};
}

void add_trend(const ResultsIndex& index, RowFacts& f) {
  const auto& e = f.errors;
  if (!e[0] || !e[1] || !e[2])
    return;
  const double resolution = index.read_resolution_percent(*f.row, MeshLevel::C);
  f.trend = grading::assess_convergence(*e[0], *e[1], *e[2], resolution);
  const grading::ObservedOrder o = grading::observed_order(*e[0], *e[1], *e[2], resolution);
  f.order = o.order;
  f.order_note = o.note;
  f.luck = grading::luck_of_one_mesh(*e[0], *e[1], *e[2]);
  note_biased_limit(index, f);
}

/// The rows on the common basis without parameter overrides whose code and target `keep`
/// accepts (ours on the discretized target: the baseline).
template <typename Keep>
std::vector<const schema::RowVerdict*> common_rows(const ResultsIndex& index, Keep&& keep) {
  std::vector<const schema::RowVerdict*> out;
  for (const auto& r : index.results().rows) {
    const schema::CaseSpec& s = r.spec;
    if (on_common_basis(s) && keep(code_of(s), s.target))
      out.push_back(&r);
  }
  return out;
}

/// The rows of codes other than ours set beside the baseline (other_code_row_facts).
std::vector<const schema::RowVerdict*> other_code_rows(const ResultsIndex& index) {
  return common_rows(index, [](const std::string& code, schema::TargetKind target) {
    return code != builtin_solver_label() && target == schema::TargetKind::Discretized;
  });
}

/// The rows of one code on one target (code_row_facts).
std::vector<const schema::RowVerdict*> rows_of_code(const ResultsIndex& index,
                                                    const std::string& code,
                                                    schema::TargetKind target) {
  return common_rows(
      index, [&](const std::string& c, schema::TargetKind t) { return c == code && t == target; });
}

DivergenceFacts divergence_of_row(const ResultsIndex& index, const schema::RowVerdict& r) {
  DivergenceFacts d;
  d.row = &r;
  d.problem = r.spec.problem;
  d.element = r.spec.element;
  d.option = {r.spec.algorithm, r.spec.contact};
  d.code = code_label(r.spec);
  const auto& v = r.values;
  d.eq47 = grading::eq47_diverging(*v[0], *v[1], *v[2]);
  const schema::DivergenceVerdict strict = grading::divergence_verdict(*v[0], *v[1], *v[2]);
  d.strict = strict.diverges;
  d.exponent = strict.exponent;
  add_credibility(index, r, d);
  return d;
}

/// The facts of `rows`' nonsingular rows with an F value.
std::vector<RowFacts> nonsingular_facts(const ResultsIndex& index,
                                        const std::vector<const schema::RowVerdict*>& rows) {
  std::vector<RowFacts> out;
  for (const schema::RowVerdict* r : rows) {
    if (!index.singular(r->spec.problem) && r->errors[2])
      out.push_back(facts_of_row(index, *r));
  }
  return out;
}

/// The divergence facts of `rows`' complete singular rows.
std::vector<DivergenceFacts> singular_facts(const ResultsIndex& index,
                                            const std::vector<const schema::RowVerdict*>& rows) {
  std::vector<DivergenceFacts> out;
  for (const schema::RowVerdict* r : rows) {
    if (index.singular(r->spec.problem) && ResultsIndex::complete(*r))
      out.push_back(divergence_of_row(index, *r));
  }
  return out;
}

}  // namespace

OptionFamily family_of(schema::Algorithm algorithm) {
  switch (algorithm) {
    case schema::Algorithm::AL:
    case schema::Algorithm::PM:
      return OptionFamily::penalty;
    case schema::Algorithm::LMP:
    case schema::Algorithm::PLM:
      return OptionFamily::multiplier;
    case schema::Algorithm::MPC:
      return OptionFamily::mpc;
  }
  return OptionFamily::mpc;
}

double RowFacts::m_to_f_change() const {
  return errors[1] && errors[2] ? std::abs(*errors[2] - *errors[1]) : 0.0;
}

bool RowFacts::read_leaves_grade_open() const {
  return errors[2] && !grading::read_settles_grade(*errors[2], read_resolution_on_f);
}

std::optional<bool> RowFacts::at_least(schema::Grade grade) const {
  if (!evidence() || !errors[2])
    return std::nullopt;
  return grading::read_at_least(*errors[2], read_resolution_on_f, grade);
}

bool on_common_basis(const schema::CaseSpec& spec) {
  return spec.recovery == schema::Recovery::spr && spec.overrides.empty();
}

std::string code_label(const schema::CaseSpec& spec) {
  const std::string code = code_of(spec);
  return code == builtin_solver_label() ? std::string()
                                        : solver_display_name(code) + " " + option_label_of(spec);
}

RowFacts facts_of_row(const ResultsIndex& index, const schema::RowVerdict& r) {
  RowFacts f;
  f.row = &r;
  f.problem = r.spec.problem;
  if (const schema::ProblemRecord* p = index.problem(f.problem))
    f.situation = p->situation;
  f.quantity = r.quantity;
  f.element = r.spec.element;
  f.option = {r.spec.algorithm, r.spec.contact};
  f.code = code_label(r.spec);
  f.errors = r.errors;
  if (r.errors[2])
    f.grade = grading::grade_of_error(*r.errors[2]);
  f.study_c = r.converging.value_or(false);
  f.read_resolution_on_f = index.read_resolution_percent(r, MeshLevel::F);
  add_credibility(index, *f.row, f);
  add_trend(index, f);  // after the credibility, which a biased limit needs
  return f;
}

std::vector<RowFacts> row_facts(const ResultsIndex& index) {
  return nonsingular_facts(index, index.baseline_rows());
}

std::vector<DivergenceFacts> divergence_facts(const ResultsIndex& index) {
  return singular_facts(index, index.baseline_rows());
}

std::vector<RowFacts> other_code_row_facts(const ResultsIndex& index) {
  return nonsingular_facts(index, other_code_rows(index));
}

std::vector<DivergenceFacts> other_code_divergence_facts(const ResultsIndex& index) {
  return singular_facts(index, other_code_rows(index));
}

std::vector<RowFacts> code_row_facts(const ResultsIndex& index, const std::string& code,
                                     schema::TargetKind target) {
  return nonsingular_facts(index, rows_of_code(index, code, target));
}

std::vector<DivergenceFacts> code_divergence_facts(const ResultsIndex& index,
                                                   const std::string& code,
                                                   schema::TargetKind target) {
  return singular_facts(index, rows_of_code(index, code, target));
}

std::vector<const RowFacts*> facts_of(const std::vector<RowFacts>& all, schema::ProblemId problem) {
  std::vector<const RowFacts*> out;
  for (const auto& f : all) {
    if (f.problem == problem)
      out.push_back(&f);
  }
  return out;
}

bool coincide(const schema::RowVerdict& a, const schema::RowVerdict& b) {
  return std::ranges::equal(a.values, b.values, [](const auto& x, const auto& y) {
    return x.has_value() == y.has_value() && (!x || grading::values_coincide(*x, *y));
  });
}

}  // namespace cs::reports
