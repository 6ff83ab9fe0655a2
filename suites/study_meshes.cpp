#include "suites/study_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "solver/mesh/far_field_stretch.hpp"
#include "solver/mesh/indenter.hpp"
#include "solver/mesh/mesh_merge.hpp"
#include "solver/mesh/mesh_sets.hpp"
#include "solver/mesh/mesh_transform.hpp"
#include "solver/mesh/nested_refinement.hpp"
#include "solver/mesh/structured_block.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

using solver::ElementType;
using solver::Mesh;

void require_positive(double value, const char* name, ProblemId problem) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw SuiteInputError(
        fmt::format("study mesh {}: {} = {} (must be > 0)", to_string(problem), name, value));
  }
}

/// The layout the problem's descriptor declares.
const MeshLayout& layout_of(ProblemId p) {
  return problem_descriptor(p).mesh_layout;
}
bool is_patch(ProblemId p) {
  const MeshFamily f = layout_of(p).family;
  return f == MeshFamily::patch || f == MeshFamily::mismatched_patch;
}

/// Gives a block made by make_block or make_nested_refinement the study's set names.
void name_block_sets(Mesh& block) {
  solver::rename_set(block, "bottom", "contact");
  solver::rename_set(block, "left", "symmetry");
  solver::rename_set(block, "right", "far_x");
  solver::rename_set(block, "top", "far_z");
}

/// Gives an indenter the study's set names (make_indenter names: contact, back, left, right).
void name_indenter_sets_for_study(Mesh& indenter) {
  solver::rename_set(indenter, "back", "load");
  solver::rename_set(indenter, "left", "symmetry");
  solver::rename_set(indenter, "right", "side");
}

/// The block's surface corner-node x positions (z = 0), increasing.
std::vector<double> surface_corner_x(const Mesh& block) {
  std::vector<double> xs;
  for (const auto& s : solver::edge_set(block, "contact")) {
    const auto n = block.side_nodes(s);
    xs.push_back(block.nodes[n[0]].x());
    xs.push_back(block.nodes[n[1]].x());
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  return xs;
}

/// Surface node positions for an indenter of the given half-width: the block's positions
/// below it, and the half-width itself (a block node closer than 0.3 of its element to the
/// half-width is dropped, so the last element is not a sliver).
std::vector<double> indenter_surface_x(const std::vector<double>& block_x, double half_width) {
  std::vector<double> xs;
  for (std::size_t i = 0; i < block_x.size(); ++i) {
    const double x = block_x[i];
    if (x >= half_width * (1 - 1e-12))
      break;
    const bool last_below = i + 1 < block_x.size() && block_x[i + 1] > half_width;
    if (i > 0 && last_below && half_width - x < 0.3 * (block_x[i + 1] - x))
      break;
    xs.push_back(x);
  }
  xs.push_back(half_width);
  return xs;
}

/// Moves the faces of a square block of side `side` out to extent * side, keeping every node
/// within side / 2 of the contact centre where it is.
void extend_block(Mesh& block, double side, double extent) {
  if (extent != 1.0)
    solver::stretch_far_field(block, {0.5 * side, side, extent * side});
}

void require_extent(const StudyMeshSpec& spec) {
  const bool allowed = !is_patch(spec.problem) || spec.extent == 1.0;
  if (!(spec.extent >= 1.0) || !std::isfinite(spec.extent) || !allowed) {
    throw SuiteInputError(fmt::format("study mesh {}: extent = {} (must be >= 1{})",
                                      to_string(spec.problem), spec.extent,
                                      is_patch(spec.problem) ? ", and 1 for a patch test" : ""));
  }
}

struct UniformLayout {
  double width = 0, depth = 0;
  int n = 0;  // elements along each side at this level
};

UniformLayout uniform_layout(const StudyMeshSpec& spec) {
  const MeshLayout& layout = layout_of(spec.problem);
  if (layout.elements_per_side < 1 || !(layout.block_side_over_a > 0.0)) {
    throw SuiteInputError(fmt::format(
        "study mesh {}: a uniform layout needs elements_per_side >= 1 and block_side_over_a > 0 "
        "(has {} and {})",
        to_string(spec.problem), layout.elements_per_side, layout.block_side_over_a));
  }
  const int f = level_factor(spec.level);
  const double width = layout.block_side_over_a * spec.a;
  const double depth = is_patch(spec.problem) ? spec.options.patch_height_over_a * spec.a : width;
  return {width, depth, layout.elements_per_side * f};
}

/// P, P', H, F: a uniform block and a structured indenter.
StudyMesh build_uniform(const StudyMeshSpec& spec) {
  const auto& o = spec.options;
  const UniformLayout layout = uniform_layout(spec);
  require_positive(layout.depth, "patch_height_over_a * a", spec.problem);

  solver::BlockSpec block_spec;
  block_spec.type = spec.element;
  block_spec.size = {layout.width, layout.depth};
  block_spec.nx = layout.n;
  block_spec.nz = layout.n;
  block_spec.body_name = study_sets::kBlock;
  Mesh block = solver::make_block(block_spec);
  name_block_sets(block);
  const double h = layout.width / layout.n;

  solver::IndenterSpec ind;
  ind.type = spec.element;
  ind.body_name = study_sets::kIndenter;
  const std::vector<double> block_x = surface_corner_x(block);
  const MeshFamily family = layout_of(spec.problem).family;
  if (is_patch(spec.problem)) {
    ind.profile = solver::flat_profile(spec.a);
    ind.height = o.patch_indenter_height_over_a * spec.a;
    if (family == MeshFamily::mismatched_patch) {
      const int n = o.pprime_indenter_elements > 0 ? o.pprime_indenter_elements : layout.n - 1;
      ind.surface_x = solver::uniform_between(0.0, spec.a, n);
    } else {
      ind.surface_x = block_x;
    }
  } else if (family == MeshFamily::hertz) {
    const double half_width = o.hertz_indenter_half_width_over_a * spec.a;
    require_positive(half_width, "hertz_indenter_half_width_over_a * a", spec.problem);
    if (!(spec.R > half_width)) {
      throw SuiteInputError(
          fmt::format("study mesh {}: R = {} must exceed the indenter half-width {}",
                      to_string(spec.problem), spec.R, half_width));
    }
    ind.profile = solver::circle_profile(spec.R, std::min(half_width, layout.width));
    ind.height = o.hertz_indenter_height_over_a * spec.a;
    ind.surface_x = indenter_surface_x(block_x, ind.profile.half_width);
  } else {  // flat punch with sharp corners
    ind.profile = solver::flat_profile(spec.a);
    ind.height = o.punch_indenter_height_over_a * spec.a;
    ind.surface_x = indenter_surface_x(block_x, spec.a);
  }
  require_positive(ind.height, "indenter height", spec.problem);
  ind.n_rows = std::max(1, static_cast<int>(std::lround(ind.height / h)));
  Mesh indenter = solver::make_indenter(ind);
  name_indenter_sets_for_study(indenter);
  extend_block(block, layout.width, spec.extent);  // H and F blocks are square

  StudyMesh out;
  out.info.n_block_elements = block.n_elements();
  out.info.n_indenter_elements = indenter.n_elements();
  out.info.block_width = layout.width * spec.extent;
  out.info.block_depth = layout.depth * spec.extent;
  out.info.indenter_half_width = ind.profile.half_width;
  out.info.indenter_height = ind.height;
  out.info.h_background = h;
  out.info.indenter_surface_elements = static_cast<int>(ind.surface_x.size()) - 1;
  out.mesh = solver::merge_bodies({block, indenter});
  return out;
}

// ---- Steuermann ------------------------------------------------------------------------------

/// The C-level layout of the S block: background cells N, levels, and the engine input.
struct SteuermannLayout {
  int n = 0;
  int levels = 0;
  solver::NestedRefinementSpec block;
  solver::NestedRefinementLayout plan;
};

int levels_for(double cell, double band, int band_elements) {
  // least L >= 1 with cell / 3^L <= band / band_elements
  int levels = 1;
  double h = cell / 3.0;
  while (h * band_elements > band * (1 + 1e-12) && levels < solver::kMaxRefinementLevels) {
    h /= 3.0;
    ++levels;
  }
  return levels;
}

SteuermannLayout plan_steuermann(const StudyMeshSpec& spec, int target) {
  const auto& o = spec.options;
  const double b = spec.b;
  const double band = spec.a - spec.b;
  SteuermannLayout best;
  long best_error = std::numeric_limits<long>::max();
  for (int n = 8; n <= 2000; ++n) {
    solver::NestedRefinementSpec s;
    s.cell_size = 8.0 * b / n;
    s.nx = n;
    s.nz = n;
    s.refine_x_min = b;
    s.refine_x_max = spec.a;
    s.levels = levels_for(s.cell_size, band, o.steuermann_band_elements);
    s.box_padding = o.steuermann_box_padding;
    s.box_depth = o.steuermann_box_depth;
    s.snap_x = {b, spec.a};
    s.body_name = study_sets::kBlock;
    solver::NestedRefinementLayout plan;
    try {
      plan = solver::plan_nested_refinement(s);
    } catch (const solver::MeshError&) {
      continue;  // boxes do not fit this background: try the next
    }
    const long error = std::abs(static_cast<long>(plan.n_elements) - target);
    if (error < best_error) {
      best_error = error;
      best = {n, s.levels, s, plan};
    }
    if (plan.n_elements > 2 * target)
      break;  // counts only grow from here
  }
  if (best.n == 0) {
    throw SuiteInputError(
        fmt::format("study mesh S: no background fits b = {}, a = {}", b, spec.a));
  }
  // The indenter takes one level more than the block (steuermann_indenter), and the levels
  // stop at the nested refinement's limit: a band that needs the last one is not resolved.
  if (best.levels >= solver::kMaxRefinementLevels) {
    throw SuiteInputError(fmt::format(
        "study mesh S: the contact band past the flat face, a - b = {:.3g} b, is too narrow "
        "for the mesh ({} levels of nested refinement at most); a larger load (p_over_E) "
        "widens it",
        band / b, solver::kMaxRefinementLevels - 1));
  }
  return best;
}

/// The S indenter at level C: same lattice and boxes as the block near the surface.
Mesh steuermann_indenter(const StudyMeshSpec& spec, const SteuermannLayout& layout,
                         double* height) {
  const double coarse = 3.0 * layout.block.cell_size;
  const double w = spec.b + spec.r_e;
  int nx = std::max(1, static_cast<int>(std::lround(w / coarse)));
  while (nx * coarse <= spec.a)
    ++nx;
  const int strip = 2;
  const int nz = std::max(
      strip + 2, static_cast<int>(std::ceil(
                     spec.options.steuermann_indenter_height_over_re * spec.r_e / coarse - 1e-9)));
  solver::NestedRefinementSpec s = layout.block;
  s.cell_size = coarse;
  s.nx = nx;
  s.nz = nz;
  s.levels = layout.levels + 1;
  s.surface_strip_cells = strip;
  s.body_name = study_sets::kIndenter;
  if (s.refine_x_max > nx * coarse)
    s.refine_x_max = nx * coarse;
  Mesh indenter = solver::make_nested_refinement(s);
  solver::mirror_z(indenter);  // now in -nz*coarse <= z <= 0, surface ("bottom") at z = 0
  solver::rename_set(indenter, "bottom", "contact");
  solver::rename_set(indenter, "top", "back");
  *height = nz * coarse;
  return indenter;
}

/// Moves the indenter's x in (x_fix, x_end] linearly onto (x_fix, w], x_fix = max(a, x_end -
/// coarse cell), so that its side lands on x = b + r_e and nothing moves for x <= a.
void fit_indenter_width(Mesh& indenter, double a, double coarse, double x_end, double w) {
  if (x_end == w)
    return;
  const double x_fix = std::max(a, x_end - coarse);
  const double scale = (w - x_fix) / (x_end - x_fix);
  solver::map_nodes(indenter, [&](const Eigen::Vector2d& p) {
    Eigen::Vector2d q = p;
    if (p.x() > x_fix)
      q.x() = p.x() == x_end ? w : x_fix + (p.x() - x_fix) * scale;
    return q;
  });
}

StudyMesh build_steuermann(const StudyMeshSpec& spec) {
  require_positive(spec.b, "b", spec.problem);
  require_positive(spec.r_e, "r_e", spec.problem);
  require_positive(spec.a, "a", spec.problem);
  if (!(spec.a > spec.b && spec.a < spec.b + spec.r_e)) {
    throw SuiteInputError(
        fmt::format("study mesh {}: contact half-width a = {} must lie in (b, b + r_e) = ({}, {})",
                    to_string(spec.problem), spec.a, spec.b, spec.b + spec.r_e));
  }
  if (spec.options.steuermann_band_elements < 1) {
    throw SuiteInputError(fmt::format("study mesh S: steuermann_band_elements = {} (must be >= 1)",
                                      spec.options.steuermann_band_elements));
  }
  const int target = spec.options.steuermann_target_elements > 0
                         ? spec.options.steuermann_target_elements
                         : steuermann_target_elements(spec.r_e / spec.b, MeshLevel::C);
  const SteuermannLayout layout = plan_steuermann(spec, target);
  const int f = level_factor(spec.level);

  Mesh block = solver::refine_uniformly(solver::make_nested_refinement(layout.block), f);
  if (spec.element == ElementType::Q8) {
    block = solver::to_quadratic(block);
  }
  name_block_sets(block);

  // The indenter: refined and fitted to its width as Q4, then wrapped (see indenter.hpp).
  double height = 0.0;
  const double coarse = 3.0 * layout.block.cell_size;
  Mesh indenter = solver::refine_uniformly(steuermann_indenter(spec, layout, &height), f);
  const double x_end = solver::node_set(indenter, "right").empty()
                           ? 0.0
                           : indenter.nodes[solver::node_set(indenter, "right").front()].x();
  const double w = spec.b + spec.r_e;
  fit_indenter_width(indenter, spec.a, coarse, x_end, w);
  if (spec.element == ElementType::Q8) {
    indenter = solver::to_quadratic(indenter);
  }
  solver::wrap_onto_profile(indenter, solver::rounded_punch_profile(spec.b, spec.r_e), height);
  name_indenter_sets_for_study(indenter);
  extend_block(block, 8.0 * spec.b, spec.extent);

  StudyMesh out;
  out.info.n_block_elements = block.n_elements();
  out.info.n_indenter_elements = indenter.n_elements();
  out.info.block_width = 8.0 * spec.b * spec.extent;
  out.info.block_depth = 8.0 * spec.b * spec.extent;
  out.info.indenter_half_width = w;
  out.info.indenter_height = height;
  out.info.h_background = layout.block.cell_size / f;
  out.info.indenter_surface_elements =
      static_cast<int>(solver::edge_set(indenter, "contact").size());
  out.info.steuermann_background_cells = layout.n;
  out.info.steuermann_levels = layout.levels;
  out.info.steuermann_boxes = layout.plan.boxes;
  out.mesh = solver::merge_bodies({block, indenter});
  return out;
}

/// Shortest block.contact side with both ends at x <= a (plus round-off).
double contact_element_size(const Mesh& mesh, double a) {
  double h = std::numeric_limits<double>::infinity();
  for (const auto& s : solver::edge_set(mesh, study_sets::kBlockContact)) {
    const auto n = mesh.side_nodes(s);
    const Eigen::Vector2d& p = mesh.nodes[n[0]];
    const Eigen::Vector2d& q = mesh.nodes[n[1]];
    if (std::max(p.x(), q.x()) <= a * (1 + 1e-12))
      h = std::min(h, (q - p).norm());
  }
  return h;
}

}  // namespace

int level_factor(MeshLevel level) {
  switch (level) {
    case MeshLevel::C:
      return 1;
    case MeshLevel::M:
      return 2;
    case MeshLevel::F:
      return 4;
    case MeshLevel::VF:
      return 8;
  }
  return 1;
}

int table1_elements(ProblemId problem, MeshLevel level) {
  if (level == MeshLevel::VF)
    return 0;  // beyond the study: Table 1 has no VF count
  const int f = level_factor(level);
  return layout_of(problem).table1_elements * f * f;
}

int steuermann_target_elements(double re_over_b, MeshLevel level) {
  if (!(re_over_b > 0.0) || !std::isfinite(re_over_b)) {
    throw SuiteInputError(
        fmt::format("steuermann_target_elements: r_e/b = {} (must be > 0)", re_over_b));
  }
  // Table 1 at C, ordered by r_e/b.
  const double ratio[3] = {1.0 / 7.0, 1.0 / 3.0, 1.0};
  const double count[3] = {16809, 16222, 8372};
  const int f = level_factor(level);
  constexpr double kSame = 1e-9;
  double c = 0.0;
  if (re_over_b <= ratio[0] * (1 + kSame)) {
    c = count[0];
  } else if (re_over_b >= ratio[2] * (1 - kSame)) {
    c = count[2];
  } else {
    const int i = re_over_b < ratio[1] ? 0 : 1;
    if (std::abs(re_over_b / ratio[i + 1] - 1.0) < kSame) {
      c = count[i + 1];
    } else {
      const double t = std::log(re_over_b / ratio[i]) / std::log(ratio[i + 1] / ratio[i]);
      c = count[i] + t * (count[i + 1] - count[i]);
    }
  }
  return static_cast<int>(std::lround(c)) * f * f;
}

StudyMesh build_study_mesh(const StudyMeshSpec& spec) {
  const MeshFamily family = layout_of(spec.problem).family;
  if (family == MeshFamily::own) {
    throw SuiteInputError(
        fmt::format("study mesh {}: the problem builds its own mesh (its layout is `own`)",
                    to_string(spec.problem)));
  }
  require_positive(spec.a, "a", spec.problem);
  require_extent(spec);
  const bool steuermann = family == MeshFamily::steuermann;
  StudyMesh out = steuermann ? build_steuermann(spec) : build_uniform(spec);
  out.info.n_nodes = out.mesh.n_nodes();
  out.info.table1_block_elements =
      steuermann ? (spec.options.steuermann_target_elements > 0
                        ? spec.options.steuermann_target_elements * level_factor(spec.level) *
                              level_factor(spec.level)
                        : steuermann_target_elements(spec.r_e / spec.b, spec.level))
                 : table1_elements(spec.problem, spec.level);
  out.info.h_contact = contact_element_size(out.mesh, spec.a);
  return out;
}

}  // namespace cs::suites
