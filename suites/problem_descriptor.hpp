#pragma once
// One problem of the battery, declared once: what the report and `list` know of it (its
// schema record: title, analysis type, singular or not, graded quantities, the study's tables),
// its settable parameters, and the builder of its model.
//
// Each problem has one file under suites/problems/ that defines the specialization
// `problem_descriptor<ProblemId::X>()`. The catalogue (suites/problem_catalog.hpp) collects
// them over every enumerator of ProblemId, so a problem named in the vocabulary without its
// descriptor file fails to link. Adding a problem: its oracle, its problem file, and its line
// in schema/case_axes.hpp.

#include <vector>

#include "schema/problem_record.hpp"
#include "suites/case_spec.hpp"
#include "suites/parameters.hpp"

namespace cs::suites {

struct ProblemSetup;

struct ProblemDescriptor {
  schema::ProblemRecord record;
  std::vector<ParameterSpec> parameters;
  /// Builds the model of one case (parameters validated and resolved).
  ProblemSetup (*build)(const CaseSpec& spec, const Parameters& params) = nullptr;
};

/// The descriptor of problem P; defined in P's file under suites/problems/.
template <ProblemId P>
const ProblemDescriptor& problem_descriptor();

}  // namespace cs::suites
