// Unit tests of mesh operations: uniform refinement, Q4 -> Q8, mirroring, set utilities, merge.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/mesh/mesh_merge.hpp"
#include "solver/mesh/mesh_quality.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/mesh_transform.hpp"
#include "solver/mesh/structured_block.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_mesh_transform {
namespace {

using cs::testing::Near;

constexpr cs::testing::Tolerance kRoundOff{1e-12, 1e-14};

Mesh small_block(ElementType type, const std::string& name, double z0) {
  BlockSpec spec;
  spec.type = type;
  spec.origin = {0.0, z0};
  spec.size = {2.0, 1.0};
  spec.nx = 3;
  spec.nz = 2;
  spec.x_spacing = {SpacingKind::Geometric, 1.5, {}};
  spec.body_name = name;
  return make_block(spec);
}

TEST(MeshTransform, RefineUniformlyEqualsTheFinerBlock) {
  BlockSpec spec;
  spec.size = {2.0, 1.0};
  spec.nx = 3;
  spec.nz = 2;
  const Mesh coarse = make_block(spec);
  const Mesh fine = refine_uniformly(coarse, 2);
  spec.nx = 6;
  spec.nz = 4;
  const Mesh direct = make_block(spec);
  EXPECT_EQ(fine.n_elements(), 24);
  EXPECT_EQ(fine.n_nodes(), direct.n_nodes());
  EXPECT_NO_THROW(check_mesh(fine));
  EXPECT_EQ(mesh_topology(fine).n_boundary_sides, 2 * (6 + 4));
  for (const char* name : {"left", "right", "bottom", "top"}) {
    ASSERT_EQ(fine.edge_sets.at(name).size(), direct.edge_sets.at(name).size()) << name;
    const auto a = fine.node_sets.at(name);
    const auto b = direct.node_sets.at(name);
    ASSERT_EQ(a.size(), b.size()) << name;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_TRUE(Near((fine.nodes[a[i]] - direct.nodes[b[i]]).norm(), 0.0, kRoundOff)) << name;
    }
  }
  EXPECT_EQ(fine.node_sets.at("all").size(), static_cast<std::size_t>(fine.n_nodes()));
  EXPECT_THROW(refine_uniformly(to_quadratic(coarse), 2), MeshError);
  EXPECT_THROW(refine_uniformly(coarse, 0), MeshError);
}

TEST(MeshTransform, ToQuadraticSharesMidsideNodes) {
  const Mesh q4 = small_block(ElementType::Q4, "b", 0.0);
  const Mesh q8 = to_quadratic(q4);
  const Mesh direct = small_block(ElementType::Q8, "b", 0.0);
  EXPECT_EQ(q8.type, ElementType::Q8);
  EXPECT_EQ(q8.n_nodes(), direct.n_nodes());  // one node per distinct side
  EXPECT_NO_THROW(check_mesh(q8));
  EXPECT_EQ(q8.node_sets.at("bottom").size(), 7u);
  for (const auto& e : q8.elements) {
    for (int s = 0; s < 4; ++s) {
      const Eigen::Vector2d mid = 0.5 * (q8.nodes[e[s]] + q8.nodes[e[(s + 1) % 4]]);
      EXPECT_TRUE(Near((q8.nodes[e[4 + s]] - mid).norm(), 0.0, kRoundOff));
    }
  }
  EXPECT_THROW(to_quadratic(q8), MeshError);
}

TEST(MeshTransform, MirrorKeepsOrientationAndSets) {
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    Mesh mesh = small_block(type, "b", 0.0);
    mirror_z(mesh);
    EXPECT_NO_THROW(check_mesh(mesh));
    for (const auto& s : mesh.edge_sets.at("top")) {  // the old top, now at z = -1
      for (int n : mesh.side_nodes(s)) {
        if (n >= 0) {
          EXPECT_EQ(mesh.nodes[n].y(), -1.0);
        }
      }
    }
    for (const auto& s : mesh.edge_sets.at("left")) {
      for (int n : mesh.side_nodes(s)) {
        if (n >= 0) {
          EXPECT_EQ(mesh.nodes[n].x(), 0.0);
        }
      }
    }
  }
}

TEST(MeshMerge, TwoBodiesKeepTheirSetsUnderPrefixes) {
  const Mesh block = small_block(ElementType::Q8, "block", 0.0);
  const Mesh indenter = small_block(ElementType::Q8, "indenter", -1.0);
  const Mesh merged = merge_bodies({block, indenter});
  EXPECT_EQ(merged.n_elements(), block.n_elements() + indenter.n_elements());
  EXPECT_EQ(merged.n_nodes(), block.n_nodes() + indenter.n_nodes());
  EXPECT_EQ(merged.body_names, (std::vector<std::string>{"block", "indenter"}));
  EXPECT_EQ(merged.element_body.front(), 0);
  EXPECT_EQ(merged.element_body.back(), 1);
  EXPECT_NO_THROW(check_mesh(merged));
  // The same set, shifted: "indenter.bottom" is the indenter's bottom, body 1.
  const auto& original = indenter.node_sets.at("bottom");
  const auto& shifted = node_set(merged, "indenter.bottom");
  ASSERT_EQ(original.size(), shifted.size());
  for (std::size_t i = 0; i < original.size(); ++i) {
    EXPECT_EQ(merged.nodes[shifted[i]], indenter.nodes[original[i]]);
  }
  for (const auto& s : edge_set(merged, "indenter.top")) {
    EXPECT_EQ(merged.element_body[s.element], 1);
    for (int n : merged.side_nodes(s))
      EXPECT_EQ(merged.nodes[n].y(), 0.0);
  }
  for (const auto& s : edge_set(merged, "block.bottom")) {
    EXPECT_EQ(merged.element_body[s.element], 0);
  }
  EXPECT_EQ(node_set(merged, "block.all").size(), static_cast<std::size_t>(block.n_nodes()));
  // Touching surfaces, but no shared nodes: the bodies stay separate.
  EXPECT_EQ(mesh_topology(merged).n_interior_sides,
            mesh_topology(block).n_interior_sides + mesh_topology(indenter).n_interior_sides);
  // A merged (multi-body) mesh merges again with its names kept.
  const Mesh third = small_block(ElementType::Q8, "third", 1.0);
  const Mesh all = merge_bodies({merged, third});
  EXPECT_EQ(all.body_names.size(), 3u);
  EXPECT_NO_THROW(node_set(all, "indenter.bottom"));
  EXPECT_NO_THROW(node_set(all, "third.top"));
}

TEST(MeshMerge, RejectsMixedTypesAndDuplicateBodies) {
  EXPECT_THROW(merge_bodies({small_block(ElementType::Q4, "a", 0.0),
                             small_block(ElementType::Q8, "b", 0.0)}),
               MeshError);
  EXPECT_THROW(merge_bodies({small_block(ElementType::Q4, "a", 0.0),
                             small_block(ElementType::Q4, "a", 1.0)}),
               MeshError);
}

TEST(MeshSets, LookupErrorsNameTheSetAndTheKnownOnes) {
  const Mesh mesh = small_block(ElementType::Q4, "b", 0.0);
  try {
    node_set(mesh, "contact");
    ADD_FAILURE() << "expected MeshError";
  } catch (const MeshError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'contact'"), std::string::npos) << what;
    EXPECT_NE(what.find("bottom"), std::string::npos) << what;
  }
  EXPECT_THROW(edge_set(mesh, "nope"), MeshError);
  EXPECT_THROW(edge_set_nodes_sorted_along_x(mesh, "nope"), MeshError);
}

TEST(MeshSets, EdgeSetNodesSortedAlongXAndRenamed) {
  Mesh mesh = small_block(ElementType::Q8, "b", 0.0);
  const auto nodes = edge_set_nodes_sorted_along_x(mesh, "top");
  ASSERT_EQ(nodes.size(), 7u);
  EXPECT_TRUE(std::is_sorted(nodes.begin(), nodes.end(),
                             [&](int a, int b) { return mesh.nodes[a].x() < mesh.nodes[b].x(); }));
  rename_set(mesh, "top", "surface");
  EXPECT_EQ(node_set(mesh, "surface"), nodes);
  EXPECT_THROW(node_set(mesh, "top"), MeshError);
  EXPECT_THROW(rename_set(mesh, "surface", "left"), MeshError);
  const auto sides =
      boundary_sides_where(mesh, [](const Eigen::Vector2d& p) { return p.y() == 1.0; });
  EXPECT_EQ(sides.size(), 3u);
  EXPECT_EQ(nodes_of_sides(mesh, sides), nodes);
}

}  // namespace
}  // namespace cs::solver::test_mesh_transform
