#include "solver/mesh/nested_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <fmt/format.h>

#include "solver/mesh/mesh_sets.hpp"

namespace cs::solver {
namespace {

/// A box of cells [i0, i1) x [k0, k1) in the cell indices of one level.
struct IndexBox {
  int i0 = 0, i1 = 0, k0 = 0, k1 = 0;
  int n_cells() const { return (i1 - i0) * (k1 - k0); }
  bool contains(int i, int k) const { return i >= i0 && i < i1 && k >= k0 && k < k1; }
};

/// Which side of an unrefined cell faces the finer box next to it (none, or the split side).
enum class Split { None, ZMin, XMax, ZMax, XMin };

Split split_side(const IndexBox& finer, int i, int k) {
  const bool in_rows = k >= finer.k0 && k < finer.k1;
  const bool in_cols = i >= finer.i0 && i < finer.i1;
  if (in_rows && i == finer.i0 - 1)
    return Split::XMax;
  if (in_rows && i == finer.i1)
    return Split::XMin;
  if (in_cols && k == finer.k1)
    return Split::ZMin;
  if (in_cols && k == finer.k0 - 1)
    return Split::ZMax;
  return Split::None;
}

int pow3(int n) {
  int p = 1;
  for (int i = 0; i < n; ++i)
    p *= 3;
  return p;
}

void check_spec(const NestedRefinementSpec& s) {
  if (!(s.cell_size > 0.0) || !std::isfinite(s.cell_size)) {
    throw MeshError(fmt::format("nested refinement: cell_size = {} (must be > 0)", s.cell_size));
  }
  if (s.nx < 1 || s.nz < 1) {
    throw MeshError(
        fmt::format("nested refinement: nx = {}, nz = {} (both must be >= 1)", s.nx, s.nz));
  }
  if (s.surface_strip_cells < 0 || (s.surface_strip_cells > 0 && s.levels < 1)) {
    throw MeshError(fmt::format(
        "nested refinement: surface_strip_cells = {} with levels = {} (a strip needs a level)",
        s.surface_strip_cells, s.levels));
  }
  if (s.levels < 0 || s.levels > kMaxRefinementLevels) {
    throw MeshError(fmt::format("nested refinement: levels = {} (must be 0..{})", s.levels,
                                kMaxRefinementLevels));
  }
  if (!(s.box_padding >= 0.0) || !(s.box_depth > 0.0)) {
    throw MeshError(
        fmt::format("nested refinement: box_padding = {}, box_depth = {} (must be >= 0 and > 0)",
                    s.box_padding, s.box_depth));
  }
  const double lo = s.refine_x_min - s.origin.x();
  const double hi = s.refine_x_max - s.origin.x();
  if (!(lo >= 0.0 && hi >= lo && hi <= s.nx * s.cell_size)) {
    throw MeshError(fmt::format(
        "nested refinement: refined segment [{}, {}] is empty or outside [{}, {}]", s.refine_x_min,
        s.refine_x_max, s.origin.x(), s.origin.x() + s.nx * s.cell_size));
  }
}

/// The index boxes of levels 0..levels (box 0: the whole background grid).
std::vector<IndexBox> index_boxes(const NestedRefinementSpec& s) {
  std::vector<IndexBox> boxes = {{0, s.nx, 0, s.nz}};
  const double lo = s.refine_x_min - s.origin.x();
  const double hi = s.refine_x_max - s.origin.x();
  for (int l = 1; l <= s.levels; ++l) {
    const IndexBox& parent = boxes.back();    // level l-1 cells
    const int n_across = s.nx * pow3(l - 1);  // level l-1 cells across the rectangle
    const int n_down = s.nz * pow3(l - 1);
    const double h = s.cell_size / pow3(l - 1);
    IndexBox box;
    if (l == 1 && s.surface_strip_cells > 0) {  // the whole surface strip
      box = {0, s.nx, 0, s.surface_strip_cells};
    } else {
      box.i0 = static_cast<int>(std::floor(lo / h - s.box_padding + 1e-9));
      box.i1 = static_cast<int>(std::ceil(hi / h + s.box_padding - 1e-9));
      box.k0 = 0;
      box.k1 = static_cast<int>(std::ceil(s.box_depth - 1e-9));
    }
    // Stay one cell inside the parent box wherever its side is inside the rectangle.
    box.i0 = std::max(box.i0, parent.i0 + (parent.i0 > 0 ? 1 : 0));
    box.i1 = std::min(box.i1, parent.i1 - (parent.i1 < n_across ? 1 : 0));
    box.k1 = std::min(box.k1, parent.k1 - (parent.k1 < n_down ? 1 : 0));
    if (box.i1 <= box.i0 || box.k1 <= box.k0) {
      throw MeshError(fmt::format(
          "nested refinement: the level-{} box vanishes inside its parent (too many levels for "
          "box_padding = {}, box_depth = {})",
          l, s.box_padding, s.box_depth));
    }
    boxes.push_back({3 * box.i0, 3 * box.i1, 3 * box.k0, 3 * box.k1});
  }
  return boxes;
}

/// The box of level l+1 expressed in level-l cell indices.
IndexBox coarsened(const IndexBox& b) {
  return {b.i0 / 3, b.i1 / 3, b.k0 / 3, b.k1 / 3};
}

}  // namespace

NestedRefinementLayout plan_nested_refinement(const NestedRefinementSpec& spec) {
  check_spec(spec);
  const auto boxes = index_boxes(spec);
  NestedRefinementLayout layout;
  layout.finest_size = spec.cell_size / pow3(spec.levels);
  for (int l = 0; l <= spec.levels; ++l) {
    const IndexBox& box = boxes[l];
    const double h = spec.cell_size / pow3(l);
    RefinementBox out;
    out.level = l;
    out.cell_size = h;
    out.x_min = spec.origin.x() + box.i0 * h;
    out.x_max = spec.origin.x() + box.i1 * h;
    out.z_min = spec.origin.y() + box.k0 * h;
    out.z_max = spec.origin.y() + box.k1 * h;
    out.n_cells = box.n_cells();
    layout.boxes.push_back(out);
    if (l == spec.levels) {
      layout.n_elements += box.n_cells();
      continue;
    }
    const IndexBox finer = coarsened(boxes[l + 1]);
    int transitions = 0;
    if (finer.i0 > box.i0)
      transitions += finer.k1 - finer.k0;
    if (finer.i1 < box.i1)
      transitions += finer.k1 - finer.k0;
    if (finer.k1 < box.k1)
      transitions += finer.i1 - finer.i0;
    if (finer.k0 > box.k0)
      transitions += finer.i1 - finer.i0;
    layout.n_transition_cells += transitions;
    layout.n_elements += box.n_cells() - finer.n_cells() + 3 * transitions;
  }
  return layout;
}

namespace {

/// Builds nodes on the lattice (spacing H0 / (2 3^levels)) and elements cell by cell.
class LatticeMesher {
 public:
  LatticeMesher(const NestedRefinementSpec& spec, Mesh& mesh)
      : spec_(spec), mesh_(mesh), unit_(spec.cell_size / (2.0 * pow3(spec.levels))) {}

  int node(std::int64_t i, std::int64_t k) {
    const std::int64_t key = (k << 32) | i;
    const auto [it, inserted] = ids_.emplace(key, mesh_.n_nodes());
    if (inserted) {
      mesh_.nodes.emplace_back(spec_.origin.x() + i * unit_, spec_.origin.y() + k * unit_);
      lattice_.push_back({i, k});
    }
    return it->second;
  }

  void quad(std::array<int, 4> c) {
    std::array<int, 8> e;
    e.fill(-1);
    std::copy(c.begin(), c.end(), e.begin());
    mesh_.elements.push_back(e);
  }

  /// A cell of size s (lattice units) with lower corner (i, k), split as `split` says.
  void cell(std::int64_t i, std::int64_t k, std::int64_t s, Split split) {
    if (split == Split::None) {
      quad({node(i, k), node(i + s, k), node(i + s, k + s), node(i, k + s)});
      return;
    }
    // Template in local (u, v) with the split side at v = 0, rotated onto the cell.
    auto at = [&](std::int64_t u, std::int64_t v) {
      switch (split) {
        case Split::ZMin:
          return node(i + u, k + v);
        case Split::XMax:
          return node(i + s - v, k + u);
        case Split::ZMax:
          return node(i + s - u, k + s - v);
        default:
          return node(i + v, k + s - u);  // Split::XMin
      }
    };
    const std::int64_t t = s / 3;
    const std::int64_t m = s / 2;
    const int a0 = at(0, 0), a1 = at(t, 0), a2 = at(2 * t, 0), a3 = at(s, 0);
    const int t0 = at(0, s), t1 = at(s, s), i1 = at(t, m), i2 = at(2 * t, m);
    quad({a0, a1, i1, t0});
    quad({a1, a2, i2, i1});
    quad({a2, a3, t1, i2});
    quad({i1, i2, t1, t0});
  }

  const std::vector<std::array<std::int64_t, 2>>& lattice() const { return lattice_; }
  double unit() const { return unit_; }

 private:
  const NestedRefinementSpec& spec_;
  Mesh& mesh_;
  double unit_;
  std::unordered_map<std::int64_t, int> ids_;
  std::vector<std::array<std::int64_t, 2>> lattice_;
};

/// The piecewise-linear map of x that moves finest-level node lines onto the snap targets. Works
/// on lattice coordinates, so that the moved lines land on their targets exactly.
void snap_columns(const NestedRefinementSpec& spec, const IndexBox& finest_box,
                  const std::vector<std::array<std::int64_t, 2>>& lattice, double unit,
                  Mesh& mesh) {
  const std::int64_t step = 2;  // finest cell size in lattice units
  const std::int64_t lo = finest_box.i0 * step;
  const std::int64_t hi = finest_box.i1 * step;
  auto x_of = [&](std::int64_t i) { return spec.origin.x() + i * unit; };
  std::vector<std::pair<std::int64_t, double>> knots = {{lo, x_of(lo)}};
  std::vector<double> targets = spec.snap_x;
  std::sort(targets.begin(), targets.end());
  for (double target : targets) {
    if (!(target > x_of(lo) && target < x_of(hi)))
      continue;
    const std::int64_t line =
        lo + step * static_cast<std::int64_t>(std::llround((target - x_of(lo)) / (step * unit)));
    if (line <= knots.back().first || line >= hi)
      continue;
    const double stretch = (target - knots.back().second) / (x_of(line) - x_of(knots.back().first));
    const double stretch_after = (x_of(hi) - target) / (x_of(hi) - x_of(line));
    if (stretch < 0.5 || stretch > 2.0 || stretch_after < 0.5 || stretch_after > 2.0)
      continue;
    knots.emplace_back(line, target);
  }
  if (knots.size() == 1)
    return;
  knots.emplace_back(hi, x_of(hi));
  for (std::size_t n = 0; n < lattice.size(); ++n) {
    const std::int64_t i = lattice[n][0];
    if (i <= lo || i >= hi)
      continue;
    std::size_t j = 1;
    while (i > knots[j].first)
      ++j;
    const auto& [i0, x0] = knots[j - 1];
    const auto& [i1, x1] = knots[j];
    mesh.nodes[n].x() =
        i == i1 ? x1 : x0 + static_cast<double>(i - i0) / static_cast<double>(i1 - i0) * (x1 - x0);
  }
}

}  // namespace

Mesh make_nested_refinement(const NestedRefinementSpec& spec) {
  const NestedRefinementLayout layout = plan_nested_refinement(spec);
  const auto boxes = index_boxes(spec);
  Mesh mesh;
  mesh.type = ElementType::Q4;
  mesh.body_names = {spec.body_name};
  mesh.elements.reserve(layout.n_elements);
  LatticeMesher mesher(spec, mesh);
  for (int l = 0; l <= spec.levels; ++l) {
    const IndexBox& box = boxes[l];
    const std::int64_t s = 2 * pow3(spec.levels - l);  // cell size in lattice units
    const bool finest = l == spec.levels;
    const IndexBox finer = finest ? IndexBox{} : coarsened(boxes[l + 1]);
    for (int k = box.k0; k < box.k1; ++k) {
      for (int i = box.i0; i < box.i1; ++i) {
        if (!finest && finer.contains(i, k))
          continue;
        mesher.cell(i * s, k * s, s, finest ? Split::None : split_side(finer, i, k));
      }
    }
  }
  mesh.element_body.assign(mesh.elements.size(), 0);

  // Boundary sides from lattice coordinates: both corners on the same rectangle edge.
  const auto& lat = mesher.lattice();
  const std::int64_t i_max = static_cast<std::int64_t>(spec.nx) * 2 * pow3(spec.levels);
  const std::int64_t k_max = static_cast<std::int64_t>(spec.nz) * 2 * pow3(spec.levels);
  for (const char* name : {"left", "right", "bottom", "top"})
    mesh.edge_sets[name];
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int side = 0; side < 4; ++side) {
      const auto& p = lat[mesh.elements[e][side]];
      const auto& q = lat[mesh.elements[e][(side + 1) % 4]];
      if (p[0] == 0 && q[0] == 0)
        mesh.edge_sets["left"].push_back({e, side});
      if (p[0] == i_max && q[0] == i_max)
        mesh.edge_sets["right"].push_back({e, side});
      if (p[1] == 0 && q[1] == 0)
        mesh.edge_sets["bottom"].push_back({e, side});
      if (p[1] == k_max && q[1] == k_max)
        mesh.edge_sets["top"].push_back({e, side});
    }
  }
  // Exact far coordinates, then the snap map, before sorting the sets.
  for (std::size_t n = 0; n < lat.size(); ++n) {
    if (lat[n][0] == i_max)
      mesh.nodes[n].x() = spec.origin.x() + spec.nx * spec.cell_size;
    if (lat[n][1] == k_max)
      mesh.nodes[n].y() = spec.origin.y() + spec.nz * spec.cell_size;
  }
  snap_columns(spec, boxes.back(), lat, mesher.unit(), mesh);
  for (auto& [name, sides] : mesh.edge_sets) {
    sort_edge_set(mesh, sides);
    mesh.node_sets[name];
  }
  rebuild_edge_node_sets(mesh);
  return mesh;
}

}  // namespace cs::solver
