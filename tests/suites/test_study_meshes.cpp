// Tests of the study's meshes: Table 1 counts, valid elements, named sets, node alignment between
// block and indenter (P vs P'), and the Steuermann refinement at the contact edge.

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "solver/mesh/mesh_quality.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "suites/study_meshes.hpp"
#include "suites/suite_error.hpp"
#include "support/tolerance.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::suites::test_study_meshes {
namespace {

using cs::testing::Near;
using solver::ElementType;
namespace sets = study_sets;

/// a / b of the Steuermann punch from Eq. 32 (bisection), with P = 2 p (b + r_e), p/E = 1e-3,
/// nu = 1/4 and the factor (1 - nu^2): the suite's convention. The meshes only need b < a < b+r_e.
double steuermann_a(double re_over_b) {
  const double lhs = 2.0 * re_over_b * (1.0 - 1.0 / 16.0) * 2e-3 * (1.0 + re_over_b);
  auto rhs = [](double phi) {
    return (M_PI - 2 * phi) / (2 * std::sin(phi) * std::sin(phi)) - 1.0 / std::tan(phi);
  };
  double lo = 0.1, hi = M_PI / 2 - 1e-15;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rhs(mid) > lhs ? lo : hi) = mid;
  }
  return 1.0 / std::sin(0.5 * (lo + hi));
}

StudyMeshSpec spec_for(ProblemId problem, MeshLevel level, ElementType element) {
  StudyMeshSpec spec;
  spec.problem = problem;
  spec.level = level;
  spec.element = element;
  spec.a = 1.0;
  spec.R = 419.0;  // a/R of H with p/E = 1e-3, nu = 1/4
  if (problem == ProblemId::S_1 || problem == ProblemId::S_1_3 || problem == ProblemId::S_1_7) {
    spec.b = 1.0;
    spec.r_e = problem == ProblemId::S_1 ? 1.0 : problem == ProblemId::S_1_3 ? 1.0 / 3 : 1.0 / 7;
    spec.a = steuermann_a(spec.r_e);
  }
  return spec;
}

const std::vector<ProblemId> kStructured = {
    ProblemId::P_p, ProblemId::P_a, ProblemId::Pprime_p, ProblemId::Pprime_a,
    ProblemId::H_p, ProblemId::H_a, ProblemId::F_p,      ProblemId::F_a};
const std::vector<ProblemId> kSteuermann = {ProblemId::S_1, ProblemId::S_1_3, ProblemId::S_1_7};

TEST(StudyMeshes, Table1Values) {
  EXPECT_EQ(table1_elements(ProblemId::P_p, MeshLevel::F), 1024);
  EXPECT_EQ(table1_elements(ProblemId::Pprime_a, MeshLevel::M), 400);
  EXPECT_EQ(table1_elements(ProblemId::H_a, MeshLevel::C), 256);
  EXPECT_EQ(table1_elements(ProblemId::S_1, MeshLevel::F), 133952);
  EXPECT_EQ(table1_elements(ProblemId::S_1_3, MeshLevel::M), 64888);
  EXPECT_EQ(table1_elements(ProblemId::S_1_7, MeshLevel::F), 268944);
  EXPECT_EQ(table1_elements(ProblemId::F_p, MeshLevel::F), 16384);
  EXPECT_EQ(steuermann_target_elements(1.0 / 3.0, MeshLevel::C), 16222);
  EXPECT_EQ(steuermann_target_elements(0.01, MeshLevel::C), 16809);
  const int between = steuermann_target_elements(0.5, MeshLevel::C);
  EXPECT_GT(between, 8372);
  EXPECT_LT(between, 16222);
}

TEST(StudyMeshes, StructuredCountsEqualTable1AndElementsAreValid) {
  for (ProblemId p : kStructured) {
    for (MeshLevel level : schema::kStudyMeshes) {
      for (ElementType element : {ElementType::Q4, ElementType::Q8}) {
        const StudyMesh m = build_study_mesh(spec_for(p, level, element));
        const std::string what = fmt::format("{} {} {}", to_string(p), to_string(level),
                                             element == ElementType::Q8 ? "Q8" : "Q4");
        EXPECT_EQ(m.info.n_block_elements, table1_elements(p, level)) << what;
        EXPECT_EQ(m.info.table1_block_elements, table1_elements(p, level)) << what;
        const int block =
            static_cast<int>(std::count(m.mesh.element_body.begin(), m.mesh.element_body.end(), 0));
        EXPECT_EQ(block, m.info.n_block_elements) << what;
        EXPECT_EQ(m.mesh.n_elements(), m.info.n_block_elements + m.info.n_indenter_elements);
        EXPECT_EQ(m.mesh.type, element);
        EXPECT_NO_THROW(solver::check_mesh(m.mesh)) << what;
        EXPECT_GT(solver::min_jacobian_determinant(m.mesh), 0.0) << what;
      }
    }
  }
}

// Requirement: the fourth level VF halves F's element sides (8x C's, 64x its elements) and has
// no Table 1 count (the study ran three meshes).
TEST(StudyMeshes, VeryFineLevelHalvesTheFineMesh) {
  EXPECT_EQ(level_factor(MeshLevel::VF), 2 * level_factor(MeshLevel::F));
  for (ProblemId p : kStructured)
    EXPECT_EQ(table1_elements(p, MeshLevel::VF), 0) << to_string(p);
  const StudyMesh c = build_study_mesh(spec_for(ProblemId::H_p, MeshLevel::C, ElementType::Q4));
  const StudyMesh vf = build_study_mesh(spec_for(ProblemId::H_p, MeshLevel::VF, ElementType::Q4));
  EXPECT_EQ(vf.info.n_block_elements, 64 * c.info.n_block_elements);
  EXPECT_NEAR(vf.info.h_contact, c.info.h_contact / 8.0, 1e-12 * c.info.h_contact);
}

TEST(StudyMeshes, GeometryAndSetsOfTheHertzMesh) {
  const StudyMesh m = build_study_mesh(spec_for(ProblemId::H_a, MeshLevel::M, ElementType::Q8));
  EXPECT_EQ(m.mesh.body_names, (std::vector<std::string>{sets::kBlock, sets::kIndenter}));
  EXPECT_EQ(m.info.block_width, 8.0);
  EXPECT_EQ(m.info.block_depth, 8.0);
  EXPECT_EQ(m.info.h_contact, 0.25);  // 8a / 32
  for (const char* name : {sets::kBlockContact, sets::kBlockSymmetry, sets::kBlockFarX,
                           sets::kBlockFarZ, sets::kIndenterContact, sets::kIndenterLoad,
                           sets::kIndenterSymmetry, sets::kIndenterSide}) {
    EXPECT_FALSE(solver::edge_set(m.mesh, name).empty()) << name;
    EXPECT_FALSE(solver::node_set(m.mesh, name).empty()) << name;
  }
  for (int n : solver::node_set(m.mesh, sets::kBlockContact))
    EXPECT_EQ(m.mesh.nodes[n].y(), 0.0);
  for (int n : solver::node_set(m.mesh, sets::kBlockFarZ))
    EXPECT_EQ(m.mesh.nodes[n].y(), 8.0);
  for (int n : solver::node_set(m.mesh, sets::kBlockFarX))
    EXPECT_EQ(m.mesh.nodes[n].x(), 8.0);
  for (int n : solver::node_set(m.mesh, sets::kBlockSymmetry)) {
    EXPECT_EQ(m.mesh.nodes[n].x(), 0.0);
  }
  for (int n : solver::node_set(m.mesh, sets::kIndenterLoad)) {
    EXPECT_EQ(m.mesh.nodes[n].y(), -m.info.indenter_height);
  }
  // The indenter's surface is the sphere through the origin, z = -(R - sqrt(R^2 - r^2)).
  for (int n : solver::node_set(m.mesh, sets::kIndenterContact)) {
    const auto& p = m.mesh.nodes[n];
    EXPECT_TRUE(Near(p.y(), -(419.0 - std::sqrt(419.0 * 419.0 - p.x() * p.x())), {1e-9, 1e-15}));
    EXPECT_LE(p.y(), 0.0);
  }
  for (const auto& s : solver::edge_set(m.mesh, sets::kIndenterContact)) {
    EXPECT_EQ(m.mesh.element_body[s.element], 1);
  }
}

/// Block surface nodes under the indenter with an indenter surface node at the same x, and
/// their number.
std::pair<int, int> aligned_surface_nodes(const StudyMesh& m, double x_max) {
  const auto block = solver::edge_set_nodes_sorted_along_x(m.mesh, sets::kBlockContact);
  const auto indenter = solver::edge_set_nodes_sorted_along_x(m.mesh, sets::kIndenterContact);
  int under = 0, aligned = 0;
  for (int n : block) {
    const double x = m.mesh.nodes[n].x();
    if (x > x_max)
      continue;
    ++under;
    const bool match = std::any_of(indenter.begin(), indenter.end(), [&](int k) {
      return std::abs(m.mesh.nodes[k].x() - x) <= 1e-12 * x_max;  // round-off of equal formulas
    });
    aligned += match ? 1 : 0;
  }
  return {aligned, under};
}

TEST(StudyMeshes, PatchTestNodesMatchButPrimeNodesDoNot) {
  for (MeshLevel level : schema::kStudyMeshes) {
    for (ElementType element : {ElementType::Q4, ElementType::Q8}) {
      const StudyMesh p = build_study_mesh(spec_for(ProblemId::P_p, level, element));
      const auto [aligned_p, under_p] = aligned_surface_nodes(p, 1.0);
      EXPECT_EQ(aligned_p, under_p);
      EXPECT_EQ(p.info.indenter_surface_elements, 8 * level_factor(level));

      const StudyMesh q = build_study_mesh(spec_for(ProblemId::Pprime_a, level, element));
      const auto [aligned_q, under_q] = aligned_surface_nodes(q, 1.0);
      EXPECT_EQ(q.info.indenter_surface_elements, 10 * level_factor(level) - 1);
      // Only the two ends line up (and, for Q8, the middle, a mid-side node of the indenter).
      EXPECT_EQ(aligned_q, element == ElementType::Q4 ? 2 : 3);
      EXPECT_GT(under_q, 10);
    }
  }
}

TEST(StudyMeshes, IndenterNodesMatchForHertzAndFlatPunch) {
  for (ProblemId problem : {ProblemId::H_p, ProblemId::F_a}) {
    const StudyMesh m = build_study_mesh(spec_for(problem, MeshLevel::M, ElementType::Q8));
    const auto [aligned, under] = aligned_surface_nodes(m, m.info.indenter_half_width);
    EXPECT_EQ(aligned, under) << to_string(problem);
  }
}

TEST(StudyMeshes, SteuermannCountsWithin5PercentOfTable1AtEveryLevel) {
  for (ProblemId p : kSteuermann) {
    for (MeshLevel level : schema::kStudyMeshes) {
      const StudyMeshSpec spec = spec_for(p, level, ElementType::Q4);
      const StudyMesh m = build_study_mesh(spec);
      const double table = table1_elements(p, level);
      EXPECT_TRUE(Near(m.info.n_block_elements, table, {0.05, 0.0}))
          << to_string(p) << " " << to_string(level);
      // Halving element sides: exactly 4x and 16x the C count.
      const int f = level_factor(level);
      EXPECT_EQ(m.info.n_block_elements % (f * f), 0);
      if (level == MeshLevel::C) {
        EXPECT_NO_THROW(solver::check_mesh(m.mesh)) << to_string(p);
      }
    }
  }
}

TEST(StudyMeshes, SteuermannQ8MeshesAreValidAndAligned) {
  for (ProblemId p : kSteuermann) {
    const StudyMeshSpec spec = spec_for(p, MeshLevel::M, ElementType::Q8);
    const StudyMesh m = build_study_mesh(spec);
    EXPECT_NO_THROW(solver::check_mesh(m.mesh)) << to_string(p);
    const auto [aligned, under] = aligned_surface_nodes(m, spec.a);
    EXPECT_EQ(aligned, under) << to_string(p);
    EXPECT_EQ(m.info.indenter_half_width, spec.b + spec.r_e);
    for (int n : solver::node_set(m.mesh, sets::kIndenterSide)) {
      EXPECT_TRUE(Near(m.mesh.nodes[n].x(), spec.b + spec.r_e, {1e-14, 0.0}));
    }
  }
}

/// Checks that the smallest block elements sit in a narrow band around the contact edge
/// [b, a] at the surface, and that there are nodes exactly at x = b and x = a.
void expect_refined_at_contact_edge(const StudyMeshSpec& spec) {
  const StudyMesh m = build_study_mesh(spec);
  const auto& mesh = m.mesh;
  const std::string what = fmt::format("r_e/b = {}", spec.r_e / spec.b);
  double smallest = INFINITY;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_body[e] == 0)
      smallest = std::min(smallest, solver::element_size(mesh, e));
  }
  const double band = spec.a - spec.b;
  ASSERT_FALSE(m.info.steuermann_boxes.empty());
  const double finest = m.info.steuermann_boxes.back().cell_size / level_factor(spec.level);
  EXPECT_LE(finest, band / spec.options.steuermann_band_elements) << what;
  EXPECT_LT(finest, m.info.h_background / 2.9) << what;  // at least one 3:1 level
  // Snapping x = b and x = a onto node lines stretches cells by at most 2x either way.
  EXPECT_LE(smallest, finest * (1 + 1e-9)) << what;
  EXPECT_GE(smallest, 0.5 * finest) << what;
  EXPECT_LE(m.info.h_contact, 2 * finest) << what;
  EXPECT_GE(m.info.h_contact, 0.5 * finest) << what;
  // Elements of the finest size: centroids within a few box paddings of [b, a], at the top.
  const double reach = 2.0 * spec.options.steuermann_box_padding * 3.0 * finest;
  int n_small = 0;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (mesh.element_body[e] != 0 || solver::element_size(mesh, e) > 1.01 * finest)
      continue;
    ++n_small;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (int k = 0; k < 4; ++k)
      c += 0.25 * mesh.nodes[mesh.elements[e][k]];
    EXPECT_GT(c.x(), spec.b - reach) << what;
    EXPECT_LT(c.x(), spec.a + reach) << what;
    EXPECT_LT(c.y(), reach) << what;
  }
  EXPECT_GT(n_small, spec.options.steuermann_band_elements);
  // The surface between b and a is divided into finest-size elements only.
  for (const auto& s : solver::edge_set(mesh, sets::kBlockContact)) {
    const auto n = mesh.side_nodes(s);
    const double x0 = mesh.nodes[n[0]].x(), x1 = mesh.nodes[n[1]].x();
    const double mid = 0.5 * (x0 + x1);
    if (mid > spec.b && mid < spec.a) {
      EXPECT_LE(std::abs(x1 - x0), 2 * finest) << what;
    }
  }
  const auto surface = solver::node_set(mesh, sets::kBlockContact);
  for (double x : {spec.b, spec.a}) {
    EXPECT_TRUE(
        std::any_of(surface.begin(), surface.end(), [&](int n) { return mesh.nodes[n].x() == x; }))
        << what << ": no node at x = " << x;
  }
}

TEST(StudyMeshes, SteuermannRefinementSitsAtTheContactEdge) {
  for (ProblemId p : kSteuermann) {
    expect_refined_at_contact_edge(spec_for(p, MeshLevel::C, ElementType::Q4));
  }
  // A changed r_e/b still refines at its own contact edge.
  StudyMeshSpec spec = spec_for(ProblemId::S_1_3, MeshLevel::C, ElementType::Q4);
  spec.r_e = 0.5;
  spec.a = steuermann_a(0.5);
  expect_refined_at_contact_edge(spec);
  spec.r_e = 4.0;
  spec.a = steuermann_a(4.0);
  expect_refined_at_contact_edge(spec);
}

TEST(StudyMeshes, SteuermannFineMeshHasTheStudysSize) {
  // The largest mesh of the battery, built once: 268,944 elements in the study.
  const StudyMesh m = build_study_mesh(spec_for(ProblemId::S_1_7, MeshLevel::F, ElementType::Q4));
  EXPECT_TRUE(Near(m.info.n_block_elements, 268944, {0.05, 0.0}));
  EXPECT_EQ(m.info.n_block_elements % 16, 0);
  EXPECT_GT(solver::min_jacobian_determinant(m.mesh), 0.0);
}

TEST(StudyMeshes, BadGeometryIsRejected) {
  StudyMeshSpec spec = spec_for(ProblemId::S_1, MeshLevel::C, ElementType::Q4);
  spec.a = 0.9;  // a < b
  EXPECT_THROW(build_study_mesh(spec), SuiteInputError);
  spec = spec_for(ProblemId::H_p, MeshLevel::C, ElementType::Q4);
  spec.R = 1.5;  // smaller than the indenter's half-width 2a
  EXPECT_THROW(build_study_mesh(spec), SuiteInputError);
  spec = spec_for(ProblemId::F_p, MeshLevel::C, ElementType::Q4);
  spec.a = -1.0;
  EXPECT_THROW(build_study_mesh(spec), SuiteInputError);
}

TEST(StudyMeshes, ExtentMovesTheFacesAndKeepsTheMeshNearTheContact) {
  // Requirement (#12): `extent` enlarges H, S and F blocks with the near-contact mesh unchanged.
  const std::vector<ProblemId> problems = {ProblemId::H_p, ProblemId::H_a,   ProblemId::F_p,
                                           ProblemId::S_1, ProblemId::S_1_3, ProblemId::S_1_7};
  for (const ProblemId problem : problems) {
    for (const ElementType element : {ElementType::Q4, ElementType::Q8}) {
      SCOPED_TRACE(
          fmt::format("{} {}", to_string(problem), element == ElementType::Q4 ? "Q4" : "Q8"));
      const StudyMeshSpec study = spec_for(problem, MeshLevel::C, element);
      StudyMeshSpec wide = study;
      wide.extent = 4.0;
      const StudyMesh a = build_study_mesh(study);
      const StudyMesh b = build_study_mesh(wide);
      ASSERT_EQ(a.mesh.n_nodes(), b.mesh.n_nodes());
      ASSERT_EQ(a.mesh.elements, b.mesh.elements);
      EXPECT_DOUBLE_EQ(b.info.block_width, 4.0 * a.info.block_width);
      EXPECT_DOUBLE_EQ(b.info.block_depth, 4.0 * a.info.block_depth);
      EXPECT_EQ(a.info.h_contact, b.info.h_contact);
      EXPECT_NO_THROW(solver::check_mesh(b.mesh));
      // Nodes within half the study's extent stay; a Q8 mid-side node of a side that crosses
      // that square follows its corner, so look a little inside it.
      const double inner = 0.45 * a.info.block_width;
      int kept = 0, moved = 0;
      for (int n = 0; n < a.mesh.n_nodes(); ++n) {
        const auto& p = a.mesh.nodes[n];
        if (std::max(std::abs(p.x()), std::abs(p.y())) <= inner) {
          EXPECT_EQ(p, b.mesh.nodes[n]) << "node " << n;
          ++kept;
        } else {
          moved += p != b.mesh.nodes[n];
        }
      }
      EXPECT_GT(kept, 0);
      EXPECT_GT(moved, 0);
      double far_x = 0.0;
      for (const int n : solver::node_set(b.mesh, sets::kBlockFarX))
        far_x = std::max(far_x, b.mesh.nodes[n].x());
      EXPECT_NEAR(far_x, b.info.block_width, 1e-9 * b.info.block_width);
    }
  }
}

TEST(StudyMeshes, ExtentBelowOneOrOnAPatchTestIsRejected) {
  StudyMeshSpec spec = spec_for(ProblemId::H_p, MeshLevel::C, ElementType::Q4);
  spec.extent = 0.5;
  EXPECT_THROW(build_study_mesh(spec), SuiteInputError);
  spec.extent = std::nan("");
  EXPECT_THROW(build_study_mesh(spec), SuiteInputError);
  spec = spec_for(ProblemId::P_p, MeshLevel::C, ElementType::Q4);
  spec.extent = 2.0;
  EXPECT_THROW(build_study_mesh(spec), SuiteInputError);
}

}  // namespace
}  // namespace cs::suites::test_study_meshes
