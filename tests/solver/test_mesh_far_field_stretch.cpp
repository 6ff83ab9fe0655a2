// Requirement: the far-field stretch enlarges a quadrant block to a given extent while every
// node within `inner` stays put, square faces stay square and straight, no element inverts,
// and the aspect ratio of an element grows locally by the exponent m of the stretch.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/mesh/far_field_stretch.hpp"
#include "solver/mesh/mesh_error.hpp"
#include "solver/mesh/mesh_quality.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/structured_block.hpp"

namespace cs::solver {
namespace {

Mesh square_block(ElementType type, int n) {
  BlockSpec spec;
  spec.type = type;
  spec.size = {8.0, 8.0};
  spec.nx = n;
  spec.nz = n;
  return make_block(spec);
}

/// Largest side over smallest side of element e (corners only).
double aspect_ratio(const Mesh& m, int e) {
  double lo = 1e300, hi = 0.0;
  for (int s = 0; s < 4; ++s) {
    const double l = (m.nodes[m.elements[e][(s + 1) % 4]] - m.nodes[m.elements[e][s]]).norm();
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  return hi / lo;
}

TEST(FarFieldStretch, InnerNodesStayAndFacesMoveToTheNewExtent) {
  for (const ElementType type : {ElementType::Q4, ElementType::Q8}) {
    const Mesh before = square_block(type, 16);
    Mesh after = before;
    stretch_far_field(after, {4.0, 8.0, 64.0});
    ASSERT_NO_THROW(check_mesh(after));
    for (int n = 0; n < before.n_nodes(); ++n) {
      const auto& p = before.nodes[n];
      const auto& q = after.nodes[n];
      const double r = std::max(p.x(), p.y());
      if (r <= 4.0) {
        EXPECT_EQ(p, q) << "node " << n;
      }
      if (std::abs(p.x() - 8.0) < 1e-12) {
        EXPECT_NEAR(q.x(), 64.0, 1e-12) << "the face x = 8 goes to x = 64 and stays straight";
      }
      if (std::abs(p.y() - 8.0) < 1e-12) {
        EXPECT_NEAR(q.y(), 64.0, 1e-12);
      }
      if (p.y() == 0.0) {
        EXPECT_EQ(q.y(), 0.0) << "the contact surface stays on z = 0";
      }
      if (p.x() == 0.0) {
        EXPECT_EQ(q.x(), 0.0) << "the symmetry line stays on x = 0";
      }
    }
  }
}

/// The largest growth of an element's aspect ratio when a block of n x n elements is stretched
/// from 8 to 64 with inner = 4.
double worst_aspect_growth(int n) {
  const Mesh before = square_block(ElementType::Q4, n);
  Mesh after = before;
  stretch_far_field(after, {4.0, 8.0, 64.0});
  double worst = 0.0;
  for (int e = 0; e < after.n_elements(); ++e)
    worst = std::max(worst, aspect_ratio(after, e) / aspect_ratio(before, e));
  return worst;
}

TEST(FarFieldStretch, AspectRatiosGrowByTheExponentForSmallElements) {
  // m = ln(64/4) / ln(8/4) = 4 is the growth of a small element away from the diagonal; finite
  // elements, and those across the diagonal x = z where the squares turn, exceed it by a
  // margin that does not grow under refinement.
  const double coarse = worst_aspect_growth(16), fine = worst_aspect_growth(64);
  EXPECT_GT(coarse, 4.0);
  EXPECT_LT(fine, coarse);
  EXPECT_GT(fine, 4.0);
  EXPECT_LT(fine, 5.5);
}

TEST(FarFieldStretch, Q8MidSideNodesStayAtTheMidpoints) {
  Mesh m = square_block(ElementType::Q8, 8);
  stretch_far_field(m, {4.0, 8.0, 32.0});
  for (const auto& e : m.elements) {
    for (int s = 0; s < 4; ++s) {
      const Eigen::Vector2d mid = 0.5 * (m.nodes[e[s]] + m.nodes[e[(s + 1) % 4]]);
      EXPECT_NEAR((m.nodes[e[4 + s]] - mid).norm(), 0.0, 1e-12);
    }
  }
}

TEST(FarFieldStretch, TheMapIsContinuousAndMonotoneAlongARay) {
  const FarFieldStretch s{2.0, 4.0, 32.0};
  double last = 0.0;
  for (double r = 0.25; r <= 4.0 + 1e-12; r += 0.25) {
    const double x = far_field_stretch(s, {r, 0.5 * r}).x();
    EXPECT_GT(x, last);
    last = x;
  }
  EXPECT_NEAR(far_field_stretch(s, {2.0 + 1e-9, 0.0}).x(), 2.0, 1e-8);
  EXPECT_NEAR(far_field_stretch(s, {4.0, 1.0}).x(), 32.0, 1e-12);
  EXPECT_NEAR(far_field_stretch(s, {4.0, 1.0}).y(), 8.0, 1e-12);
}

TEST(FarFieldStretch, BadBoundsAreMeshErrors) {
  Mesh m = square_block(ElementType::Q4, 2);
  EXPECT_THROW(stretch_far_field(m, {0.0, 8.0, 16.0}), MeshError);
  EXPECT_THROW(stretch_far_field(m, {8.0, 8.0, 16.0}), MeshError);
  EXPECT_THROW(stretch_far_field(m, {4.0, 8.0, 7.0}), MeshError);
  EXPECT_THROW(stretch_far_field(m, {4.0, 8.0, std::nan("")}), MeshError);
  EXPECT_NO_THROW(stretch_far_field(m, {4.0, 8.0, 8.0}));
}

}  // namespace
}  // namespace cs::solver
