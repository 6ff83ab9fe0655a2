#include "apps/list_command.hpp"

#include <string>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "suites/case_spec.hpp"
#include "suites/problem_catalog.hpp"

namespace cs::apps {
namespace {

template <class E>
std::string joined(const std::vector<E>& values) {
  std::string out;
  for (const auto& v : values)
    out += (out.empty() ? "" : " ") + std::string(suites::to_string(v));
  return out;
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

void print_text() {
  using namespace cs::suites;
  fmt::print("Problems (the study's battery), with the parameters particular to each:\n");
  for (auto id : all_problems()) {
    const auto& info = problem_info(id);
    std::string quantities;
    for (const auto& q : info.quantities)
      quantities += (quantities.empty() ? "" : ", ") + q;
    fmt::print("  {:<9} {} — graded: {} (study Tables {})\n", to_string(id), info.title, quantities,
               info.study_tables);
    for (const auto& p : info.parameters) {
      if (!is_common(p.name))
        print_parameter(p);
    }
  }
  fmt::print("\nParameters of every problem (--set name=value):\n");
  for (const auto& p : problem_info(ProblemId::S_1).parameters) {
    if (is_common(p.name))
      print_parameter(p);
  }
  fmt::print("\nOptions:\n");
  fmt::print("  --mesh       {}   (coarse h, medium h/2, fine h/4)\n", joined(all_mesh_levels()));
  fmt::print("  --element    {}   (4-node bilinear, 8-node serendipity; 4Q/8Q accepted)\n",
             joined(all_elements()));
  fmt::print(
      "  --algorithm  {}   (IMC accepted for MPC; LMP and PLM are the same method "
      "without friction)\n",
      joined(all_algorithms()));
  fmt::print("  --contact    {}   (the study's ss and ns, and mortar)\n", joined(all_contacts()));
  fmt::print(
      "  --target     discretized rigid   (stiff meshed indenter, E ratio 1e6; or a rigid "
      "analytic profile)\n");
  fmt::print(
      "  --recovery   {}   (nodal stresses: superconvergent patch recovery; or "
      "extrapolated and averaged, as commercial codes print)\n",
      joined(all_recoveries()));
}

void print_json() {
  using namespace cs::suites;
  nlohmann::json problems = nlohmann::json::array();
  for (auto id : all_problems()) {
    const auto& info = problem_info(id);
    nlohmann::json params = nlohmann::json::object();
    for (const auto& p : info.parameters) {
      params[p.name] = {
          {"default", p.default_value}, {"range", range_text(p)}, {"description", p.description}};
    }
    problems.push_back({{"name", std::string(to_string(id))},
                        {"title", info.title},
                        {"axisymmetric", info.axisymmetric},
                        {"quantities", info.quantities},
                        {"study_tables", info.study_tables},
                        {"parameters", params}});
  }
  auto names = [](const auto& values) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& v : values)
      a.push_back(std::string(to_string(v)));
    return a;
  };
  const nlohmann::json out{{"problems", problems},
                           {"meshes", names(all_mesh_levels())},
                           {"elements", names(all_elements())},
                           {"algorithms", names(all_algorithms())},
                           {"contacts", names(all_contacts())},
                           {"targets", {"discretized", "rigid"}},
                           {"recoveries", names(all_recoveries())}};
  fmt::print("{}\n", out.dump(2));
}

}  // namespace

void add_list_command(CLI::App& app) {
  auto* list = app.add_subcommand("list", "List the problems, their parameters and the options");
  auto json = std::make_shared<bool>(false);
  list->add_flag("--json", *json, "Print as one JSON object");
  list->callback([json] { *json ? print_json() : print_text(); });
}

}  // namespace cs::apps
