#pragma once
// One problem of the battery, declared once: every fact about it. Its schema record (what the
// report and `list` know: title, analysis type, singular or not, graded quantities, the study's
// tables, and the situation and length scale below), its settable parameters, the builder of
// its model, the analyst's situation it stands for, the length that normalizes its results,
// its relative cost, its mesh layout and its entry in `contact-suite oracle`. The constructor
// takes them all, so a descriptor that leaves one out does not compile; nothing else in the
// code keeps a list of problems or switches over them.
//
// Each built-in problem has one file under suites/problems/ that defines the specialization
// `problem_descriptor<ProblemId::X>()`. The catalogue (suites/problem_catalog.hpp) collects
// them over every enumerator of ProblemId, so a problem named in the vocabulary without its
// descriptor file fails to link. Adding a built-in problem: its oracle, its problem file, and
// its line in schema/case_axes.hpp. A problem outside the battery is registered at run time
// instead (register_problem, one line).

#include <utility>
#include <vector>

#include "schema/problem_facts.hpp"
#include "schema/problem_record.hpp"
#include "suites/case_spec.hpp"
#include "suites/mesh_layout.hpp"
#include "suites/oracle_entry.hpp"
#include "suites/parameters.hpp"

namespace cs::suites {

struct ProblemSetup;

/// Builds the model of one case (parameters validated and resolved).
using ProblemBuilder = ProblemSetup (*)(const CaseSpec& spec, const Parameters& params);

struct ProblemDescriptor {
  /// Every fact, none defaulted. `record` gets `situation` and `length_scale` copied in.
  ProblemDescriptor(schema::ProblemRecord record_, std::vector<ParameterSpec> parameters_,
                    ProblemBuilder build_, schema::Situation situation_,
                    schema::LengthScale length_scale_, double relative_cost_,
                    MeshLayout mesh_layout_, OracleEntry oracle_)
      : record(std::move(record_)),
        parameters(std::move(parameters_)),
        build(build_),
        situation(situation_),
        length_scale(length_scale_),
        relative_cost(relative_cost_),
        mesh_layout(mesh_layout_),
        oracle(oracle_) {
    record.situation = situation;
    record.length_scale = length_scale;
  }

  schema::ProblemRecord record;
  std::vector<ParameterSpec> parameters;
  ProblemBuilder build;
  schema::Situation situation;
  schema::LengthScale length_scale;
  /// A rough cost of one model at level C relative to the uniform study meshes (1): S is 30
  /// (its C block has 8,372 to 16,809 elements, H's 256, F's 1,024). `run` schedules and
  /// shards by it (times the level's f^2, and 3 for Q8) so that the largest models start first;
  /// changing it moves cases between shards.
  double relative_cost;
  MeshLayout mesh_layout;
  OracleEntry oracle;
};

/// The descriptor of problem P; defined in P's file under suites/problems/.
template <ProblemId P>
const ProblemDescriptor& problem_descriptor();

}  // namespace cs::suites
