#pragma once
// The neutral case directory: one model as any external code reads it (docs/solver-protocol.md
// describes every field). Two files:
//   mesh.msh   Gmsh MSH 4.1 ASCII: nodes (tag = our node index + 1, coordinates (x, z, 0)),
//              the bodies' quadrilaterals (tag = our element index + 1; Gmsh type 3 = Q4,
//              16 = Q8, whose node order is ours: corners counter-clockwise, then mid-sides),
//              every edge set as line elements (type 1 or 8) and every node set as point
//              elements (type 15), each set a physical group named as the set;
//   case.json  the analysis, the bodies' materials and roles, the boundary conditions, the
//              loads (consistent nodal forces), the contact pair with, for a rigid target, its
//              analytic profile (type, parameters, position, signed-distance formula), the load
//              control and what is sampled.
// Everything comes from the same ProblemSetup the built-in solver and the CalculiX adapter run
// on. No I/O in the text builders; write_case_directory() writes both files.

#include <filesystem>
#include <string>

#include "suites/case_spec.hpp"
#include "suites/problem_setup.hpp"

namespace cs::suites {

/// The format version written into case.json ("format_version"); readers refuse others.
inline constexpr int kCaseFormatVersion = 1;

/// The mesh of `setup` as a Gmsh MSH 4.1 ASCII document (see the file comment).
std::string gmsh_document(const solver::Model& model);

/// The case description of `spec` on `setup` as a JSON document (see docs/solver-protocol.md).
/// `option` is the external code's option label the case runs ("" for none).
std::string case_json(const CaseSpec& spec, const ProblemSetup& setup, const std::string& option);

/// Writes mesh.msh and case.json into `dir` (which must exist). Throws std::runtime_error
/// naming the file when it cannot be written.
void write_case_directory(const std::filesystem::path& dir, const CaseSpec& spec,
                          const ProblemSetup& setup, const std::string& option);

}  // namespace cs::suites
