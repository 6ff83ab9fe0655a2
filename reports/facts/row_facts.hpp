#pragma once
// What the report may say of each baseline row, decided once by the grading layer (grading/)
// and queried by every page: the signed errors, the study's grade and c, the noise-aware trend
// and observed order, whether the F case is credible (interface checks) and whether its grade is
// the luck of one mesh. Only a row that is `evidence()` may support or refute a claim or an
// advice; the others are shown, marked, and never counted.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "grading/convergence.hpp"
#include "reports/results/results_index.hpp"

namespace cs::reports {

/// The study's option families: AL and PM (penalty; AL augments only past FTOLN), LMP and PLM
/// (Lagrange multipliers; the same without friction) and MPC (the study's IMC).
enum class OptionFamily { penalty, multiplier, mpc };
OptionFamily family_of(schema::Algorithm algorithm);

/// A limit of a row's values other than the exact value: its error (%) and the values' order.
struct BiasedLimit {
  double error_percent = 0.0;
  double order = 0.0;
};

/// A failed interface check and its measure (e.g. force balance 19.2: the relative residual).
struct CheckFailure {
  std::string check;
  std::optional<double> measure;
};

/// One nonsingular baseline row, graded.
struct RowFacts {
  const schema::RowVerdict* row = nullptr;
  schema::ProblemId problem = schema::ProblemId::P_p;
  std::optional<schema::Situation> situation;  ///< the problem record's (none in old files)
  schema::Quantity quantity = schema::Quantity::sigma_c;
  schema::Element element = schema::Element::Q4;
  Option option;
  /// Another code's option, as the report names it ("calculix linear-ss"); empty for ours.
  std::string code;
  std::array<std::optional<double>, 3> errors;          ///< signed percent, C, M, F
  std::optional<schema::Grade> grade;                   ///< Eq. 46 on F
  bool study_c = false;                                 ///< the study's convergence flag
  std::optional<grading::ConvergenceAssessment> trend;  ///< all three meshes present
  std::optional<double> order;                          ///< guarded observed order
  /// Where the values converge, by their trusted estimate, to a limit other than the exact value
  /// (the exact value outside the GCI band, the limit's error beyond 0.01 points and beyond its
  /// step from the F error): that error (%)
  /// and the values' order; `order` is then empty, an order of the errors being meaningless.
  std::optional<BiasedLimit> biased_limit;
  std::string order_note;              ///< why there is no order
  bool fine_converged = false;         ///< the F case's contact iterations converged
  bool credible = true;                ///< the F case passes the interface checks
  std::vector<CheckFailure> failures;  ///< the F case's failed interface checks
  bool luck = false;                   ///< e or g on F after an error above 100 % on C or M

  /// The read's own resolution on F (ResultsIndex::read_resolution_percent): half a node
  /// spacing for a value read between two nodes, 0 for one read at a point.
  double read_resolution_on_f = 0.0;

  /// What one refinement changes in the error, |e_F - e_M| (points; 0 without both): the noise
  /// a comparison of two rows' F errors must beat (the verdict page's ties, the claims' trends).
  double m_to_f_change() const;

  /// May this row support or refute a statement? Graded, converged on F, credible, not luck.
  bool evidence() const { return grade && fine_converged && credible && !luck; }

  /// A value read between two nodes whose F error does not settle its grade within that read's
  /// resolution (grading::read_settles_grade): H_a Q4 a_FE, +-6.25 % (the edge half a node
  /// spacing off), or CM_p PM ss Q4 c/a, +10.49 +- 4.42 % (s or u). Its grade says nothing of
  /// the option's accuracy.
  bool read_leaves_grade_open() const;

  /// May this row support or refute a statement about an option's accuracy (a grade, which of
  /// two errors is larger)? evidence() and not read_leaves_grade_open(). The claims leave such
  /// reads out; the verdict page lets one bound its cell's grade at its best reading
  /// (grading::best_reading_grade), which no reading of it beats.
  bool accuracy_evidence() const { return evidence() && !read_leaves_grade_open(); }

  /// For a claim of a grade or better ("g or better"): evidence() and its F error is `grade` or
  /// better at every reading (true), at none (false), within its resolution
  /// (grading::read_at_least); nullopt when not evidence, or the read leaves it open. One rule
  /// with the verdict page: a read counts where every reading of it says the same.
  std::optional<bool> at_least(schema::Grade grade) const;
};

/// The flat punch's divergence verdicts of one baseline row.
struct DivergenceFacts {
  const schema::RowVerdict* row = nullptr;
  schema::ProblemId problem = schema::ProblemId::F_p;
  schema::Element element = schema::Element::Q4;
  Option option;
  std::string code;     ///< as RowFacts::code
  bool eq47 = false;    ///< the study's Eq. 47
  bool strict = false;  ///< monotone growth with a square-root-like exponent
  std::optional<double> exponent;
  bool fine_converged = false;
  bool credible = true;                ///< the F case passes the interface checks
  std::vector<CheckFailure> failures;  ///< the F case's failed interface checks
  /// May this row support or refute a statement? Converged and credible on F.
  bool evidence() const { return fine_converged && credible; }
};

/// The rows the verdicts are made of: patch-recovered stresses of the code's displacements (for
/// ours the baseline's), without parameter overrides.
bool on_common_basis(const schema::CaseSpec& spec);

/// RowFacts::code of a row's spec: "calculix linear-ss" for another code's row, empty for ours.
std::string code_label(const schema::CaseSpec& spec);

/// The facts of any row (another code's, a rigid target's): ungraded without an F value.
RowFacts facts_of_row(const ResultsIndex& index, const schema::RowVerdict& row);

/// Every graded quantity of every nonsingular baseline row that has an F value, in index order.
std::vector<RowFacts> row_facts(const ResultsIndex& index);

/// Every complete singular baseline row.
std::vector<DivergenceFacts> divergence_facts(const ResultsIndex& index);

/// The same facts of the other codes' rows that are set beside our baseline: on the discretized
/// target, on the common basis (our patch recovery of their displacements), without parameter
/// overrides. Empty for results of one code.
std::vector<RowFacts> other_code_row_facts(const ResultsIndex& index);
std::vector<DivergenceFacts> other_code_divergence_facts(const ResultsIndex& index);

/// The facts of one code's rows ("calculix", solvers.hpp) on one target, on the common basis,
/// without parameter overrides: what that code's own verdict cells are made of.
std::vector<RowFacts> code_row_facts(const ResultsIndex& index, const std::string& code,
                                     schema::TargetKind target);
std::vector<DivergenceFacts> code_divergence_facts(const ResultsIndex& index,
                                                   const std::string& code,
                                                   schema::TargetKind target);

/// The row facts of one problem (a view into `all`).
std::vector<const RowFacts*> facts_of(const std::vector<RowFacts>& all, schema::ProblemId problem);

/// True when two rows' values coincide on every mesh at the study's resolution
/// (grading::values_coincide): the pages then show them as one row ("AL, PM").
bool coincide(const schema::RowVerdict& a, const schema::RowVerdict& b);

}  // namespace cs::reports
