// Contact geometry: rigid profiles, contact surfaces and their tributary weights, projections
// onto meshed targets, mortar cuts.
//
// Requirement: gaps, normals and closest points of every rigid profile are right (checked
// against closed forms); a Q8 side splits a uniform pressure 1/6, 2/3, 1/6 and the axisymmetric
// weights carry r (per radian); the element depth is the host element's size normal to the side.

#include <cmath>

#include <gtest/gtest.h>

#include "solver/contact/constraint_set.hpp"
#include "solver/contact/contact_error.hpp"
#include "solver/contact/gap_normal.hpp"
#include "solver/contact/mortar.hpp"
#include "support/tolerance.hpp"
#include "test_contact_support.hpp"

namespace cs::solver {
namespace {

using cs::testing::Near;
constexpr double kTight = 1e-13;  // round-off of a few flops

TEST(ContactRigidProfile, PlaneAndCircle) {
  const ProfilePoint p = closest_point(RigidPlane{{0.0, -1.0}, {0.0, 2.0}}, {3.0, 0.5});
  EXPECT_TRUE(Near(p.gap, 1.5, {0, kTight}));
  EXPECT_TRUE(Near(p.normal.y(), 1.0, {0, kTight}));
  EXPECT_TRUE(Near(p.closest.y(), -1.0, {0, kTight}));
  const RigidCircle c{{0.0, -10.0}, 10.0};
  const ProfilePoint q = closest_point(c, {6.0, -2.0});  // |x - c| = 10: on the circle
  EXPECT_TRUE(Near(q.gap, 0.0, {0, kTight}));
  EXPECT_TRUE(Near(q.normal.x(), 0.6, {0, kTight}));
  EXPECT_TRUE(Near(q.normal.y(), 0.8, {0, kTight}));
  EXPECT_TRUE(Near(closest_point(c, {0.0, 0.5}).gap, 0.5, {0, kTight}));
}

TEST(ContactRigidProfile, RoundedPunch) {
  const RoundedFlatPunch punch{{0.0, 0.0}, {0.0, 1.0}, 1.0, 0.5};
  // Under the flat: the gap is the distance to the face.
  ProfilePoint p = closest_point(punch, {0.7, 0.25});
  EXPECT_TRUE(Near(p.gap, 0.25, {0, kTight}));
  EXPECT_TRUE(Near(p.normal.y(), 1.0, {0, kTight}));
  // Beside the flat, in front of the edge arc (centre (1, -0.5), radius 0.5): a surface point
  // at x = 1.3 has gap sqrt(0.3^2 + 0.5^2) - 0.5, normal from the arc centre.
  p = closest_point(punch, {1.3, 0.0});
  const double q = std::hypot(0.3, 0.5);
  EXPECT_TRUE(Near(p.gap, q - 0.5, {0, kTight}));
  EXPECT_TRUE(Near(p.normal.x(), 0.3 / q, {0, kTight}));
  EXPECT_TRUE(Near(p.normal.y(), 0.5 / q, {0, kTight}));
  // Symmetric about s = 0.
  EXPECT_TRUE(Near(closest_point(punch, {-1.3, 0.0}).gap, q - 0.5, {0, kTight}));
  // Beside the vertical side, behind the arc centre.
  p = closest_point(punch, {2.0, -1.0});
  EXPECT_TRUE(Near(p.gap, 0.5, {0, kTight}));
  EXPECT_TRUE(Near(p.normal.x(), 1.0, {0, kTight}));
  EXPECT_EQ(profile_kinks(punch).size(), 4u);
}

TEST(ContactRigidProfile, SharpPunchCorner) {
  const SharpFlatPunch punch{{0.0, 0.0}, {0.0, 1.0}, 1.0};
  ProfilePoint p = closest_point(punch, {1.0, 0.0});  // the corner itself: face normal
  EXPECT_TRUE(Near(p.gap, 0.0, {0, kTight}));
  EXPECT_TRUE(Near(p.normal.y(), 1.0, {0, kTight}));
  p = closest_point(punch, {1.3, 0.4});  // in front of the corner: distance to the corner
  EXPECT_TRUE(Near(p.gap, 0.5, {0, kTight}));
  EXPECT_TRUE(Near(p.normal.x(), 0.6, {0, kTight}));
  EXPECT_THROW(validate(RigidProfile{SharpFlatPunch{{0, 0}, {0, 0}, 1.0}}), ContactError);
  EXPECT_THROW(validate(RigidProfile{RoundedFlatPunch{{0, 0}, {0, 1}, 1.0, 0.0}}), ContactError);
}

// Requirement: with GapNormal::ContactSurface the gap is the distance from the contact point
// along the contact surface's normal to the target's tangent line (checked: the point moved
// back by that gap lies on a tilted rigid plane), the force direction is that normal, and the
// target's normal is kept where the surfaces do not face each other or when Target is chosen.
TEST(ContactGapNormal, AlongTheContactSurfaceNormalReachesTheTargetLine) {
  const double theta = 0.3;
  const RigidPlane plane{{0.2, 1.0}, {-std::sin(theta), -std::cos(theta)}};  // faces down
  const Eigen::Vector2d x{0.7, 0.4}, n_contact{0.0, 1.0};  // a block's top face, below it
  TargetPoint tp;
  const ProfilePoint pp = closest_point(RigidProfile{plane}, x);
  tp.gap = pp.gap;
  tp.normal = pp.normal;
  tp.closest = pp.closest;
  const TargetPoint along = oriented(tp, GapNormal::ContactSurface, n_contact);
  EXPECT_TRUE(Near(along.normal.x(), 0.0, {0, kTight}));
  EXPECT_TRUE(Near(along.normal.y(), -1.0, {0, kTight}));
  EXPECT_TRUE(Near(along.gap, tp.gap / std::cos(theta), {0, kTight}));
  const Eigen::Vector2d hit = x - along.gap * along.normal;  // straight up from x
  EXPECT_TRUE(Near((hit - plane.point).dot(plane.normal), 0.0, {0, kTight}));
  EXPECT_GT(std::abs(along.gap - tp.gap), 0.01);  // the closest distance is not that gap

  const TargetPoint same = oriented(tp, GapNormal::Target, n_contact);
  EXPECT_EQ(same.gap, tp.gap);
  EXPECT_EQ(same.normal, tp.normal);
  // a contact surface at right angles to the target: no gap along its normal
  const TargetPoint away = along_contact_normal(tp, Eigen::Vector2d{tp.normal.y(), -tp.normal.x()});
  EXPECT_EQ(away.gap, tp.gap);
  EXPECT_EQ(away.normal, tp.normal);
}

Model one_block(ElementType type, AnalysisType analysis, double x0, double width, int nx) {
  Model m;
  m.mesh = merge_bodies({contact_test::block_mesh(type, x0, 0.0, width, 0.5, nx, 2, "b")});
  m.analysis = analysis;
  m.materials.push_back({200.0, 0.3});
  return m;
}

TEST(ContactSurfaceGeometry, DepthNormalAndStiffness) {
  const Model m = one_block(ElementType::Q8, AnalysisType::PlaneStrain, 0.0, 2.0, 4);
  const ContactSurface s(m, "b.bottom");
  ASSERT_EQ(s.n_segments(), 4);
  for (int k = 0; k < s.n_segments(); ++k) {
    EXPECT_TRUE(Near(s.segment(k).depth_h, 0.25, {kTight, 0}));  // 0.5 / 2 elements
    EXPECT_TRUE(Near(s.segment(k).youngs_modulus_E, 200.0, {kTight, 0}));
    EXPECT_TRUE(Near(s.normal(k, 0.3).y(), -1.0, {0, kTight}));  // outward of the block
    EXPECT_TRUE(Near(s.measure(k, 0.3), 0.25, {kTight, 0}));     // ds/dt = L/2
  }
  EXPECT_EQ(s.nodes().size(), 9u);
}

TEST(ContactSurfaceGeometry, QuadraticSideSplitsPressureOneSixthTwoThirds) {
  const Model m = one_block(ElementType::Q8, AnalysisType::PlaneStrain, 0.0, 1.0, 1);
  const std::vector<ContactNode> nodes = contact_nodes(ContactSurface(m, "b.bottom"));
  ASSERT_EQ(nodes.size(), 3u);
  std::vector<double> w;
  for (const ContactNode& n : nodes)
    w.push_back(n.weight_w);
  std::sort(w.begin(), w.end());
  EXPECT_TRUE(Near(w[0], 1.0 / 6.0, {kTight, 0}));
  EXPECT_TRUE(Near(w[1], 1.0 / 6.0, {kTight, 0}));
  EXPECT_TRUE(Near(w[2], 2.0 / 3.0, {kTight, 0}));
}

TEST(ContactSurfaceGeometry, AxisymmetricWeightsCarryTheRadius) {
  // Q4 side from r = 1 to r = 3: int N_a r dr = (1/6)(2 r_a + r_b) L.
  const Model m = one_block(ElementType::Q4, AnalysisType::Axisymmetric, 1.0, 2.0, 1);
  const std::vector<ContactNode> nodes = contact_nodes(ContactSurface(m, "b.bottom"));
  ASSERT_EQ(nodes.size(), 2u);
  for (const ContactNode& n : nodes) {
    const double r = n.position.x();
    const double other = 4.0 - r;
    EXPECT_TRUE(Near(n.weight_w, (2.0 * r + other) * 2.0 / 6.0, {kTight, 0}));
  }
  // Q8 side on the axis: the corner at r = 0 has int N_a r dr = 0 (no consistent force), so
  // it is flagged degenerate and reports its mid-side neighbour's pressure.
  const Model q8 = one_block(ElementType::Q8, AnalysisType::Axisymmetric, 0.0, 1.0, 1);
  const std::vector<ContactNode> axis = contact_nodes(ContactSurface(q8, "b.bottom"));
  int degenerate = 0;
  for (const ContactNode& n : axis) {
    if (n.position.x() == 0.0) {
      EXPECT_TRUE(Near(n.weight_w, 0.0, {0, kTight}));
      EXPECT_TRUE(n.degenerate());
      ASSERT_GE(n.pressure_neighbour, 0);
      EXPECT_TRUE(Near(axis[n.pressure_neighbour].position.x(), 0.5, {0, kTight}));
      ++degenerate;
    }
  }
  EXPECT_EQ(degenerate, 1);
}

TEST(ContactTargetProjection, MeshedTargetInsideAndBeyondItsEnd) {
  contact_test::PatchSpec spec;
  spec.indenter_nx = 3;
  const Model model = contact_test::patch_model(spec);
  const ContactTarget target = make_target(model, TargetSurface{"indenter.top"});
  // A point 0.1 below the middle of the indenter's face (z = 0, normal +z out of it).
  TargetPoint tp = project(target, {0.5, 0.1});
  EXPECT_TRUE(Near(tp.gap, 0.1, {0, kTight}));
  EXPECT_TRUE(Near(tp.normal.y(), 1.0, {0, kTight}));
  double sum = 0.0;
  for (int i = 0; i < tp.n_master; ++i)
    sum += tp.master_weights[i];
  EXPECT_TRUE(Near(sum, 1.0, {0, kTight}));  // partition of unity
  // Beyond the end of the face (x = 1): closest to the corner node, normal from it.
  tp = project(target, {1.3, 0.4});
  EXPECT_TRUE(Near(tp.gap, 0.5, {0, kTight}));
  EXPECT_TRUE(Near(tp.normal.x(), 0.6, {0, kTight}));
  EXPECT_EQ(describe(target), "target surface 'indenter.top'");
}

// Requirement: a point inside a convex target corner, on its bisector (equally far from both
// sides, to round-off), projects onto the corner node with the bisector as normal, the same in
// any units: not onto whichever side round-off finds a hair closer (whose normal is tilted by
// half the corner's angle).
TEST(ContactTargetProjection, EquallyCloseSidesTakeTheirSharedNode) {
  contact_test::PatchSpec spec;
  spec.indenter_nx = 2;
  for (const double L : {1.0, 1e3, 1e-3}) {
    Model model = contact_test::patch_model(spec);
    int peak = -1;
    for (int n : resolve_nodes(model.mesh, NodeSelection::edge_set("indenter.top"))) {
      if (std::abs(model.mesh.nodes[n].x() - 0.5) < 1e-12)
        peak = n;
    }
    ASSERT_GE(peak, 0);
    model.mesh.nodes[peak].y() = 0.1;  // a roof: two sides meeting at (0.5, 0.1)
    for (auto& x : model.mesh.nodes)
      x *= L;
    const ContactTarget target = make_target(model, TargetSurface{"indenter.top"});
    const TargetPoint tp = project(target, Eigen::Vector2d(0.5, 0.05) * L);
    EXPECT_TRUE(Near(tp.gap / L, -0.05, {0, kTight})) << "L = " << L;
    EXPECT_TRUE(Near(tp.normal.x(), 0.0, {0, kTight})) << "L = " << L;
    EXPECT_TRUE(Near(tp.normal.y(), 1.0, {0, kTight})) << "L = " << L;
    EXPECT_TRUE(Near(tp.closest.y() / L, 0.1, {0, kTight})) << "L = " << L;
  }
}

TEST(ContactMortar, CutsAtTargetNodesInsideTheSegment) {
  const Model m = one_block(ElementType::Q4, AnalysisType::PlaneStrain, 0.0, 1.0, 2);
  const ContactSurface s(m, "b.bottom");
  // Segment [0, 0.5] (or [0.5, 1]): points projecting to x = 0.2 cut at t = -0.2 (or none).
  const std::vector<Eigen::Vector2d> points{{0.2, -0.01}, {0.5, -0.01}, {5.0, 0.0}};
  int cuts = 0;
  for (int k = 0; k < s.n_segments(); ++k) {
    for (double t : mortar_cuts(s, k, points)) {
      EXPECT_TRUE(Near(s.point(k, t).x(), 0.2, {0, kTight}));
      ++cuts;
    }
  }
  EXPECT_EQ(cuts, 1);  // x = 0.5 is a segment end, x = 5 is far away
}

}  // namespace
}  // namespace cs::solver
