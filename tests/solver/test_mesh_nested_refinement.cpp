// Unit tests of the nested 3:1 refinement with transition elements.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/mesh/mesh_quality.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/nested_refinement.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_mesh_nested_refinement {
namespace {

using cs::testing::Near;

constexpr cs::testing::Tolerance kRoundOff{1e-12, 1e-14};  // sums of element areas

NestedRefinementSpec spec_toward(double x_min, double x_max, int levels) {
  NestedRefinementSpec s;
  s.origin = {0.0, 0.0};
  s.cell_size = 0.5;
  s.nx = 16;
  s.nz = 12;
  s.refine_x_min = x_min;
  s.refine_x_max = x_max;
  s.levels = levels;
  return s;
}

/// Conformity and coverage: positive Jacobians, areas summing to the rectangle's, and a boundary
/// as long as the rectangle's perimeter (a hanging node would add inner boundary length).
void expect_conforming_cover(const Mesh& mesh, double width, double depth) {
  EXPECT_NO_THROW(check_mesh(mesh));
  double area = 0.0;
  for (int e = 0; e < mesh.n_elements(); ++e)
    area += element_area(mesh, e);
  EXPECT_TRUE(Near(area, width * depth, kRoundOff));
  const MeshTopology topology = mesh_topology(mesh);
  EXPECT_TRUE(Near(topology.boundary_length, 2 * (width + depth), kRoundOff));
}

TEST(NestedRefinement, WithoutLevelsIsTheBackgroundGrid) {
  const Mesh mesh = make_nested_refinement(spec_toward(3.0, 3.0, 0));
  EXPECT_EQ(mesh.n_elements(), 16 * 12);
  EXPECT_EQ(mesh.n_nodes(), 17 * 13);
  expect_conforming_cover(mesh, 8.0, 6.0);
}

TEST(NestedRefinement, PlannedCountMatchesTheBuiltMeshAndItConforms) {
  for (int levels = 1; levels <= 4; ++levels) {
    const auto spec = spec_toward(3.0, 3.2, levels);
    const NestedRefinementLayout plan = plan_nested_refinement(spec);
    const Mesh mesh = make_nested_refinement(spec);
    EXPECT_EQ(mesh.n_elements(), plan.n_elements) << levels;
    EXPECT_GT(plan.n_transition_cells, 0);
    EXPECT_TRUE(Near(plan.finest_size, 0.5 / std::pow(3.0, levels), kRoundOff));
    expect_conforming_cover(mesh, 8.0, 6.0);
  }
}

TEST(NestedRefinement, SmallestElementsCoverTheRefinedSegment) {
  const auto spec = spec_toward(3.0, 3.2, 3);
  const Mesh mesh = make_nested_refinement(spec);
  const double h_min = 0.5 / 27.0;
  double smallest = INFINITY;
  for (int e = 0; e < mesh.n_elements(); ++e)
    smallest = std::min(smallest, element_size(mesh, e));
  EXPECT_TRUE(Near(smallest, h_min, {1e-9, 0.0}));
  // Every surface side over the segment has the finest size; far from it, the background size.
  for (const auto& s : edge_set(mesh, "bottom")) {
    const auto n = mesh.side_nodes(s);
    const double x0 = mesh.nodes[n[0]].x(), x1 = mesh.nodes[n[1]].x();
    const double mid = 0.5 * (x0 + x1);
    if (mid > 3.0 && mid < 3.2) {
      EXPECT_TRUE(Near(std::abs(x1 - x0), h_min, {1e-9, 0.0})) << mid;
    }
    if (mid < 1.0 || mid > 5.5) {
      EXPECT_TRUE(Near(std::abs(x1 - x0), 0.5, {1e-9, 0.0})) << mid;
    }
  }
  // Elements of the finest size lie within the boxes' reach of the segment, near the surface.
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (element_size(mesh, e) > 1.01 * h_min)
      continue;
    const Eigen::Vector2d c =
        0.25 * (mesh.nodes[mesh.elements[e][0]] + mesh.nodes[mesh.elements[e][2]] +
                mesh.nodes[mesh.elements[e][1]] + mesh.nodes[mesh.elements[e][3]]);
    EXPECT_GT(c.x(), 3.0 - 4 * 3 * h_min);
    EXPECT_LT(c.x(), 3.2 + 4 * 3 * h_min);
    EXPECT_LT(c.y(), 4 * 3 * h_min);
  }
}

TEST(NestedRefinement, SnapPutsNodeLinesOnTheTargets) {
  auto spec = spec_toward(3.0, 3.2, 3);
  spec.snap_x = {3.0123, 3.1987};
  const Mesh mesh = make_nested_refinement(spec);
  const auto& surface = node_set(mesh, "bottom");
  for (double target : spec.snap_x) {
    const bool found = std::any_of(surface.begin(), surface.end(),
                                   [&](int n) { return mesh.nodes[n].x() == target; });
    EXPECT_TRUE(found) << target;
  }
  expect_conforming_cover(mesh, 8.0, 6.0);
}

TEST(NestedRefinement, SetsLieOnTheRectangleEdges) {
  const Mesh mesh = make_nested_refinement(spec_toward(0.0, 0.4, 2));  // boxes reach x = 0
  expect_conforming_cover(mesh, 8.0, 6.0);
  for (int n : node_set(mesh, "left"))
    EXPECT_EQ(mesh.nodes[n].x(), 0.0);
  for (int n : node_set(mesh, "right"))
    EXPECT_EQ(mesh.nodes[n].x(), 8.0);
  for (int n : node_set(mesh, "bottom"))
    EXPECT_EQ(mesh.nodes[n].y(), 0.0);
  for (int n : node_set(mesh, "top"))
    EXPECT_EQ(mesh.nodes[n].y(), 6.0);
  double length = 0.0;
  for (const auto& s : edge_set(mesh, "bottom")) {
    const auto n = mesh.side_nodes(s);
    length += (mesh.nodes[n[1]] - mesh.nodes[n[0]]).norm();
  }
  EXPECT_TRUE(Near(length, 8.0, kRoundOff));
}

TEST(NestedRefinement, SurfaceStripRefinesTheWholeSurfaceOnce) {
  auto spec = spec_toward(3.0, 3.2, 2);
  spec.surface_strip_cells = 2;
  const Mesh mesh = make_nested_refinement(spec);
  expect_conforming_cover(mesh, 8.0, 6.0);
  for (const auto& s : edge_set(mesh, "bottom")) {
    const auto n = mesh.side_nodes(s);
    EXPECT_LE(std::abs(mesh.nodes[n[1]].x() - mesh.nodes[n[0]].x()), 0.5 / 3 * (1 + 1e-12));
  }
}

TEST(NestedRefinement, BadInputIsRejectedWithACause) {
  auto spec = spec_toward(3.0, 3.2, 2);
  spec.cell_size = -1.0;
  EXPECT_THROW(plan_nested_refinement(spec), MeshError);
  spec = spec_toward(9.0, 9.5, 2);  // outside the rectangle
  EXPECT_THROW(plan_nested_refinement(spec), MeshError);
  spec = spec_toward(3.0, 3.2, 2);
  spec.box_depth = 0.0;
  EXPECT_THROW(plan_nested_refinement(spec), MeshError);
  spec = spec_toward(3.0, 3.2, 6);
  spec.box_padding = 0.0;
  spec.box_depth = 1.0;  // a box one cell deep leaves no room for the next level
  try {
    plan_nested_refinement(spec);
    ADD_FAILURE() << "expected MeshError";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("vanishes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cs::solver::test_mesh_nested_refinement
