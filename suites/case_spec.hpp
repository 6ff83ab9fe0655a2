#pragma once
// One analysis of the battery: which problem, which mesh, which element, which contact
// algorithm and discretization, which target, how nodal stresses are recovered, and any
// parameter overrides.
//
// The option axes are orthogonal enums; names (as used by the command line, results.json and
// the reports) are converted in one place, case_spec.cpp, and validated there once.

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "solver/mesh/mesh.hpp"

namespace cs::suites {

/// The study's eleven problems (names as the study prints them, primes spelled out).
enum class ProblemId { P_p, P_a, Pprime_p, Pprime_a, H_p, H_a, S_1, S_1_3, S_1_7, F_p, F_a };

/// The study's three systematically refined meshes: coarse, medium (h/2), fine (h/4).
enum class MeshLevel { C, M, F };

/// The study's contact algorithms (its names). LMP and PLM are the same method without
/// friction; both run the Lagrange multiplier algorithm. MPC is the study's IMC.
enum class Algorithm { AL, PM, LMP, PLM, MPC };

/// Contact discretization: node-to-surface, surface-to-surface (Gauss points), mortar.
enum class ContactKind { ns, ss, mortar };

/// The indenter: a stiff meshed body (the study's choice, E ratio 1e6) or a rigid profile.
enum class TargetKind { Discretized, Rigid };

/// How the graded nodal stresses are recovered (solver/stress_recovery.hpp):
///   spr: superconvergent patch recovery (the default: O(h^2) at a loaded surface for Q4);
///   extrapolated: extrapolated from the Gauss points and averaged, the nodal stresses
///     commercial codes print (the study's ANSYS values), O(h) at a loaded surface for Q4.
enum class Recovery { spr, extrapolated };

using solver::ElementType;

/// One analysis. `overrides` holds `--set name=value` pairs, validated by the problem.
struct CaseSpec {
  ProblemId problem = ProblemId::P_p;
  MeshLevel mesh = MeshLevel::C;
  ElementType element = ElementType::Q4;
  Algorithm algorithm = Algorithm::LMP;
  ContactKind contact = ContactKind::ss;
  TargetKind target = TargetKind::Discretized;
  Recovery recovery = Recovery::spr;
  std::map<std::string, double> overrides;
};

std::string_view to_string(ProblemId v);
std::string_view to_string(MeshLevel v);
std::string_view to_string(ElementType v);
std::string_view to_string(Algorithm v);
std::string_view to_string(ContactKind v);
std::string_view to_string(TargetKind v);
std::string_view to_string(Recovery v);

/// Parsers: exact names (and the aliases IMC for MPC, 4Q/8Q for Q4/Q8, discretized|rigid);
/// anything else throws SuiteInputError listing the accepted names.
ProblemId parse_problem(std::string_view name);
MeshLevel parse_mesh_level(std::string_view name);
ElementType parse_element(std::string_view name);
Algorithm parse_algorithm(std::string_view name);
ContactKind parse_contact(std::string_view name);
TargetKind parse_target(std::string_view name);
Recovery parse_recovery(std::string_view name);

/// Every value of each axis, in the study's order.
const std::vector<ProblemId>& all_problems();
const std::vector<MeshLevel>& all_mesh_levels();
const std::vector<ElementType>& all_elements();
const std::vector<Algorithm>& all_algorithms();
/// ns and ss: the study's discretizations. Mortar is a further option, see all_contacts().
const std::vector<ContactKind>& study_contacts();
const std::vector<ContactKind>& all_contacts();
const std::vector<Recovery>& all_recoveries();

/// True for the axisymmetric problems (P_a, Pprime_a, H_a, F_a).
bool is_axisymmetric(ProblemId p);
/// True for the singular flat-punch problems, graded for divergence (Eq. 47), not convergence.
bool is_singular(ProblemId p);

/// A stable identifier of a case: "H_p/F/Q4/LMP/ss" (+ "/rigid", "/extrapolated" and "/k=v"
/// overrides).
std::string case_id(const CaseSpec& spec);

/// Parses one `--set name=value` argument; throws SuiteInputError on a malformed one.
std::pair<std::string, double> parse_override(std::string_view text);

}  // namespace cs::suites
