#include "adapters/calculix/result_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "adapters/calculix/calculix_error.hpp"
#include "adapters/calculix/input_deck.hpp"
#include "solver/mesh/mesh_sets.hpp"

namespace cs::adapters::calculix {
namespace {

using solver::Model;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Our node index of a deck node id, or a CalculixOutputError naming the block.
int our_node(const Model& model, int deck_id, std::string_view block) {
  const int node = deck_id - 1;
  if (node < 0 || node >= model.mesh.n_nodes())
    throw CalculixOutputError(
        fmt::format("CalculiX results: block '{}' names node {}, which the deck does not have",
                    block, deck_id));
  return node;
}

void check_nodes(const FrdNodes& nodes, const Model& model) {
  double extent = 0.0;
  for (const auto& x : model.mesh.nodes)
    extent = std::max({extent, std::abs(x.x()), std::abs(x.y())});
  const double tolerance = 1e-5 * extent + 1e-300;  // E12.5: 6 significant digits
  for (std::size_t k = 0; k < nodes.ids.size(); ++k) {
    const int node = our_node(model, nodes.ids[k], "nodes");
    const Eigen::Vector2d frd(nodes.coordinates[3 * k], nodes.coordinates[3 * k + 1]);
    if (!((frd - model.mesh.nodes[node]).lpNorm<Eigen::Infinity>() <= tolerance))  // NaN too
      throw CalculixOutputError(fmt::format(
          "CalculiX results: node {} is at ({}, {}) in the .frd but at ({}, {}) in the model",
          nodes.ids[k], frd.x(), frd.y(), model.mesh.nodes[node].x(), model.mesh.nodes[node].y()));
  }
}

const FrdResultBlock& required_block(const FrdFile& frd, std::string_view name,
                                     std::initializer_list<std::string_view> components) {
  const FrdResultBlock* block = frd.last_block(name);
  if (block == nullptr)
    throw CalculixOutputError(fmt::format("CalculiX results: no '{}' block in the .frd", name));
  for (std::string_view c : components) {
    const int k = block->component(c);
    if (k < 0)
      throw CalculixOutputError(
          fmt::format("CalculiX results: block '{}' has no component '{}'", name, c));
    for (int row = 0; row < block->n_nodes(); ++row) {
      if (!std::isfinite(block->value(row, k)))  // a diverged solve writes NaN as a value
        throw CalculixOutputError(
            fmt::format("CalculiX results: block '{}' gives node {} a {} that is not finite", name,
                        block->node_ids[row], c));
    }
  }
  return *block;
}

std::vector<solver::Stress> nodal_stress(const FrdFile& frd, const Model& model) {
  const auto& block = required_block(frd, "STRESS", {"SXX", "SYY", "SZZ", "SXY"});
  const int sxx = block.component("SXX"), syy = block.component("SYY");
  const int szz = block.component("SZZ"), sxy = block.component("SXY");
  std::vector<solver::Stress> out(model.mesh.n_nodes(), {kNaN, kNaN, kNaN, kNaN});
  for (int row = 0; row < block.n_nodes(); ++row) {
    const int node = our_node(model, block.node_ids[row], block.name);
    out[node] = {block.value(row, sxx), block.value(row, syy), block.value(row, sxy),
                 block.value(row, szz)};
  }
  return out;
}

/// The first two components of a vector block (DISP: D1, D2; FORC: F1, F2) per node, scaled.
std::vector<Eigen::Vector2d> nodal_vector(const FrdFile& frd, const Model& model,
                                          std::string_view name, std::string_view c1,
                                          std::string_view c2, double scale) {
  const auto& block = required_block(frd, name, {c1, c2});
  const int i1 = block.component(c1), i2 = block.component(c2);
  std::vector<Eigen::Vector2d> out(model.mesh.n_nodes(), Eigen::Vector2d(kNaN, kNaN));
  for (int row = 0; row < block.n_nodes(); ++row) {
    const int node = our_node(model, block.node_ids[row], block.name);
    out[node] = scale * Eigen::Vector2d(block.value(row, i1), block.value(row, i2));
  }
  return out;
}

std::vector<CalculixContactNode> contact_nodes(const FrdFile& frd, const ExpansionMap& expansion,
                                               const Model& model,
                                               const solver::ContactPair& pair) {
  const auto& sides = solver::resolve_edge_set(model.mesh, pair.contact_surface);
  std::vector<CalculixContactNode> out;
  std::vector<int> slot(model.mesh.n_nodes(), -1), copies;
  for (int node : solver::nodes_of_sides(model.mesh, sides)) {
    slot[node] = static_cast<int>(out.size());
    out.push_back({node, model.mesh.nodes[node], 0.0, 0.0, false});
  }
  copies.assign(out.size(), 0);
  const auto& block = required_block(frd, "CONTACT", {"COPEN", "CPRESS"});
  const int open = block.component("COPEN"), press = block.component("CPRESS");
  for (int row = 0; row < block.n_nodes(); ++row) {
    const int node = our_node(model, deck_node(expansion, block.node_ids[row]), block.name);
    const int k = slot[node];
    if (k < 0)
      continue;  // surface-to-surface output lists every node; only the slave's matter
    out[k].pressure += block.value(row, press);
    out[k].penetration -= block.value(row, open);
    out[k].reported = true;
    ++copies[k];
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (copies[k] > 1) {
      out[k].pressure /= copies[k];
      out[k].penetration /= copies[k];
    }
  }
  return out;
}

}  // namespace

void map_results(const FrdFile& frd, const ExpansionMap& expansion, const Model& model,
                 const solver::ContactPair& pair, CalculixResult& result) {
  check_nodes(frd.nodes, model);
  result.nodal_stress = nodal_stress(frd, model);
  result.displacement = nodal_vector(frd, model, "DISP", "D1", "D2", 1.0);
  result.reaction = nodal_vector(frd, model, "FORC", "F1", "F2", 1.0 / ccx_force_factor(model));
  result.contact = contact_nodes(frd, expansion, model, pair);
}

}  // namespace cs::adapters::calculix
