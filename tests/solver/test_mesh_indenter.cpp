// Unit tests of the indenter profiles and meshes.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/mesh/indenter.hpp"
#include "solver/mesh/mesh_quality.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_mesh_indenter {
namespace {

using cs::testing::Near;

constexpr cs::testing::Tolerance kRoundOff{1e-13, 1e-15};

TEST(IndenterProfile, CircleAndRoundedPunchFollowTheirFormulas) {
  const auto circle = circle_profile(10.0, 3.0);
  EXPECT_EQ(circle.z_of_x(0.0), 0.0);
  EXPECT_TRUE(Near(circle.z_of_x(3.0), -(10.0 - std::sqrt(91.0)), kRoundOff));
  const auto punch = rounded_punch_profile(1.0, 0.5);
  EXPECT_EQ(punch.half_width, 1.5);
  EXPECT_EQ(punch.z_of_x(0.7), 0.0);
  EXPECT_EQ(punch.z_of_x(1.0), 0.0);
  EXPECT_TRUE(Near(punch.z_of_x(1.3), -(0.5 - std::sqrt(0.25 - 0.09)), kRoundOff));
  EXPECT_TRUE(Near(punch.z_of_x(1.5), -0.5, kRoundOff));
  EXPECT_THROW(circle_profile(1.0, 2.0), MeshError);
  EXPECT_THROW(rounded_punch_profile(1.0, 0.0), MeshError);
}

IndenterSpec punch_spec(ElementType type) {
  IndenterSpec spec;
  spec.type = type;
  spec.profile = rounded_punch_profile(1.0, 0.5);
  // Fine near the contact edge, reaching the vertical tangent at x = 1.5.
  spec.surface_x = {0.0, 0.25, 0.5, 0.75, 0.9, 1.0, 1.02, 1.04, 1.1, 1.2, 1.35, 1.45, 1.5};
  spec.height = 1.0;
  spec.n_rows = 6;
  spec.row_growth = 1.3;
  return spec;
}

TEST(Indenter, SurfaceNodesSitOnTheProfileAtTheGivenX) {
  for (ElementType type : {ElementType::Q4, ElementType::Q8}) {
    const IndenterSpec spec = punch_spec(type);
    const Mesh mesh = make_indenter(spec);
    EXPECT_NO_THROW(check_mesh(mesh)) << (type == ElementType::Q4 ? "Q4" : "Q8");
    EXPECT_EQ(mesh.n_elements(), 12 * 6);
    const auto nodes = edge_set_nodes_sorted_along_x(mesh, "contact");
    EXPECT_EQ(nodes.size(), type == ElementType::Q4 ? 13u : 25u);
    for (int n : nodes) {
      const auto& p = mesh.nodes[n];
      EXPECT_TRUE(Near(p.y(), spec.profile.z_of_x(p.x()), kRoundOff)) << p.transpose();
    }
    // Corner nodes at exactly the requested x.
    for (double x : spec.surface_x) {
      EXPECT_TRUE(std::any_of(nodes.begin(), nodes.end(), [&](int n) {
        return mesh.nodes[n].x() == x;
      })) << x;
    }
    for (int n : node_set(mesh, "back"))
      EXPECT_EQ(mesh.nodes[n].y(), -1.0);
    for (int n : node_set(mesh, "left"))
      EXPECT_EQ(mesh.nodes[n].x(), 0.0);
    for (int n : node_set(mesh, "right"))
      EXPECT_EQ(mesh.nodes[n].x(), 1.5);
  }
}

TEST(Indenter, Q8MidsideNodesKeepTheirXWhereTheSurfaceIsGentle) {
  const IndenterSpec spec = punch_spec(ElementType::Q8);
  const Mesh mesh = make_indenter(spec);
  for (const auto& s : edge_set(mesh, "contact")) {
    const auto n = mesh.side_nodes(s);
    const double x0 = mesh.nodes[n[0]].x(), x1 = mesh.nodes[n[1]].x();
    if (std::max(x0, x1) <= 1.1) {
      EXPECT_TRUE(Near(mesh.nodes[n[2]].x(), 0.5 * (x0 + x1), kRoundOff));
    }
  }
}

TEST(Indenter, RejectsAnIndenterThinnerThanItsProfileDrop) {
  IndenterSpec spec = punch_spec(ElementType::Q4);
  spec.height = 0.4;  // the rounded edge drops 0.5
  EXPECT_THROW(make_indenter(spec), MeshError);
  spec = punch_spec(ElementType::Q4);
  spec.surface_x.back() = 1.4;  // does not reach the half-width
  EXPECT_THROW(make_indenter(spec), MeshError);
}

}  // namespace
}  // namespace cs::solver::test_mesh_indenter
