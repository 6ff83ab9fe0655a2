// Unit tests of the curved quarter meshes (solver/mesh/circular_sector.hpp) and of welding
// (solver/mesh/mesh_weld.hpp): counts against the blocks' layout, nodes on the arcs, areas
// against pi/4 (ro^2 - ri^2) and pi R^2 / 4, matching arc angles, bad input.

#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "solver/mesh/circular_sector.hpp"
#include "solver/mesh/mesh_quality.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/mesh_weld.hpp"
#include "solver/mesh/structured_block.hpp"
#include "support/tolerance.hpp"

namespace cs::solver {
namespace {

using cs::testing::Near;
constexpr double kPi = std::numbers::pi;
constexpr cs::testing::Tolerance kRoundOff{1e-13, 1e-13};  // coordinates from a few flops

double total_area(const Mesh& mesh) {
  double area = 0.0;
  for (int e = 0; e < mesh.n_elements(); ++e)
    area += element_area(mesh, e);
  return area;
}

std::vector<double> angles(const Mesh& mesh, const std::string& set) {
  std::vector<double> out;
  for (int n : node_set(mesh, set))
    out.push_back(std::atan2(mesh.nodes[n].y(), mesh.nodes[n].x()));
  std::sort(out.begin(), out.end());
  return out;
}

TEST(QuarterDisc, WeldsTheThreeBlocksWithoutDuplicates) {
  // Core (n+1)^2 nodes, each curved block adds m (n+1), less the diagonal's m the second time.
  const int n = 4, m = 3;
  const Mesh disc =
      make_quarter_disc({.type = ElementType::Q4, .radius = 2.0, .n_arc = 2 * n, .n_radial = m});
  EXPECT_EQ(disc.n_elements(), n * n + 2 * n * m);
  EXPECT_EQ(disc.n_nodes(), (n + 1) * (n + 1) + m * (n + 1) + m * n);
  EXPECT_NO_THROW(check_mesh(disc));
  const MeshTopology topology = mesh_topology(disc);
  EXPECT_EQ(topology.n_boundary_sides, 2 * n + 2 * (n + m));
}

TEST(QuarterDisc, ArcNodesOnTheCircleAtEqualAngles) {
  for (const auto type : {ElementType::Q4, ElementType::Q8}) {
    const Mesh disc = make_quarter_disc({.type = type, .radius = 1.5, .n_arc = 8, .n_radial = 2});
    const auto theta = angles(disc, "arc");
    const int per_element = type == ElementType::Q4 ? 1 : 2;
    ASSERT_EQ(theta.size(), static_cast<std::size_t>(8 * per_element + 1));
    for (std::size_t k = 0; k < theta.size(); ++k)
      EXPECT_TRUE(Near(theta[k], k * kPi / (2.0 * 8 * per_element), kRoundOff));
    for (int node : node_set(disc, "arc"))
      EXPECT_TRUE(Near(disc.nodes[node].norm(), 1.5, kRoundOff));
    EXPECT_EQ(edge_set(disc, "arc").size(), 8u);
    EXPECT_EQ(edge_set(disc, "x_axis").size(), 4u + 2u);
    EXPECT_EQ(edge_set(disc, "z_axis").size(), 4u + 2u);
  }
}

TEST(QuarterDisc, AreaConvergesToAQuarterCircle) {
  // Q4 replaces each arc element by its chord: the missing area is R^2 (dt - sin dt)/2 per
  // element, n_arc R^2 dt^3 / 12 in all, O(dt^2) relative. Q8 sides are parabolas: O(dt^4).
  const double R = 1.0, exact = kPi * R * R / 4.0;
  for (int n_arc : {8, 16}) {
    const double dt = kPi / (2.0 * n_arc);
    const Mesh q4 =
        make_quarter_disc({.type = ElementType::Q4, .radius = R, .n_arc = n_arc, .n_radial = 2});
    EXPECT_TRUE(Near(total_area(q4), exact - n_arc * (dt - std::sin(dt)) / 2.0, kRoundOff));
    const Mesh q8 =
        make_quarter_disc({.type = ElementType::Q8, .radius = R, .n_arc = n_arc, .n_radial = 2});
    EXPECT_TRUE(Near(total_area(q8), exact, {std::pow(dt, 4), 0.0}));
  }
}

TEST(QuarterAnnulus, SetsAreaAndGeometricRadii) {
  const double ri = 1.0, ro = 3.0;
  const int n_arc = 16, n_radial = square_radial_count(ri, ro, n_arc);
  EXPECT_EQ(n_radial, static_cast<int>(std::ceil(std::log(3.0) / std::log(1 + kPi / 32))));
  const Mesh ring = make_quarter_annulus({.type = ElementType::Q8,
                                          .inner_radius = ri,
                                          .outer_radius = ro,
                                          .n_arc = n_arc,
                                          .n_radial = n_radial});
  EXPECT_NO_THROW(check_mesh(ring));
  EXPECT_EQ(ring.n_elements(), n_arc * n_radial);
  EXPECT_EQ(edge_set(ring, "inner").size(), static_cast<std::size_t>(n_arc));
  EXPECT_EQ(edge_set(ring, "outer").size(), static_cast<std::size_t>(n_arc));
  EXPECT_EQ(edge_set(ring, "x_axis").size(), static_cast<std::size_t>(n_radial));
  EXPECT_EQ(edge_set(ring, "z_axis").size(), static_cast<std::size_t>(n_radial));
  const double dt = kPi / (2.0 * n_arc);
  EXPECT_TRUE(Near(total_area(ring), kPi / 4.0 * (ro * ro - ri * ri), {std::pow(dt, 4), 0.0}));
  // The first radial element is about square: its depth over the bore's arc element.
  const double first = ri * std::pow(ro / ri, 1.0 / n_radial) - ri;
  EXPECT_TRUE(Near(first / (ri * dt), 1.0, {0.25, 0.0}));  // ceil() shortens it a little
}

TEST(QuarterAnnulus, BoreMatchesTheDiscArcNodeForNode) {
  const Mesh ring = make_quarter_annulus({.type = ElementType::Q8,
                                          .inner_radius = 1.0,
                                          .outer_radius = 2.0,
                                          .n_arc = 32,
                                          .n_radial = 8});
  const Mesh disc =
      make_quarter_disc({.type = ElementType::Q8, .radius = 1.001, .n_arc = 32, .n_radial = 8});
  const auto a = angles(ring, "inner"), b = angles(disc, "arc");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
    EXPECT_TRUE(Near(a[k], b[k], kRoundOff));
}

TEST(CircularSector, BadInputIsAMeshError) {
  EXPECT_THROW(make_quarter_annulus({.inner_radius = 2.0, .outer_radius = 1.0}), MeshError);
  EXPECT_THROW(make_quarter_annulus({.n_radial = 0}), MeshError);
  EXPECT_THROW(make_quarter_disc({.n_arc = 7}), MeshError);
  EXPECT_THROW(make_quarter_disc({.radius = -1.0}), MeshError);
  EXPECT_THROW(make_quarter_disc({.core_fraction = 0.75}), MeshError);
  EXPECT_THROW(weld_blocks({}, "x", 1e-9), MeshError);
}

}  // namespace
}  // namespace cs::solver
