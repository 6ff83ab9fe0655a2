// The neutral case directory (suites/case_directory.hpp): an independent reader (meshio) reads
// mesh.msh with every set as a physical group, and case.json states the rigid target's profile
// and the load control.
//
// Requirement: a code that knows nothing of contact-suite finds in mesh.msh every node at its
// coordinates, every element of every body, and every node set and edge set under its own name,
// and in case.json the analytic profile of a rigid target and, for S with a rigid punch, a given
// total load with an unknown depth.

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "suites/case_directory.hpp"
#include "suites/executor_factory.hpp"
#include "support/temp_dir.hpp"

namespace cs::suites {
namespace {

std::string run_command(const std::string& command, int* status) {
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) {
    *status = -1;
    return {};
  }
  std::string out;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
    out += buffer;
  *status = ::pclose(pipe);
  return out;
}

bool meshio_available() {
  int status = 0;
  run_command("/usr/bin/python3 -c 'import meshio'", &status);
  return status == 0;
}

CaseSpec directory_spec(ProblemId problem, Element element, TargetKind target) {
  CaseSpec spec;
  spec.problem = problem;
  spec.element = element;
  spec.target = target;
  return spec;
}

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

/// meshio's view of mesh.msh: "points N", then per cell block "cells <type> <count>", then
/// per physical name "group <name> <dimension> <count of cells>".
std::string meshio_summary(const std::filesystem::path& msh) {
  const std::string program =
      "import meshio, collections\n"
      "m = meshio.read('" +
      msh.string() +
      "')\n"
      "print('points', len(m.points))\n"
      "counts = collections.Counter()\n"
      "for b in m.cells: counts[b.type] += len(b.data)\n"
      "for t in sorted(counts): print('cells', t, counts[t])\n"
      "for name, (tag, dim) in sorted(m.field_data.items()):\n"
      "    n = 0\n"
      "    for b, tags in zip(m.cells, m.cell_data['gmsh:physical']):\n"
      "        n += int((tags == tag).sum()) if b.dim == dim else 0\n"
      "    print('group', name, dim, n)\n"
      "print('x', repr(float(m.points[-1][0])), repr(float(m.points[-1][1])))\n";
  const std::filesystem::path script = msh.parent_path() / "read.py";
  std::ofstream(script) << program;
  int status = 0;
  std::string out = run_command("/usr/bin/python3 " + script.string(), &status);
  if (status != 0)
    ADD_FAILURE() << out;
  return out;
}

class CaseDirectoryTest : public ::testing::TestWithParam<Element> {};

TEST_P(CaseDirectoryTest, MeshioReadsEveryGroup) {
  if (!meshio_available())
    GTEST_SKIP() << "python3-meshio is not installed";
  const CaseSpec spec = directory_spec(ProblemId::H_p, GetParam(), TargetKind::Discretized);
  const ProblemSetup setup = build_problem(spec);
  cs::testing::TempDir dir;
  write_case_directory(dir.path(), spec, setup, "");
  const std::string out = meshio_summary(dir.path() / "mesh.msh");
  const solver::Mesh& mesh = setup.model.mesh;
  const bool q8 = GetParam() == Element::Q8;

  EXPECT_NE(out.find(fmt::format("points {}\n", mesh.n_nodes())), std::string::npos) << out;
  EXPECT_NE(out.find(fmt::format("cells {} {}\n", q8 ? "quad8" : "quad", mesh.n_elements())),
            std::string::npos)
      << out;
  for (int b = 0; b < setup.model.n_bodies(); ++b) {
    int count = 0;
    for (int body : mesh.element_body)
      count += body == b ? 1 : 0;
    EXPECT_NE(out.find(fmt::format("group {} 2 {}\n", mesh.body_names[b], count)),
              std::string::npos)
        << mesh.body_names[b] << "\n"
        << out;
  }
  for (const auto& [name, sides] : mesh.edge_sets)
    EXPECT_NE(out.find(fmt::format("group {} 1 {}\n", name, sides.size())), std::string::npos)
        << name << "\n"
        << out;
  // A node set is its own point group unless it is exactly the nodes of its edge set.
  for (const auto& [name, nodes] : mesh.node_sets) {
    const bool own_group =
        out.find(fmt::format("group {} 0 {}\n", name, nodes.size())) != std::string::npos;
    const bool as_edges = mesh.edge_sets.contains(name);
    EXPECT_TRUE(own_group || as_edges) << name << "\n" << out;
  }
  // Coordinates written with 17 digits read back bit for bit.
  const auto at = out.find("\nx ");
  ASSERT_NE(at, std::string::npos) << out;
  std::istringstream in(out.substr(at + 3));
  double x = 0.0, z = 0.0;
  in >> x >> z;
  EXPECT_EQ(x, mesh.nodes.back().x());
  EXPECT_EQ(z, mesh.nodes.back().y());
}

INSTANTIATE_TEST_SUITE_P(Elements, CaseDirectoryTest, ::testing::Values(Element::Q4, Element::Q8),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(CaseDirectory, RigidTargetCarriesItsProfile) {
  const CaseSpec spec = directory_spec(ProblemId::H_p, Element::Q4, TargetKind::Rigid);
  const ProblemSetup setup = build_problem(spec);
  cs::testing::TempDir dir;
  write_case_directory(dir.path(), spec, setup, "nitsche");
  const auto j = read_json(dir.path() / "case.json");
  EXPECT_EQ(j["format_version"], kCaseFormatVersion);
  EXPECT_EQ(j["option"], "nitsche");
  const auto& target = j["contact_pair"]["target"];
  ASSERT_EQ(target["kind"], "rigid");
  EXPECT_EQ(target["profile"]["type"], "circle");
  const auto& circle =
      std::get<solver::RigidCircle>(std::get<solver::RigidProfile>(setup.pair.target));
  EXPECT_EQ(target["profile"]["radius"].get<double>(), circle.radius);
  EXPECT_EQ(target["profile"]["center"][1].get<double>(), circle.center.y());
  EXPECT_EQ(j["load_control"]["kind"], "given_loads");
  EXPECT_EQ(j["bodies"][1]["role"], "fixed_not_in_contact");
}

TEST(CaseDirectory, SteuermannRigidIsAGivenLoadWithUnknownDepth) {
  const CaseSpec spec = directory_spec(ProblemId::S_1_3, Element::Q4, TargetKind::Rigid);
  const ProblemSetup setup = build_problem(spec);
  cs::testing::TempDir dir;
  write_case_directory(dir.path(), spec, setup, "");
  const auto j = read_json(dir.path() / "case.json");
  const auto& control = j["load_control"];
  ASSERT_EQ(control["kind"], "total_load");
  EXPECT_EQ(control["total_load"].get<double>(), setup.load_control->target_load);
  EXPECT_EQ(control["reaction_set"], setup.load_control->reaction_set);
  EXPECT_EQ(j["contact_pair"]["target"]["profile"]["type"], "rounded_flat_punch");
  int load_controlled = 0;
  for (const auto& bc : j["boundary_conditions"])
    load_controlled += bc.value("load_controlled", false) ? 1 : 0;
  EXPECT_EQ(load_controlled, 1);
}

// Requirement: where a case's run directory cannot be made, every stress basis of the case
// fails with that reason (the run is shared by the bases: the second must not read it as a run
// that wrote no files), and nothing is run.
TEST(CaseDirectory, NoRunDirectoryFailsEveryBasisWithTheReason) {
  cs::testing::TempDir dir;
  std::ofstream(dir.path() / "file") << "not a directory\n";
  ExecutorOptions options;
  options.external_work_root = dir.path() / "file" / "runs";
  CaseSpec spec = directory_spec(ProblemId::P_p, Element::Q4, TargetKind::Rigid);
  spec.algorithm = Algorithm::AL;
  spec.contact = ContactKind::ns;
  spec.solver = SolverKind::external;
  spec.solver_name = "getfem";
  spec.solver_option = "nodal_al";
  const auto executor = make_executor_for(spec, options);
  for (const Recovery basis : {Recovery::spr, Recovery::own}) {
    spec.recovery = basis;
    const CaseResult r = executor->run(spec);
    EXPECT_EQ(r.status, CaseStatus::failed) << case_id(spec);
    EXPECT_NE(r.reason.find("cannot create a run directory"), std::string::npos)
        << case_id(spec) << ": " << r.reason;
  }
}

}  // namespace
}  // namespace cs::suites
