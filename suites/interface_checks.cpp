#include "suites/interface_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "solver/contact/gap_normal.hpp"
#include "solver/dof_map.hpp"
#include "solver/internal_forces.hpp"
#include "solver/load_vector.hpp"
#include "solver/surface_path.hpp"

namespace cs::suites {
namespace {

/// A node lies outside the exact patch when it meets the target more than one element beyond
/// the exact contact half-width: the discrete edge of contact cannot be placed finer than an
/// element.
bool outside_patch(const ProblemSetup& setup, double x, double h) {
  return x > setup.contact_half_width_a + h * (1.0 + 1e-9);
}

/// Where node `n` meets the target, along the surface. A gap measured along the target's normal
/// (our default, and every other code's contact) sees the block's displacement along its surface
/// wherever the target is inclined to it: the node meets the target at its reference x plus
/// u_x. A gap linearized along the block's normal (`half_space_gap`, as the exact solutions
/// are) meets it at the reference x. On the rounded punch the two differ by the surface's inward
/// displacement at the edge, (1 - 2 nu)(1 + nu) P / (2 E) on a half-plane: 9 % of a - b on
/// S(1/3) at p/E = 1e-3, a few F elements.
double meeting_x(const solver::ContactNodeResult& n, const Eigen::VectorXd& u,
                 solver::GapNormal gap_normal) {
  const bool moves = gap_normal == solver::GapNormal::Target && u.size() > 2 * n.node;
  return n.position.x() + (moves ? u[2 * n.node] : 0.0);
}

schema::InterfaceChecks checks_of(const ProblemSetup& setup, const solver::ContactResult& contact,
                                  double applied_load, const Eigen::VectorXd& u,
                                  solver::GapNormal gap_normal) {
  schema::InterfaceChecks checks;
  if (contact.nodes.empty() || !(setup.p > 0.0))
    return checks;
  if (applied_load > 0.0 && std::isfinite(applied_load))
    checks.force_balance = (contact.total_normal_force - applied_load) / applied_load;
  const double h = setup.mesh_info.h_contact;
  double outside = 0.0, penetration = 0.0;
  for (const auto& n : contact.nodes) {
    penetration = std::max(penetration, n.penetration);
    if (outside_patch(setup, meeting_x(n, u, gap_normal), h))
      outside = std::max(outside, n.pressure);
  }
  checks.max_tensile_over_p = contact.max_tension / setup.p;
  checks.max_outside_over_p = outside / setup.p;
  if (h > 0.0)
    checks.max_penetration_over_h = penetration / h;
  return checks;
}

/// Each surface node's contact pressure from the nodal contact forces F (compressive positive)
/// of a code that writes none: the traction's mean against a weight w >= 0 whose nodal forces
/// are known, so that a traction that never pulls reads >= 0 at every node:
///   Q4 side: w = the node's hat N_a:            p_a = sum F_a / sum L/2 over its sides;
///   Q8 side: the mid-side node, w = 1 - xi^2:   p_m = F_m / (2 L / 3);
///            a corner, w = its linear hat, N_c + N_m / 2 on each side at it:
///                                               p_c = (F_c + sum F_m / 2) / sum L/2.
/// A Q8 corner's own force over its lumped share (Simpson's L/6) is no such mean: N_c is
/// negative over the far half of each side, so a traction gathered there (the edge of a
/// contact patch) makes the corner's force pull though the traction never does.
std::map<int, double> pressures_of_forces(const solver::Mesh& mesh, const solver::SurfacePath& path,
                                          const std::map<int, double>& force) {
  std::map<int, double> pushed, length, out;
  const bool quadratic = solver::nodes_per_side(mesh.type) == 3;
  for (std::size_t k = 0; k < path.sides.size(); ++k) {
    const std::array<int, 3> nodes = mesh.side_nodes(path.sides[k]);
    const double L = path.side_length[k];
    const double mid = quadratic ? force.at(nodes[2]) : 0.0;
    for (int a = 0; a < 2; ++a) {
      pushed[nodes[a]] += 0.5 * mid;
      length[nodes[a]] += 0.5 * L;
    }
    if (quadratic)
      out[nodes[2]] = mid / (2.0 * L / 3.0);
  }
  for (const auto& [node, l] : length)
    out[node] = (force.at(node) + pushed[node]) / l;
  return out;
}

/// The outward unit normal of a side of the surface: its chord turned a quarter, pointing away
/// from its element's centroid. A side along x has exactly (0, +1) or (0, -1).
Eigen::Vector2d outward_normal(const solver::Mesh& mesh, const solver::ElementSide& side) {
  const auto& e = mesh.elements[side.element];
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int k = 0; k < 4; ++k)
    centroid += mesh.nodes[e[k]] / 4.0;
  const std::array<int, 3> ends = mesh.side_nodes(side);
  const Eigen::Vector2d chord = mesh.nodes[ends[1]] - mesh.nodes[ends[0]];
  Eigen::Vector2d n(chord.y(), -chord.x());
  n.normalize();
  const Eigen::Vector2d mid = 0.5 * (mesh.nodes[ends[0]] + mesh.nodes[ends[1]]);
  return n.dot(mid - centroid) > 0.0 ? n : Eigen::Vector2d(-n);
}

/// The outward unit normal at every node of the elements on the surface: a surface node's is the
/// mean of its sides' (a Q8 mid-side node's its side's), an inner node's that of its element's
/// side. On a flat surface every one is exactly the surface's; on an arc (IF) it is radial.
std::map<int, Eigen::Vector2d> layer_normals(const solver::Mesh& mesh,
                                             const solver::SurfacePath& path) {
  std::map<int, Eigen::Vector2d> surface, out;
  for (const auto& side : path.sides) {
    const Eigen::Vector2d n = outward_normal(mesh, side);
    const std::array<int, 3> nodes = mesh.side_nodes(side);
    for (int a = 0; a < solver::nodes_per_side(mesh.type); ++a) {
      surface.try_emplace(nodes[a], Eigen::Vector2d::Zero()).first->second += n;
    }
    const auto& e = mesh.elements[side.element];
    for (auto node = e.begin(); node != e.begin() + mesh.n_element_nodes(); ++node)
      out.try_emplace(*node, n);
  }
  for (auto& [node, n] : surface)
    out[node] = n.normalized();
  return out;
}

}  // namespace

double interface_load(const ProblemSetup& setup, const Eigen::VectorXd& f) {
  if (setup.load_control)
    return setup.load_control->target_load;
  if (!setup.load_steps.empty())
    return std::nan("");
  double z = 0.0;
  for (Eigen::Index i = 1; i < f.size(); i += 2)
    z += f[i];
  return std::abs(z);
}

solver::ContactResult interface_of_displacements(
    const ProblemSetup& setup, const Eigen::VectorXd& u,
    const std::vector<ContactPressureSample>& pressures) {
  const solver::Model& model = setup.model;
  const Eigen::VectorXd f = solver::assemble_load_vector(model, model.loads);
  Eigen::VectorXd residual = solver::internal_forces(model, u) - f;
  // A prescribed DOF's residual is its support's reaction, not a contact force (the arc of IF
  // ends on its symmetry lines, whose reactions carry the hoop force).
  const solver::DofMap dofs(model);
  for (Eigen::Index d = 0; d < residual.size(); ++d) {
    if (!dofs.is_free(static_cast<int>(d)))
      residual[d] = 0.0;
  }
  const solver::SurfacePath path = solver::surface_path(model.mesh, kSampledSurface);
  // Compression is positive: the interface pushes the block against its outward normal. The
  // direction is the geometry's, never the result's: an interface that pulls reads negative.
  const std::map<int, Eigen::Vector2d> normal = layer_normals(model.mesh, path);
  const auto compressive = [&](int n) {
    const Eigen::Vector2d& d = normal.at(n);
    return -(d.x() * residual[2 * n] + d.y() * residual[2 * n + 1]);
  };
  solver::ContactResult contact;
  std::map<int, double> force;
  for (std::size_t k = 0; k < path.nodes.size(); ++k) {
    solver::ContactNodeResult node;
    node.node = path.nodes[k];
    node.position = path.positions[k];
    node.force = force[node.node] = compressive(node.node);
    contact.nodes.push_back(node);
  }
  // The total over every node of the elements on the surface, not its nodes alone: a method
  // whose contact term acts through the boundary elements' stresses (Nitsche) leaves part of
  // the transmitted force at their inner nodes; for a Galerkin method those residuals are 0.
  for (const auto& [n, d] : normal)
    contact.total_normal_force += compressive(n);
  std::map<double, double> own;
  for (const auto& p : pressures)
    own[p.x] = p.pressure;
  const std::map<int, double> derived = pressures_of_forces(model.mesh, path, force);
  for (auto& node : contact.nodes) {
    const auto given = own.find(node.position.x());
    node.pressure =
        !pressures.empty() ? (given == own.end() ? 0.0 : given->second) : derived.at(node.node);
    contact.max_tension = std::max(contact.max_tension, -node.pressure);
  }
  return contact;
}

schema::InterfaceChecks check_interface_of_displacements(const ProblemSetup& setup,
                                                         const solver::ContactResult& interface,
                                                         const Eigen::VectorXd& u) {
  const Eigen::VectorXd f = solver::assemble_load_vector(setup.model, setup.model.loads);
  // Another code measures its gaps along the target's normal: `half_space_gap` is ours alone.
  schema::InterfaceChecks checks =
      checks_of(setup, interface, interface_load(setup, f), u, solver::GapNormal::Target);
  checks.max_penetration_over_h.reset();
  return checks;
}

schema::InterfaceChecks check_interface_of_displacements(
    const ProblemSetup& setup, const Eigen::VectorXd& u,
    const std::vector<ContactPressureSample>& pressures) {
  return check_interface_of_displacements(setup, interface_of_displacements(setup, u, pressures),
                                          u);
}

schema::InterfaceChecks check_interface(const ProblemSetup& setup,
                                        const solver::ContactResult& contact, double applied_load) {
  return checks_of(setup, contact, applied_load, contact.displacement, setup.pair.gap_normal);
}

}  // namespace cs::suites
