#include "apps/list_command.hpp"

#include <string>
#include <string_view>
#include <vector>

#include <fmt/core.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "adapters/protocol/solver_registry.hpp"
#include "adapters/registered_codes.hpp"
#include "suites/case_spec.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/problems/problem_builders.hpp"

namespace cs::apps {
namespace {

/// "AL PM LMP PLM MPC": every name of an axis.
template <class E>
std::string joined() {
  std::string out;
  for (const auto& v : schema::values<E>())
    out += (out.empty() ? "" : " ") + std::string(schema::to_string(v));
  return out;
}

/// The names of an axis as a JSON array.
template <class E>
nlohmann::json names() {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& v : schema::values<E>())
    a.push_back(std::string(schema::to_string(v)));
  return a;
}

nlohmann::json quantity_names(const schema::ProblemRecord& record) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& q : record.quantities)
    a.push_back(std::string(schema::to_string(q.quantity)));
  return a;
}

void print_parameter(const suites::ParameterSpec& p) {
  fmt::print("      --set {:<22} range {:<16} {}\n",
             fmt::format("{}={:g}", p.name, p.default_value), suites::range_text(p), p.description);
}

bool is_common(const std::string& name) {
  for (const auto& p : suites::common_parameters(0.0)) {
    if (p.name == name)
      return true;
  }
  return false;
}

/// The registered codes (docs/solver-protocol.md; CalculiX's manifest is its adapter's), with
/// their options.
void print_external_solvers(const std::vector<std::filesystem::path>& dirs) {
  fmt::print("\nRegistered codes (--solver NAME; case ids end in /@NAME:OPTION):\n");
  for (const auto& code :
       adapters::registered_codes(adapters::protocol::solver_directories(dirs))) {
    std::vector<std::string_view> supports;
    for (auto s : code.supports)
      supports.push_back(adapters::protocol::to_string(s));
    fmt::print("  {:<10} {} [{}] ({})\n", code.name, code.description, fmt::join(supports, " "),
               code.folder.string());
    for (const auto& o : code.options)
      fmt::print("    {:<22} {:<20} {:<6} {}\n", code.name + ":" + o.label,
                 adapters::protocol::to_string(o.family), o.discretization, o.description);
  }
}

nlohmann::json external_solvers_json(const std::vector<std::filesystem::path>& dirs) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& code :
       adapters::registered_codes(adapters::protocol::solver_directories(dirs))) {
    nlohmann::json options = nlohmann::json::array();
    for (const auto& o : code.options)
      options.push_back({{"label", o.label},
                         {"family", adapters::protocol::to_string(o.family)},
                         {"discretization", o.discretization},
                         {"description", o.description}});
    nlohmann::json supports = nlohmann::json::array();
    for (auto s : code.supports)
      supports.push_back(adapters::protocol::to_string(s));
    out.push_back({{"name", code.name},
                   {"description", code.description},
                   {"folder", code.folder.string()},
                   {"supports", supports},
                   {"options", options}});
  }
  return out;
}

void print_text(const std::vector<std::filesystem::path>& dirs) {
  using namespace cs::suites;
  fmt::print("Problems (the study's battery), with the parameters particular to each:\n");
  for (auto id : schema::values<ProblemId>()) {
    const auto& info = problem_descriptor(id);
    std::string quantities;
    for (const auto& q : info.record.quantities)
      quantities += (quantities.empty() ? "" : ", ") + std::string(to_string(q.quantity));
    const std::string tables = info.record.study_tables.empty()
                                   ? std::string("beyond the study")
                                   : "study Tables " + info.record.study_tables;
    fmt::print("  {:<9} {} — graded: {} ({})\n", to_string(id), info.record.title, quantities,
               tables);
    for (const auto& p : info.parameters) {
      if (!is_common(p.name))
        print_parameter(p);
    }
  }
  fmt::print("\nParameters of every problem (--set name=value):\n");
  for (const auto& p : common_parameters(problems::kStudyPOverE)) {
    if (is_common(p.name))
      print_parameter(p);
  }
  fmt::print("\nOptions:\n");
  fmt::print(
      "  --mesh       {}   (coarse h, medium h/2, fine h/4; very fine h/8, only when asked)\n",
      joined<schema::MeshLevel>());
  fmt::print("  --element    {}   (4-node bilinear, 8-node serendipity; 4Q/8Q accepted)\n",
             joined<schema::Element>());
  fmt::print(
      "  --algorithm  {}   (IMC accepted for MPC; LMP and PLM are the same method "
      "without friction)\n",
      joined<schema::Algorithm>());
  fmt::print("  --contact    {}   (the study's ss and ns, and mortar)\n",
             joined<schema::ContactKind>());
  fmt::print(
      "  --target     discretized rigid   (stiff meshed indenter, E ratio 1e6; or a rigid "
      "analytic profile)\n");
  fmt::print(
      "  --recovery   {}   (nodal stresses: superconvergent patch recovery; or "
      "extrapolated and averaged, as commercial codes print)\n",
      joined<schema::Recovery>());
  fmt::print("  --solver     builtin   (ours), or a registered code below\n");
  print_external_solvers(dirs);
}

void print_json(const std::vector<std::filesystem::path>& dirs) {
  using namespace cs::suites;
  nlohmann::json problems = nlohmann::json::array();
  for (auto id : schema::values<ProblemId>()) {
    const auto& info = problem_descriptor(id);
    nlohmann::json params = nlohmann::json::object();
    for (const auto& p : info.parameters) {
      params[p.name] = {
          {"default", p.default_value}, {"range", range_text(p)}, {"description", p.description}};
    }
    problems.push_back({{"name", std::string(to_string(id))},
                        {"title", info.record.title},
                        {"axisymmetric", info.record.axisymmetric},
                        {"singular", info.record.singular},
                        {"quantities", quantity_names(info.record)},
                        {"study_tables", info.record.study_tables},
                        {"parameters", params}});
  }
  const nlohmann::json out{{"problems", problems},
                           {"meshes", names<schema::MeshLevel>()},
                           {"elements", names<schema::Element>()},
                           {"algorithms", names<schema::Algorithm>()},
                           {"contacts", names<schema::ContactKind>()},
                           {"targets", names<schema::TargetKind>()},
                           {"recoveries", names<schema::Recovery>()},
                           {"solvers", names<schema::SolverKind>()},
                           {"external_solvers", external_solvers_json(dirs)}};
  fmt::print("{}\n", out.dump(2));
}

}  // namespace

void add_list_command(CLI::App& app) {
  auto* list = app.add_subcommand("list", "List the problems, their parameters and the options");
  auto json = std::make_shared<bool>(false);
  auto dirs = std::make_shared<std::vector<std::string>>();
  list->add_flag("--json", *json, "Print as one JSON object");
  list->add_option("--solver-dir", *dirs,
                   "A further folder of external codes (see `run --solver-dir`)")
      ->check(CLI::ExistingDirectory);
  list->callback([json, dirs] {
    std::vector<std::filesystem::path> d;
    for (const auto& dir : *dirs)
      d.push_back(std::filesystem::absolute(dir));
    *json ? print_json(d) : print_text(d);
  });
}

}  // namespace cs::apps
