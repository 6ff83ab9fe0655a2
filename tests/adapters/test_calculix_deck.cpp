// Requirement: the CalculiX deck carries the model exactly: nodes and elements numbered our
// index + 1 in CalculiX's node order, one material and section per body, element-face surfaces
// S<side + 1>, every prescribed DOF evaluated at its node, the solver's consistent nodal forces
// (x 2 pi in axisymmetry), numbers that fit ccx's 20-character fields, and no model text
// outside comments. Unsupported requests are typed errors.

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "adapters/calculix/calculix_error.hpp"
#include "adapters/calculix/input_deck.hpp"
#include "calculix_test_support.hpp"
#include "solver/contact/rigid_profile.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "support/tolerance.hpp"

namespace cs::adapters::calculix {
namespace {

using cs::testing::Near;
using solver::AnalysisType;
using solver::ElementType;

/// The data lines of the deck's keyword block `keyword` (e.g. "*CLOAD"), split at commas.
std::vector<std::vector<std::string>> block(const std::string& deck, const std::string& keyword) {
  std::istringstream in(deck);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("**", 0) == 0)
      continue;
    if (!line.empty() && line[0] == '*') {
      inside = line == keyword || line.substr(0, line.find(',')) == keyword ||
               line.rfind(keyword + ",", 0) == 0;
      continue;
    }
    if (!inside)
      continue;
    std::vector<std::string> fields;
    std::istringstream items(line);
    std::string item;
    while (std::getline(items, item, ','))
      fields.push_back(item.substr(item.find_first_not_of(' ')));
    rows.push_back(fields);
  }
  return rows;
}

std::string patch_deck(const test::PatchSpec& s,
                       CcxContactType type = CcxContactType::NodeToSurface) {
  return input_deck(test::patch_model(s), test::patch_pair(), test::penalty_options(s, type, 10));
}

TEST(CalculixDeck, NodesAndElementsKeepOurOrderAndNumbering) {
  test::PatchSpec s;
  s.type = ElementType::Q8;
  const solver::Model model = test::patch_model(s);
  const std::string deck = patch_deck(s);
  const auto nodes = block(deck, "*NODE");
  ASSERT_EQ(nodes.size(), static_cast<std::size_t>(model.mesh.n_nodes()));
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    EXPECT_EQ(std::stoi(nodes[n][0]), n + 1);
    // 13 significant digits written
    EXPECT_TRUE(Near(std::stod(nodes[n][1]), model.mesh.nodes[n].x(), {1e-12, 1e-15}));
    EXPECT_TRUE(Near(std::stod(nodes[n][2]), model.mesh.nodes[n].y(), {1e-12, 1e-15}));
  }
  const auto elements = block(deck, "*ELEMENT");
  ASSERT_EQ(elements.size(), static_cast<std::size_t>(model.mesh.n_elements()));
  for (const auto& row : elements) {
    const int e = std::stoi(row[0]) - 1;
    ASSERT_EQ(row.size(), 9u);  // id + 8 nodes: CalculiX's CPE8 order is ours
    for (int k = 0; k < 8; ++k)
      EXPECT_EQ(std::stoi(row[k + 1]), model.mesh.elements[e][k] + 1);
  }
  EXPECT_NE(deck.find("*ELEMENT, TYPE=CPE8, ELSET=BODY1"), std::string::npos);
  EXPECT_NE(deck.find("*ELEMENT, TYPE=CPE8, ELSET=BODY2"), std::string::npos);
}

TEST(CalculixDeck, ElementTypesPerAnalysis) {
  solver::Model model;
  model.mesh.type = ElementType::Q4;
  EXPECT_EQ(ccx_element_type(model), "CPE4");
  model.analysis = AnalysisType::Axisymmetric;
  EXPECT_EQ(ccx_element_type(model), "CAX4");
  model.mesh.type = ElementType::Q8;
  EXPECT_EQ(ccx_element_type(model), "CAX8");
  model.analysis = AnalysisType::PlaneStrain;
  EXPECT_EQ(ccx_element_type(model), "CPE8");
}

TEST(CalculixDeck, SurfacesAreElementFacesOfOurSides) {
  // make_block: bottom = side 0 -> S1, top = side 2 -> S3 (CalculiX faces run from node k to
  // node k + 1 like our sides).
  EXPECT_EQ(ccx_face_label(0), "S1");
  EXPECT_EQ(ccx_face_label(3), "S4");
  EXPECT_THROW(ccx_face_label(4), CalculixError);
  test::PatchSpec s;
  const solver::Model model = test::patch_model(s);
  const std::string deck = patch_deck(s);
  const auto slave = block(deck, "*SURFACE, NAME=SLAVE");
  const auto& sides = model.mesh.edge_sets.at("block.bottom");
  ASSERT_EQ(slave.size(), sides.size());
  for (std::size_t k = 0; k < sides.size(); ++k) {
    EXPECT_EQ(std::stoi(slave[k][0]), sides[k].element + 1);
    EXPECT_EQ(slave[k][1], "S1");
  }
  const auto master = block(deck, "*SURFACE, NAME=MASTER");
  ASSERT_EQ(master.size(), model.mesh.edge_sets.at("indenter.top").size());
  for (const auto& row : master)
    EXPECT_EQ(row[1], "S3");
}

TEST(CalculixDeck, InteractionFollowsTheOptions) {
  test::PatchSpec s;
  const std::string ns = patch_deck(s, CcxContactType::NodeToSurface);
  EXPECT_NE(ns.find("TYPE=NODE TO SURFACE, SMALL SLIDING\nSLAVE, MASTER"), std::string::npos);
  const auto law = block(ns, "*SURFACE BEHAVIOR");
  ASSERT_EQ(law.size(), 1u);
  ASSERT_EQ(law[0].size(), 3u);                         // K, sigma_inf, c0
  EXPECT_EQ(std::stod(law[0][0]), 10 * 1000.0 / 0.25);  // fkn E / h
  EXPECT_EQ(std::stod(law[0][1]), 0.0025);
  EXPECT_EQ(std::stod(law[0][2]), 0.1);
  const std::string ss = patch_deck(s, CcxContactType::SurfaceToSurface);
  EXPECT_NE(ss.find("TYPE=SURFACE TO SURFACE\n"), std::string::npos);
  EXPECT_EQ(block(ss, "*SURFACE BEHAVIOR")[0].size(), 1u);  // K only
  CalculixOptions hard = test::penalty_options(s, CcxContactType::SurfaceToSurface, 1);
  hard.behavior = CcxPressureOverclosure::Hard;
  const std::string h = input_deck(test::patch_model(s), test::patch_pair(), hard);
  EXPECT_NE(h.find("PRESSURE-OVERCLOSURE=HARD\n*CONTACT PAIR"), std::string::npos);
  hard.contact = CcxContactType::NodeToSurface;  // ccx's defaults but our c0
  const std::string hn = input_deck(test::patch_model(s), test::patch_pair(), hard);
  EXPECT_NE(hn.find("PRESSURE-OVERCLOSURE=HARD\n0, 0, 1.000000000000e-01\n"), std::string::npos);
}

TEST(CalculixDeck, MaterialsPerBody) {
  test::PatchSpec s;
  const std::string deck = patch_deck(s);
  EXPECT_NE(deck.find("*MATERIAL, NAME=MAT1\n*ELASTIC\n1.000000000000e+03, 3.000000000000e-01"),
            std::string::npos);
  EXPECT_NE(deck.find("*MATERIAL, NAME=MAT2\n*ELASTIC\n1.000000000000e+09"), std::string::npos);
  EXPECT_NE(deck.find("*SOLID SECTION, ELSET=BODY2, MATERIAL=MAT2\n1.0\n"), std::string::npos);
}

/// Sum of the *CLOAD values per direction.
std::map<int, double> cload_totals(const std::string& deck) {
  std::map<int, double> total;
  for (const auto& row : block(deck, "*CLOAD"))
    total[std::stoi(row[1])] += std::stod(row[2]);
  return total;
}

TEST(CalculixDeck, LoadsAreConsistentNodalForces) {
  // Plane strain: p a per unit thickness, downwards; none at prescribed DOFs.
  test::PatchSpec s;
  s.p = 2.5;
  auto totals = cload_totals(patch_deck(s));
  EXPECT_TRUE(Near(totals[2], -s.p * s.a, {1e-12, 0}));  // round-off of the edge quadrature
  EXPECT_EQ(totals.count(1), 0u);
  // Axisymmetric: our per-radian p a^2 / 2 times 2 pi = the full-circle force p pi a^2.
  s.analysis = AnalysisType::Axisymmetric;
  totals = cload_totals(patch_deck(s));
  EXPECT_TRUE(Near(totals[2], -s.p * std::numbers::pi * s.a * s.a, {1e-12, 0}));
  // Q8: the mid-side nodes take 2/3 of a side's load, the corners 1/6 each.
  s.analysis = AnalysisType::PlaneStrain;
  s.type = ElementType::Q8;
  s.nx = 1;
  const solver::Model model = test::patch_model(s);
  const auto rows = block(patch_deck(s), "*CLOAD");
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) {
    const int node = std::stoi(row[0]) - 1;
    const bool mid = model.mesh.nodes[node].x() == 0.5 * s.a;
    EXPECT_TRUE(Near(std::stod(row[2]), -s.p * s.a * (mid ? 2.0 / 3.0 : 1.0 / 6.0), {1e-12, 0}));
  }
}

TEST(CalculixDeck, PrescribedValuesAreEvaluatedPerNode) {
  test::PatchSpec s;
  solver::Model model = test::patch_model(s);
  model.prescribed.clear();
  model.fix(solver::NodeSelection::node_set("block.left"), solver::Component::X);
  model.prescribe(solver::NodeSelection::node_set("indenter.bottom"), solver::Component::Z,
                  [](const Eigen::Vector2d& x) { return 1e-3 * (1.0 + x.x()); });
  model.fix(solver::NodeSelection::node_set("indenter.left"), solver::Component::X);
  const CalculixOptions options = test::penalty_options(s, CcxContactType::NodeToSurface, 1);
  const auto rows = block(input_deck(model, test::patch_pair(), options), "*BOUNDARY");
  std::map<std::pair<int, int>, double> written;
  for (const auto& row : rows) {
    EXPECT_EQ(row[1], row[2]);  // one DOF per line
    written[{std::stoi(row[0]) - 1, std::stoi(row[1])}] = std::stod(row[3]);
  }
  const auto& bottom = solver::node_set(model.mesh, "indenter.bottom");
  const auto& left = solver::node_set(model.mesh, "block.left");
  for (int n : bottom)
    EXPECT_TRUE(Near(written.at({n, 2}), 1e-3 * (1.0 + model.mesh.nodes[n].x()), {1e-12, 0}));
  for (int n : left)
    EXPECT_EQ(written.at({n, 1}), 0.0);
  EXPECT_EQ(written.size(),
            bottom.size() + left.size() + solver::node_set(model.mesh, "indenter.left").size());
}

TEST(CalculixDeck, NumbersFitTwentyCharacters) {
  test::PatchSpec s;
  s.E = -1.0 / 3.0 * -3e-300;  // extreme but valid numbers
  s.a = 1.0 / 3.0;
  const std::string deck = patch_deck(s);
  std::istringstream in(deck);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("*", 0) == 0)
      continue;
    std::istringstream items(line);
    std::string item;
    while (std::getline(items, item, ','))
      EXPECT_LE(item.size(), 21u) << line;  // ", " + at most 20 characters
  }
}

TEST(CalculixDeck, AxisNodesMoveOffTheAxisByTheOffset) {
  test::PatchSpec s;
  s.analysis = AnalysisType::Axisymmetric;
  s.nx = 4;  // shortest side touching the axis: the indenter's 0.5 / 1 = 0.5 ... block 0.25
  const solver::Model model = test::patch_model(s);
  const auto nodes = block(patch_deck(s), "*NODE");
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    const double r = std::stod(nodes[n][1]);
    const double expected = model.mesh.nodes[n].x() == 0.0 ? 1e-6 * 0.25 : model.mesh.nodes[n].x();
    EXPECT_TRUE(Near(r, expected, {1e-12, 0}));  // 13 written digits
  }
  CalculixOptions options = test::penalty_options(s, CcxContactType::NodeToSurface, 1);
  options.axis_offset = 0.0;
  const auto on_axis = block(input_deck(model, test::patch_pair(), options), "*NODE");
  EXPECT_EQ(std::stod(on_axis[0][1]), 0.0);
}

TEST(CalculixDeck, AxisNodesWithinRoundOffOfTheAxisMoveToo) {
  // A pole placed by trigonometry: r = R cos(pi / 2) = 6e-17 R, on the axis to round-off. Left
  // there, its faces collapse in CalculiX's expansion as at r = 0 (H_a and IF_a did not converge).
  test::PatchSpec s;
  s.analysis = AnalysisType::Axisymmetric;
  s.nx = 4;
  solver::Model model = test::patch_model(s);
  std::vector<int> axis;
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    if (model.mesh.nodes[n].x() == 0.0) {
      model.mesh.nodes[n].x() = std::cos(std::numbers::pi / 2) * (1.0 + n);
      axis.push_back(n);
    }
  }
  ASSERT_FALSE(axis.empty());
  const auto options = test::penalty_options(s, CcxContactType::NodeToSurface, 10);
  const auto nodes = block(input_deck(model, test::patch_pair(), options), "*NODE");
  for (int n : axis)
    EXPECT_TRUE(Near(std::stod(nodes[n][1]), 1e-6 * 0.25, {1e-12, 0})) << "node " << n;
}

TEST(CalculixDeck, ModelTextStaysInComments) {
  test::PatchSpec s;
  solver::Model model = test::patch_model(s);
  model.mesh.body_names[0] = "block\n*BOUNDARY\n1, 1, 2, 777777";
  const std::string deck = input_deck(model, test::patch_pair(),
                                      test::penalty_options(s, CcxContactType::NodeToSurface, 1));
  std::istringstream in(deck);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("777777") != std::string::npos) {
      EXPECT_EQ(line.rfind("** ", 0), 0u) << line;
    }
  }
  EXPECT_NE(deck.find("** body 0: block__BOUNDARY_1__1__2__777777"), std::string::npos);
}

TEST(CalculixDeck, UnsupportedRequestsAreTypedErrors) {
  test::PatchSpec s;
  const solver::Model model = test::patch_model(s);
  const CalculixOptions options = test::penalty_options(s, CcxContactType::NodeToSurface, 1);
  const solver::ContactPair rigid{"block.bottom", solver::RigidPlane{{0.0, 0.0}, {0.0, 1.0}}};
  EXPECT_THROW(input_deck(model, rigid, options), UnsupportedByCalculix);
  CalculixOptions mortar = options;
  mortar.contact = CcxContactType::Mortar;
  EXPECT_THROW(input_deck(model, test::patch_pair(), mortar), UnsupportedByCalculix);
  const solver::ContactPair unknown{"block.nowhere", solver::TargetSurface{"indenter.top"}};
  try {
    input_deck(model, unknown, options);
    FAIL() << "an unknown contact surface must throw";
  } catch (const CalculixError& e) {
    EXPECT_NE(std::string(e.what()).find("block.nowhere"), std::string::npos) << e.what();
  }
  CalculixOptions no_k = options;
  no_k.penalty_K = 0.0;
  EXPECT_THROW(input_deck(model, test::patch_pair(), no_k), CalculixError);
  CalculixOptions bad_job = options;
  bad_job.job_name = "../job";
  EXPECT_THROW(input_deck(model, test::patch_pair(), bad_job), CalculixError);
}

}  // namespace
}  // namespace cs::adapters::calculix
