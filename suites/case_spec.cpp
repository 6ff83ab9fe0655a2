#include "suites/case_spec.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <utility>

#include <fmt/format.h>

#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

/// One row of a name table: the enum value, its canonical name, and an accepted alias.
template <class E>
struct NameRow {
  E value;
  std::string_view name;
  std::string_view alias;
};

constexpr std::array<NameRow<ProblemId>, 11> kProblems{{
    {ProblemId::P_p, "P_p", ""},
    {ProblemId::P_a, "P_a", ""},
    {ProblemId::Pprime_p, "Pprime_p", "P'_p"},
    {ProblemId::Pprime_a, "Pprime_a", "P'_a"},
    {ProblemId::H_p, "H_p", ""},
    {ProblemId::H_a, "H_a", ""},
    {ProblemId::S_1, "S_1", ""},
    {ProblemId::S_1_3, "S_1_3", ""},
    {ProblemId::S_1_7, "S_1_7", ""},
    {ProblemId::F_p, "F_p", ""},
    {ProblemId::F_a, "F_a", ""},
}};
constexpr std::array<NameRow<MeshLevel>, 3> kMeshes{
    {{MeshLevel::C, "C", ""}, {MeshLevel::M, "M", ""}, {MeshLevel::F, "F", ""}}};
constexpr std::array<NameRow<ElementType>, 2> kElements{
    {{ElementType::Q4, "Q4", "4Q"}, {ElementType::Q8, "Q8", "8Q"}}};
constexpr std::array<NameRow<Algorithm>, 5> kAlgorithms{{
    {Algorithm::AL, "AL", ""},
    {Algorithm::PM, "PM", ""},
    {Algorithm::LMP, "LMP", ""},
    {Algorithm::PLM, "PLM", ""},
    {Algorithm::MPC, "MPC", "IMC"},
}};
constexpr std::array<NameRow<ContactKind>, 3> kContacts{{{ContactKind::ns, "ns", ""},
                                                         {ContactKind::ss, "ss", ""},
                                                         {ContactKind::mortar, "mortar", ""}}};
constexpr std::array<NameRow<TargetKind>, 2> kTargets{
    {{TargetKind::Discretized, "discretized", ""}, {TargetKind::Rigid, "rigid", ""}}};
constexpr std::array<NameRow<Recovery>, 2> kRecoveries{
    {{Recovery::spr, "spr", ""}, {Recovery::extrapolated, "extrapolated", ""}}};

template <class E, std::size_t N>
std::string_view name_of(const std::array<NameRow<E>, N>& table, E value) {
  for (const auto& row : table) {
    if (row.value == value)
      return row.name;
  }
  return "?";
}

template <class E, std::size_t N>
E parse_name(const std::array<NameRow<E>, N>& table, std::string_view text, std::string_view what) {
  for (const auto& row : table) {
    if (text == row.name || (!row.alias.empty() && text == row.alias))
      return row.value;
  }
  std::string accepted;
  for (const auto& row : table) {
    accepted += (accepted.empty() ? "" : ", ") + std::string(row.name);
  }
  throw SuiteInputError(fmt::format("unknown {} '{}' (expected one of: {})", what, text, accepted));
}

template <class E, std::size_t N>
std::vector<E> values_of(const std::array<NameRow<E>, N>& table) {
  std::vector<E> out;
  for (const auto& row : table)
    out.push_back(row.value);
  return out;
}

double parse_number(const std::string& name, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    throw SuiteInputError(fmt::format("--set {}: '{}' is not a finite number", name, text));
  }
  return value;
}

}  // namespace

std::string_view to_string(ProblemId v) {
  return name_of(kProblems, v);
}
std::string_view to_string(MeshLevel v) {
  return name_of(kMeshes, v);
}
std::string_view to_string(ElementType v) {
  return name_of(kElements, v);
}
std::string_view to_string(Algorithm v) {
  return name_of(kAlgorithms, v);
}
std::string_view to_string(ContactKind v) {
  return name_of(kContacts, v);
}
std::string_view to_string(TargetKind v) {
  return name_of(kTargets, v);
}
std::string_view to_string(Recovery v) {
  return name_of(kRecoveries, v);
}

ProblemId parse_problem(std::string_view s) {
  return parse_name(kProblems, s, "problem");
}
MeshLevel parse_mesh_level(std::string_view s) {
  return parse_name(kMeshes, s, "mesh level");
}
ElementType parse_element(std::string_view s) {
  return parse_name(kElements, s, "element");
}
Algorithm parse_algorithm(std::string_view s) {
  return parse_name(kAlgorithms, s, "algorithm");
}
ContactKind parse_contact(std::string_view s) {
  return parse_name(kContacts, s, "contact");
}
TargetKind parse_target(std::string_view s) {
  return parse_name(kTargets, s, "target");
}
Recovery parse_recovery(std::string_view s) {
  return parse_name(kRecoveries, s, "stress recovery");
}

const std::vector<ProblemId>& all_problems() {
  static const auto v = values_of(kProblems);
  return v;
}
const std::vector<MeshLevel>& all_mesh_levels() {
  static const auto v = values_of(kMeshes);
  return v;
}
const std::vector<ElementType>& all_elements() {
  static const auto v = values_of(kElements);
  return v;
}
const std::vector<Algorithm>& all_algorithms() {
  static const auto v = values_of(kAlgorithms);
  return v;
}
const std::vector<ContactKind>& study_contacts() {
  static const std::vector<ContactKind> v{ContactKind::ss, ContactKind::ns};
  return v;
}
const std::vector<Recovery>& all_recoveries() {
  static const auto v = values_of(kRecoveries);
  return v;
}
const std::vector<ContactKind>& all_contacts() {
  static const std::vector<ContactKind> v{ContactKind::ss, ContactKind::ns, ContactKind::mortar};
  return v;
}

bool is_axisymmetric(ProblemId p) {
  return p == ProblemId::P_a || p == ProblemId::Pprime_a || p == ProblemId::H_a ||
         p == ProblemId::F_a;
}

bool is_singular(ProblemId p) {
  return p == ProblemId::F_p || p == ProblemId::F_a;
}

std::string case_id(const CaseSpec& spec) {
  std::string id =
      fmt::format("{}/{}/{}/{}/{}", to_string(spec.problem), to_string(spec.mesh),
                  to_string(spec.element), to_string(spec.algorithm), to_string(spec.contact));
  if (spec.target == TargetKind::Rigid)
    id += "/rigid";
  if (spec.recovery != Recovery::spr)
    id += fmt::format("/{}", to_string(spec.recovery));
  for (const auto& [name, value] : spec.overrides)
    id += fmt::format("/{}={}", name, value);
  return id;
}

std::pair<std::string, double> parse_override(std::string_view text) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0 || eq + 1 == text.size()) {
    throw SuiteInputError(fmt::format("malformed --set '{}' (expected name=value)", text));
  }
  const std::string name(text.substr(0, eq));
  const std::string value_text(text.substr(eq + 1));
  // A value is a number or a ratio of two numbers (re_over_b=1/3).
  const auto slash = value_text.find('/');
  const double value = slash == std::string::npos
                           ? parse_number(name, value_text)
                           : parse_number(name, value_text.substr(0, slash)) /
                                 parse_number(name, value_text.substr(slash + 1));
  if (!std::isfinite(value)) {
    throw SuiteInputError(fmt::format("--set {}: '{}' is not a finite number", name, value_text));
  }
  return {name, value};
}

}  // namespace cs::suites
