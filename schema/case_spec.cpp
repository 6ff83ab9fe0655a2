#include "schema/case_spec.hpp"

#include <charconv>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

std::vector<std::string_view> split_fields(std::string_view id) {
  std::vector<std::string_view> fields;
  while (true) {
    const auto slash = id.find('/');
    fields.push_back(id.substr(0, slash));
    if (slash == std::string_view::npos)
      return fields;
    id.remove_prefix(slash + 1);
  }
}

/// One "name=value" override field; the value a finite double written in full.
std::pair<std::string, double> parse_override_field(std::string_view id, std::string_view field) {
  const auto eq = field.find('=');
  const std::string_view name = field.substr(0, eq), text = field.substr(eq + 1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (name.empty() || text.empty() || ec != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value))
    throw SchemaError(
        fmt::format("case id '{}': '{}' is not a parameter (name=number)", id, field));
  return {std::string(name), value};
}

/// The fields after the five axes: [rigid] [recovery] [name=value ...] [@solver], in this order.
void parse_options(std::string_view id, const std::vector<std::string_view>& fields,
                   CaseSpec& spec) {
  std::size_t i = 5;
  if (i < fields.size() && fields[i] == "rigid")
    spec.target = TargetKind::Rigid, ++i;
  if (i < fields.size()) {
    if (const auto recovery = try_parse<Recovery>(fields[i]))
      spec.recovery = *recovery, ++i;
  }
  while (i < fields.size() && fields[i].find('=') != std::string_view::npos &&
         !fields[i].starts_with('@')) {
    auto [name, value] = parse_override_field(id, fields[i]);
    if (!spec.overrides.emplace(std::move(name), value).second)
      throw SchemaError(fmt::format("case id '{}': parameter '{}' is given twice", id, fields[i]));
    ++i;
  }
  if (i < fields.size() && fields[i].starts_with('@')) {
    const std::string_view solver = fields[i].substr(1);
    if (solver.empty() || solver == to_string(SolverKind::builtin))
      throw SchemaError(
          fmt::format("case id '{}': '{}' is not a solver suffix (the built-in "
                      "solver's cases have none)",
                      id, fields[i]));
    const auto colon = solver.find(':');
    if (colon != std::string_view::npos) {
      spec.solver = SolverKind::external;
      spec.solver_name = std::string(solver.substr(0, colon));
      spec.solver_option = std::string(solver.substr(colon + 1));
      if (spec.solver_name.empty() || spec.solver_option.empty())
        throw SchemaError(fmt::format(
            "case id '{}': '{}' is not a solver suffix (@<code>:<option>)", id, fields[i]));
    } else if (solver == "calculix") {
      throw SchemaError(
          fmt::format("case id '{}': '{}' names CalculiX without its option (@calculix:<option>)",
                      id, fields[i]));
    } else {
      spec.solver = SolverKind::imported;
      spec.solver_name = std::string(solver);
    }
    ++i;
  }
  if (i < fields.size())
    throw SchemaError(fmt::format("case id '{}': unexpected field '{}'", id, fields[i]));
}

std::string options_suffix(const CaseSpec& spec) {
  std::string id;
  if (spec.target == TargetKind::Rigid)
    id += "/rigid";
  if (spec.recovery != Recovery::spr)
    id += fmt::format("/{}", to_string(spec.recovery));
  for (const auto& [name, value] : spec.overrides)
    id += fmt::format("/{}={}", name, value);
  if (spec.solver != SolverKind::builtin)
    id += "/@" + solver_label(spec);
  return id;
}

}  // namespace

std::string solver_label(const CaseSpec& spec) {
  if (spec.solver == SolverKind::imported)
    return spec.solver_name;
  if (spec.solver == SolverKind::external)
    return spec.solver_name + ":" + spec.solver_option;
  return std::string(to_string(spec.solver));
}

bool is_baseline(const CaseSpec& spec) {
  return spec.solver == SolverKind::builtin && spec.target == TargetKind::Discretized &&
         spec.recovery == Recovery::spr && spec.overrides.empty();
}

std::string case_id(const CaseSpec& spec) {
  return fmt::format("{}/{}/{}/{}/{}", to_string(spec.problem), to_string(spec.mesh),
                     to_string(spec.element), to_string(spec.algorithm), to_string(spec.contact)) +
         options_suffix(spec);
}

CaseSpec parse_case_id(std::string_view id) {
  const auto fields = split_fields(id);
  if (fields.size() < 5)
    throw SchemaError(
        fmt::format("case id '{}': expected problem/mesh/element/algorithm/contact[/options]", id));
  CaseSpec spec;
  try {
    spec.problem = parse<ProblemId>(fields[0]);
    spec.mesh = parse<MeshLevel>(fields[1]);
    spec.element = parse<Element>(fields[2]);
    spec.algorithm = parse<Algorithm>(fields[3]);
    spec.contact = parse<ContactKind>(fields[4]);
  } catch (const SchemaError& e) {
    throw SchemaError(fmt::format("case id '{}': {}", id, e.what()));
  }
  parse_options(id, fields, spec);
  if (const std::string canonical = case_id(spec); canonical != id)
    throw SchemaError(
        fmt::format("case id '{}' is not written as case ids are: '{}'", id, canonical));
  return spec;
}

std::string case_key(const CaseSpec& spec) {
  return fmt::format("{}/{}/{}/{}", to_string(spec.problem), to_string(spec.element),
                     to_string(spec.algorithm), to_string(spec.contact)) +
         options_suffix(spec);
}

}  // namespace cs::schema
