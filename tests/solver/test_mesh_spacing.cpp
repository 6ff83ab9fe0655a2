// Unit tests of the 1D spacings: uniform, geometric, graded toward a point, piecewise.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "solver/mesh/mesh_error.hpp"
#include "solver/mesh/spacing.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::solver::test_mesh_spacing {
namespace {

using cs::testing::Near;

constexpr cs::testing::Tolerance kRoundOff{1e-12, 1e-14};  // sums of a few hundred sizes

std::vector<double> sizes_of(const std::vector<double>& x) {
  std::vector<double> h;
  for (std::size_t i = 1; i < x.size(); ++i)
    h.push_back(x[i] - x[i - 1]);
  return h;
}

TEST(Spacing, GeometricSizesGrowByTheRatio) {
  const auto t = geometric_coordinates(5, 1.5);
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 1.0);
  const auto h = sizes_of(t);
  for (std::size_t i = 1; i < h.size(); ++i) {
    EXPECT_TRUE(Near(h[i] / h[i - 1], 1.5, kRoundOff)) << i;
  }
}

TEST(Spacing, GradedFromHasTheRequestedFirstSizeAndGrowthBound) {
  const Grading g{0.01, 1.3, 0.5};
  const auto x = graded_from(2.0, 7.0, g);
  EXPECT_EQ(x.front(), 2.0);
  EXPECT_EQ(x.back(), 7.0);
  const auto h = sizes_of(x);
  EXPECT_TRUE(Near(h.front(), 0.01, kRoundOff));
  for (std::size_t i = 1; i < h.size(); ++i) {
    EXPECT_GT(h[i], 0.0);
    EXPECT_LE(h[i] / h[i - 1], 1.3 * (1 + 1e-12)) << i;
    EXPECT_GE(h[i] / h[i - 1], 1.0 - 1e-12) << i;  // monotone growth, the cap aside
    EXPECT_LE(h[i], 0.5 * (1 + 1e-12)) << i;
  }
}

TEST(Spacing, RefinedTowardAnInteriorPoint) {
  const Grading g{0.002, 1.25};
  const double x_star = 1.0249;
  const auto x = refined_toward(0.0, 8.0, x_star, g);
  ASSERT_TRUE(std::is_sorted(x.begin(), x.end()));
  EXPECT_TRUE(std::adjacent_find(x.begin(), x.end()) == x.end());  // strictly increasing
  const auto star = std::find(x.begin(), x.end(), x_star);
  ASSERT_NE(star, x.end()) << "x* must be a node";
  const auto h = sizes_of(x);
  const auto i_star = static_cast<std::size_t>(star - x.begin());
  EXPECT_TRUE(Near(h[i_star - 1], 0.002, kRoundOff));
  EXPECT_TRUE(Near(h[i_star], 0.002, kRoundOff));
  EXPECT_TRUE(Near(*std::min_element(h.begin(), h.end()), 0.002, kRoundOff));
  // Sizes fall toward x* and rise after it.
  for (std::size_t i = 1; i < i_star; ++i)
    EXPECT_LE(h[i], h[i - 1] * (1 + 1e-12)) << i;
  for (std::size_t i = i_star + 1; i < h.size(); ++i)
    EXPECT_GE(h[i], h[i - 1] * (1 - 1e-12));
}

TEST(Spacing, ShortIntervalsFallBackToUniformNoSmallerThanHMin) {
  const auto x = graded_from(0.0, 0.025, Grading{0.01, 2.0});
  const auto h = sizes_of(x);
  for (double hi : h)
    EXPECT_GE(hi, 0.01 * (1 - 1e-12));
  EXPECT_EQ(x.back(), 0.025);
}

TEST(Spacing, JoinConcatenatesPiecesAndSharesTheirEnds) {
  const auto x = join_coordinates({uniform_between(0.0, 1.0, 4), graded_from(1.0, 3.0, {0.25, 1.5}),
                                   uniform_between(3.0, 4.0, 2)});
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_EQ(x.back(), 4.0);
  EXPECT_TRUE(std::adjacent_find(x.begin(), x.end(), std::greater_equal<>()) == x.end());
  EXPECT_EQ(std::count(x.begin(), x.end(), 1.0), 1);
  EXPECT_THROW(join_coordinates({uniform_between(0.0, 1.0, 2), uniform_between(1.5, 2.0, 2)}),
               MeshError);
  const Spacing s = breakpoints_of(x);
  EXPECT_EQ(s.kind, SpacingKind::Breakpoints);
  EXPECT_EQ(s.breakpoints.size(), x.size());
  EXPECT_TRUE(Near(s.breakpoints[4], 0.25, kRoundOff));
}

TEST(Spacing, BadGradingIsRejected) {
  EXPECT_THROW(graded_from(0.0, 1.0, {0.0, 1.2}), MeshError);
  EXPECT_THROW(graded_from(0.0, 1.0, {0.1, 0.9}), MeshError);
  EXPECT_THROW(graded_from(1.0, 1.0, {0.1, 1.2}), MeshError);
  EXPECT_THROW(refined_toward(0.0, 1.0, 2.0, {0.1, 1.2}), MeshError);
  EXPECT_THROW(geometric_coordinates(3, 0.0), MeshError);
}

}  // namespace
}  // namespace cs::solver::test_mesh_spacing
