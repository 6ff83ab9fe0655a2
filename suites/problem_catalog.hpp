#pragma once
// What is known about each of the study's problems before anything is built: its title,
// analysis type, graded quantities, settable parameters and the study's tables for it.
// Read by `contact-suite list`, by the problem builders and by the case validation.

#include <string>
#include <vector>

#include "suites/case_spec.hpp"
#include "suites/parameters.hpp"

namespace cs::suites {

/// The catalog entry of one problem.
struct ProblemInfo {
  ProblemId id;
  std::string title;                    ///< e.g. "Hertz contact of a cylinder (plane strain)"
  bool axisymmetric;                    ///< plane strain otherwise
  std::vector<std::string> quantities;  ///< graded quantities, e.g. {"sigma_c", "sigma_h"}
  std::vector<ParameterSpec> parameters;
  std::string study_tables;  ///< the study's appendix tables for it, e.g. "7a-7d, 8a-8d"
};

/// The catalog entry of `id`.
const ProblemInfo& problem_info(ProblemId id);

}  // namespace cs::suites
