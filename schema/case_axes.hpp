#pragma once
// The axes of a case: which problem, mesh level, element, contact algorithm, contact
// discretization, target, stress recovery and solver. One table per axis, here and nowhere else
// (see schema/name_table.hpp): the command line, case ids, results.json, the gate and the report
// all read these names.
//
// Adding an enumerator: add it to its enum and one `case` to its entry() (and, for an
// algorithm or a contact, to its traits()). -Werror=switch names every switch that must learn it.

#include <array>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <vector>

#include "schema/name_table.hpp"

namespace cs::schema {

/// The battery's problems (the study's eleven first, names as the study prints them, primes
/// spelled out; then the problems beyond the study: Pprime_p_E1 and Pprime_a_E1, the
/// mismatched-node patch tests with an indenter of the block's modulus; FP_p, the frictional
/// patch test, and CM_p, Cattaneo-Mindlin partial slip; IF_p and IF_a, the interference fits of
/// a shaft in a ring and a sphere in a shell, conformal contact). Each has one descriptor in
/// suites/problems/.
///
/// A problem defined outside the battery (a test's, an extension's) has no enumerator: it is
/// registered at run time (suites::register_problem, one line) and takes an id from
/// kFirstRegisteredProblem up, whose names the registry keeps (registered_entry below). The
/// enumerators stay the keys of the built-in problems, so that every switch over them is
/// checked by -Werror=switch and results.json keeps its names; see suites/problem_catalog.hpp.
enum class ProblemId : std::uint8_t {
  P_p,
  P_a,
  Pprime_p,
  Pprime_a,
  H_p,
  H_a,
  S_1,
  S_1_3,
  S_1_7,
  F_p,
  F_a,
  Pprime_p_E1,
  Pprime_a_E1,
  FP_p,
  CM_p,
  IF_p,
  IF_a,
};
/// The first id of the problems registered at run time (ids below it are enumerators).
inline constexpr std::uint8_t kFirstRegisteredProblem = 128;

/// The names of a registered problem ({} for an id no one registered), and the registered ids
/// in the order of registration (schema/registered_problems.cpp). Not constexpr: the vocabulary
/// functions reach them only at run time (name_table.hpp).
AxisEntry registered_entry(ProblemId v);
std::vector<ProblemId> registered_values(ProblemId);

constexpr std::string_view axis_name(ProblemId) {
  return "problem";
}
constexpr AxisEntry entry(ProblemId v) {
  switch (v) {
    case ProblemId::P_p:
      return {"P_p", "", "P<sub>p</sub>"};
    case ProblemId::P_a:
      return {"P_a", "", "P<sub>a</sub>"};
    case ProblemId::Pprime_p:
      return {"Pprime_p", "P'_p", "P′<sub>p</sub>"};
    case ProblemId::Pprime_a:
      return {"Pprime_a", "P'_a", "P′<sub>a</sub>"};
    case ProblemId::H_p:
      return {"H_p", "", "H<sub>p</sub>"};
    case ProblemId::H_a:
      return {"H_a", "", "H<sub>a</sub>"};
    case ProblemId::S_1:
      return {"S_1", "", "S(1)"};
    case ProblemId::S_1_3:
      return {"S_1_3", "", "S(1/3)"};
    case ProblemId::S_1_7:
      return {"S_1_7", "", "S(1/7)"};
    case ProblemId::F_p:
      return {"F_p", "", "F<sub>p</sub>"};
    case ProblemId::F_a:
      return {"F_a", "", "F<sub>a</sub>"};
    case ProblemId::Pprime_p_E1:
      return {"Pprime_p_E1", "P'_p_E1", "P′<sub>p</sub>(E<sub>1</sub>)"};
    case ProblemId::Pprime_a_E1:
      return {"Pprime_a_E1", "P'_a_E1", "P′<sub>a</sub>(E<sub>1</sub>)"};
    case ProblemId::FP_p:
      return {"FP_p", "", "FP<sub>p</sub>"};
    case ProblemId::CM_p:
      return {"CM_p", "", "CM<sub>p</sub>"};
    case ProblemId::IF_p:
      return {"IF_p", "", "IF<sub>p</sub>"};
    case ProblemId::IF_a:
      return {"IF_a", "", "IF<sub>a</sub>"};
  }
  // Not an enumerator: at compile time the end of the table (count(), values()); at run time
  // a registered problem, if any.
  if (std::is_constant_evaluated())
    return {};
  return registered_entry(v);
}

/// The study's systematically refined meshes, coarse, medium (h/2) and fine (h/4), and one
/// level beyond the study, very fine (h/8), run only when asked for (`--meshes ...,VF`).
enum class MeshLevel : std::uint8_t { C, M, F, VF };
/// The study's three meshes: the default of every run, the meshes a row is graded on (Table 2
/// grades F) and whose C-M-F verdicts the report compares with the study's.
inline constexpr std::array<MeshLevel, 3> kStudyMeshes{MeshLevel::C, MeshLevel::M, MeshLevel::F};
constexpr std::string_view axis_name(MeshLevel) {
  return "mesh level";
}
constexpr AxisEntry entry(MeshLevel v) {
  switch (v) {
    case MeshLevel::C:
      return {"C", "", ""};
    case MeshLevel::M:
      return {"M", "", ""};
    case MeshLevel::F:
      return {"F", "", ""};
    case MeshLevel::VF:
      return {"VF", "", ""};
  }
  return {};
}

/// The element: 4-node bilinear or 8-node serendipity quadrilateral (the study's 4Q, 8Q).
enum class Element : std::uint8_t { Q4, Q8 };
constexpr std::string_view axis_name(Element) {
  return "element";
}
constexpr AxisEntry entry(Element v) {
  switch (v) {
    case Element::Q4:
      return {"Q4", "4Q", ""};
    case Element::Q8:
      return {"Q8", "8Q", ""};
  }
  return {};
}

/// The study's contact algorithms (its names). LMP and PLM are the same method without
/// friction; MPC is the study's IMC.
enum class Algorithm : std::uint8_t { AL, PM, LMP, PLM, MPC };
constexpr std::string_view axis_name(Algorithm) {
  return "algorithm";
}
constexpr AxisEntry entry(Algorithm v) {
  switch (v) {
    case Algorithm::AL:
      return {"AL", "", ""};
    case Algorithm::PM:
      return {"PM", "", ""};
    case Algorithm::LMP:
      return {"LMP", "", ""};
    case Algorithm::PLM:
      return {"PLM", "", ""};
    case Algorithm::MPC:
      return {"MPC", "IMC", ""};
  }
  return {};
}

/// How the report groups and draws an algorithm.
struct AlgorithmTraits {
  /// The study's column (it merges the algorithms that coincide without friction):
  /// "AL_PM", "LMP_PLM" or "MPC", as in data/study/ansys_results.csv.
  std::string_view study_column;
  std::string_view colour;  ///< figure colour, "#rrggbb"
  bool penalty_based;       ///< enforcement depends on a penalty stiffness (FKN)
};
constexpr AlgorithmTraits traits(Algorithm v) {
  switch (v) {
    case Algorithm::AL:
      return {"AL_PM", "#1f77b4", true};
    case Algorithm::PM:
      return {"AL_PM", "#ff7f0e", true};
    case Algorithm::LMP:
      return {"LMP_PLM", "#2ca02c", false};
    case Algorithm::PLM:
      return {"LMP_PLM", "#d62728", false};
    case Algorithm::MPC:
      return {"MPC", "#9467bd", false};
  }
  return {};
}

/// Contact discretization: node-to-surface, surface-to-surface (Gauss points), mortar.
enum class ContactKind : std::uint8_t { ss, ns, mortar };
constexpr std::string_view axis_name(ContactKind) {
  return "contact";
}
constexpr AxisEntry entry(ContactKind v) {
  switch (v) {
    case ContactKind::ss:
      return {"ss", "", ""};
    case ContactKind::ns:
      return {"ns", "", ""};
    case ContactKind::mortar:
      return {"mortar", "", ""};
  }
  return {};
}

/// How the report words and draws a discretization.
struct ContactTraits {
  std::string_view words;  ///< "surface-to-surface"
  bool in_study;           ///< the study ran it (ns, ss); mortar is ours
  int dash;                ///< gnuplot dash type
  int point;               ///< gnuplot point type
};
constexpr ContactTraits traits(ContactKind v) {
  switch (v) {
    case ContactKind::ss:
      return {"surface-to-surface", true, 1, 7};
    case ContactKind::ns:
      return {"node-to-surface", true, 2, 5};
    case ContactKind::mortar:
      return {"mortar", false, 4, 9};
  }
  return {};
}

/// The indenter: a stiff meshed body (the study's choice, E ratio 1e6) or a rigid profile.
enum class TargetKind : std::uint8_t { Discretized, Rigid };
constexpr std::string_view axis_name(TargetKind) {
  return "target";
}
constexpr AxisEntry entry(TargetKind v) {
  switch (v) {
    case TargetKind::Discretized:
      return {"discretized", "", ""};
    case TargetKind::Rigid:
      return {"rigid", "", ""};
  }
  return {};
}

/// How the graded nodal stresses are recovered:
///   spr: superconvergent patch recovery (the default: O(h^2) at a loaded surface for Q4);
///   extrapolated: extrapolated from the Gauss points and averaged, the nodal stresses
///     commercial codes print (the study's ANSYS values), O(h) at a loaded surface for Q4;
///   own: another code's own nodal stresses, as its users read them (the `own` basis; an
///     external code's spr is the `common` basis: our patch recovery of its displacements).
enum class Recovery : std::uint8_t { spr, extrapolated, own };
constexpr std::string_view axis_name(Recovery) {
  return "stress recovery";
}
constexpr AxisEntry entry(Recovery v) {
  switch (v) {
    case Recovery::spr:
      return {"spr", "", "patch-recovered"};
    case Recovery::extrapolated:
      return {"extrapolated", "", "extrapolated"};
    case Recovery::own:
      return {"own", "", "the code's own"};
  }
  return {};
}

/// Which solver produced a case: ours, results imported from any other code (whose name the
/// case records beside this kind, see CaseSpec::solver_name), or a registered code run through
/// the solver protocol (docs/solver-protocol.md; CalculiX among them, through its C++ adapter),
/// named by its manifest and one of its options (CaseSpec::solver_name, solver_option).
enum class SolverKind : std::uint8_t { builtin, imported, external };
constexpr std::string_view axis_name(SolverKind) {
  return "solver";
}
constexpr AxisEntry entry(SolverKind v) {
  switch (v) {
    case SolverKind::builtin:
      return {"builtin", "", "contact-suite"};
    case SolverKind::imported:
      return {"imported", "", "imported"};
    case SolverKind::external:
      return {"external", "", "external"};
  }
  return {};
}

}  // namespace cs::schema
