#pragma once
// The report's first screen: which option to use for which situation, and why. A situation is
// a family of the battery's problems (flat contact with matched nodes; mismatched nodes with a
// stiff indenter; mismatched nodes between bodies of one modulus; smooth curved contact;
// rounded punch edges; a sharp, singular punch edge). An option is an algorithm, a contact
// discretization and an element.
//
// For each situation and option, over every baseline row of the situation's problems:
//   F error   = the largest |error| on the finest mesh (percent);
//   worst     = the largest |error| on any of C, M, F;
//   converging = how many rows converge (the study's monotone-error rule);
//   iterations = the largest number of contact iterations on F (each is one solve with the
//               factorized stiffness, so it is the cost in solves).
// Verdicts (the study's Eq. 46 bands):
//   trust  — every F error < 1 % (e), every row converging, worst < 5 %;
//   usable — every F error < 5 % (g or better);
//   avoid  — anything else, or a case that did not converge or failed.
// For the singular flat punch the verdict is the strict divergence verdict of every row
// (schema::divergence_verdict): trust when every row diverges, avoid otherwise.

#include <string>
#include <vector>

#include "reports/results/results_index.hpp"
#include "reports/tables/cross_code_rows.hpp"

namespace cs::reports {

enum class OptionVerdict { trust, usable, avoid };

/// One option's figures in one situation.
struct OptionAssessment {
  Option option;
  schema::Element element = schema::Element::Q4;
  int rows = 0;
  double fine_error = 0.0;   ///< percent, max over rows (nonsingular)
  double worst_error = 0.0;  ///< percent, max over rows and meshes (nonsingular)
  int converging = 0;        ///< rows converging (nonsingular) or diverging (singular)
  int iterations = 0;        ///< max contact iterations on the finest mesh
  bool failures = false;     ///< a case did not converge or failed, or a value is missing
  OptionVerdict verdict = OptionVerdict::avoid;
  std::string label() const;  ///< "LMP ss Q4"
};

/// A situation the advice is given for: its name, and the problems it groups, which are those
/// whose record names `situation` (their descriptors declare it).
struct Situation {
  std::string name;
  schema::Situation situation = schema::Situation::matched_patch;
  bool singular = false;
};

/// The situations of the battery, in report order.
const std::vector<Situation>& situations();

/// Every option of `solver` (a results.json solver label) with a row in the situation, best
/// first (trust, usable, avoid; then by F error and worst error, then by iterations).
std::vector<OptionAssessment> assess_situation(const ResultsIndex& index, const Situation& s,
                                               const std::string& solver = builtin_solver_label());

/// The section (empty when no situation has a row). With several solvers in the document, one
/// row per situation and solver, each solver's options ranked among themselves.
std::string recommendation_section(const ResultsIndex& index);

}  // namespace cs::reports
