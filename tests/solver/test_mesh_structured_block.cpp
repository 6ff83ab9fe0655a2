// Unit tests of the structured block generator: counts, sets, node order, spacing, bad input.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/mesh/mesh_quality.hpp"
#include "solver/mesh/structured_block.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_mesh_structured_block {
namespace {

using cs::testing::Near;

constexpr cs::testing::Tolerance kRoundOff{1e-14, 1e-14};  // coordinates from a few flops

BlockSpec spec_of(ElementType type, int nx, int nz) {
  BlockSpec spec;
  spec.type = type;
  spec.origin = {1.0, -2.0};
  spec.size = {3.0, 2.0};
  spec.nx = nx;
  spec.nz = nz;
  return spec;
}

TEST(StructuredBlock, Q4CountsAndPositiveJacobian) {
  const Mesh mesh = make_block(spec_of(ElementType::Q4, 4, 3));
  EXPECT_EQ(mesh.n_elements(), 12);
  EXPECT_EQ(mesh.n_nodes(), 5 * 4);
  EXPECT_EQ(mesh.body_names, std::vector<std::string>{"body"});
  EXPECT_EQ(mesh.element_body, std::vector<int>(12, 0));
  EXPECT_NO_THROW(check_mesh(mesh));
  // Each element is 0.75 x 2/3: det J = area / 4 everywhere.
  EXPECT_TRUE(Near(min_jacobian_determinant(mesh), 0.75 * (2.0 / 3.0) / 4.0, kRoundOff));
}

TEST(StructuredBlock, Q8CountsMidsidesAndPositiveJacobian) {
  const Mesh mesh = make_block(spec_of(ElementType::Q8, 4, 3));
  EXPECT_EQ(mesh.n_elements(), 12);
  // (2nx+1)(2nz+1) fine-grid points minus the nx*nz element centers.
  EXPECT_EQ(mesh.n_nodes(), 9 * 7 - 12);
  EXPECT_NO_THROW(check_mesh(mesh));
  for (const auto& e : mesh.elements) {
    for (int s = 0; s < 4; ++s) {
      const Eigen::Vector2d mid = 0.5 * (mesh.nodes[e[s]] + mesh.nodes[e[(s + 1) % 4]]);
      EXPECT_TRUE(Near((mesh.nodes[e[4 + s]] - mid).norm(), 0.0, kRoundOff));
    }
  }
}

TEST(StructuredBlock, CounterClockwiseCornerOrder) {
  const Mesh mesh = make_block(spec_of(ElementType::Q4, 2, 2));
  const auto& e = mesh.elements[0];
  EXPECT_EQ(mesh.nodes[e[0]], Eigen::Vector2d(1.0, -2.0));
  EXPECT_EQ(mesh.nodes[e[1]], Eigen::Vector2d(2.5, -2.0));
  EXPECT_EQ(mesh.nodes[e[2]], Eigen::Vector2d(2.5, -1.0));
  EXPECT_EQ(mesh.nodes[e[3]], Eigen::Vector2d(1.0, -1.0));
}

TEST(StructuredBlock, NamedSetsLieOnTheirEdges) {
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    const Mesh mesh = make_block(spec_of(type, 5, 4));
    const int per_side = type == ElementType::Q4 ? 1 : 2;
    EXPECT_EQ(mesh.node_sets.at("bottom").size(), static_cast<std::size_t>(5 * per_side + 1));
    EXPECT_EQ(mesh.node_sets.at("left").size(), static_cast<std::size_t>(4 * per_side + 1));
    EXPECT_EQ(mesh.node_sets.at("all").size(), static_cast<std::size_t>(mesh.n_nodes()));
    for (int n : mesh.node_sets.at("left"))
      EXPECT_EQ(mesh.nodes[n].x(), 1.0);
    for (int n : mesh.node_sets.at("right"))
      EXPECT_EQ(mesh.nodes[n].x(), 4.0);
    for (int n : mesh.node_sets.at("bottom"))
      EXPECT_EQ(mesh.nodes[n].y(), -2.0);
    for (int n : mesh.node_sets.at("top"))
      EXPECT_EQ(mesh.nodes[n].y(), 0.0);
    const auto& bottom = mesh.node_sets.at("bottom");
    EXPECT_TRUE(std::is_sorted(bottom.begin(), bottom.end(), [&](int a, int b) {
      return mesh.nodes[a].x() < mesh.nodes[b].x();
    }));
    const std::map<std::string, std::pair<int, double>> expect = {
        {"bottom", {0, -2.0}}, {"right", {1, 4.0}}, {"top", {2, 0.0}}, {"left", {3, 1.0}}};
    for (const auto& [name, side_and_value] : expect) {
      const auto& edges = mesh.edge_sets.at(name);
      EXPECT_EQ(edges.size(), static_cast<std::size_t>(name == "left" || name == "right" ? 4 : 5));
      for (const ElementSide& s : edges) {
        EXPECT_EQ(s.side, side_and_value.first) << name;
        for (int n : mesh.side_nodes(s)) {
          if (n < 0)
            continue;
          const bool vertical = name == "left" || name == "right";
          EXPECT_EQ(vertical ? mesh.nodes[n].x() : mesh.nodes[n].y(), side_and_value.second)
              << name;
        }
      }
    }
  }
}

TEST(StructuredBlock, GeometricSpacingGrowsByRatio) {
  BlockSpec spec = spec_of(ElementType::Q4, 4, 1);
  spec.x_spacing = {SpacingKind::Geometric, 2.0, {}};
  const Mesh mesh = make_block(spec);
  const auto& bottom = mesh.node_sets.at("bottom");
  // sizes h, 2h, 4h, 8h with 15h = 3
  const double h = 3.0 / 15.0;
  double expected = 1.0;
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(Near(mesh.nodes[bottom[i]].x(), expected, kRoundOff)) << i;
    expected += h * std::pow(2.0, i);
  }
}

TEST(StructuredBlock, BreakpointSpacingIsUsedAsGiven) {
  BlockSpec spec = spec_of(ElementType::Q8, 3, 1);
  spec.x_spacing = {SpacingKind::Breakpoints, 1.0, {0.0, 0.1, 0.5, 1.0}};
  const Mesh mesh = make_block(spec);
  const auto& bottom = mesh.node_sets.at("bottom");
  ASSERT_EQ(bottom.size(), 7u);
  const double expected[] = {1.0, 1.15, 1.3, 1.9, 2.5, 3.25, 4.0};
  for (int i = 0; i < 7; ++i) {
    EXPECT_TRUE(Near(mesh.nodes[bottom[i]].x(), expected[i], kRoundOff)) << i;
  }
}

TEST(StructuredBlock, BadInputThrowsMeshErrorNamingTheCause) {
  auto message_of = [](const BlockSpec& spec) -> std::string {
    try {
      make_block(spec);
    } catch (const MeshError& e) {
      return e.what();
    }
    return "no error";
  };
  BlockSpec s = spec_of(ElementType::Q4, 0, 1);
  EXPECT_NE(message_of(s).find("nx = 0"), std::string::npos) << message_of(s);
  s = spec_of(ElementType::Q4, 1, 1);
  s.size = {1.0, 0.0};
  EXPECT_NE(message_of(s).find("size"), std::string::npos) << message_of(s);
  s = spec_of(ElementType::Q4, 2, 1);
  s.x_spacing = {SpacingKind::Geometric, -1.0, {}};
  EXPECT_NE(message_of(s).find("ratio"), std::string::npos) << message_of(s);
  s.x_spacing = {SpacingKind::Breakpoints, 1.0, {0.0, 1.0}};
  EXPECT_NE(message_of(s).find("breakpoints"), std::string::npos) << message_of(s);
  s.x_spacing = {SpacingKind::Breakpoints, 1.0, {0.0, 0.7, 0.6, 1.0}};
  s.nx = 3;
  EXPECT_NE(message_of(s).find("increasing"), std::string::npos) << message_of(s);
  EXPECT_THROW(make_block(s), std::invalid_argument);  // MeshError is an invalid_argument
}

TEST(MappedBlock, RejectsAnInvertingMap) {
  MappedBlockSpec spec;
  spec.u = uniform_coordinates(2);
  spec.v = uniform_coordinates(2);
  spec.map = [](double u, double v) { return Eigen::Vector2d(u, -v); };  // mirror
  EXPECT_THROW(make_mapped_block(spec), MeshError);
}

}  // namespace
}  // namespace cs::solver::test_mesh_structured_block
