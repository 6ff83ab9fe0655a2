#pragma once
// Detection of unrestrained rigid-body motions before factorizing: the structural cause of a
// singular stiffness matrix, told by body name.
//
// The zero-energy modes of a free 2D body are, in plane strain, the translations in x and z
// and the rotation about y; in axisymmetry only the translation in z (a radial translation
// strains the hoop direction). A group of bodies (bodies sharing nodes, or declared coupled,
// e.g. by a contact pair) moves rigidly unless its prescribed DOFs restrain each mode: the
// mode's values at the group's prescribed DOFs must be linearly independent.

#include <string>
#include <utility>
#include <vector>

#include "solver/dof_map.hpp"
#include "solver/model.hpp"

namespace cs::solver {

/// A group of bodies with at least one unrestrained rigid-body mode.
struct UnrestrainedBody {
  std::vector<int> bodies;              ///< body indices of the group
  std::string name;                     ///< "'block'" or "'indenter' + 'block'"
  std::vector<std::string> free_modes;  ///< e.g. "translation in x", "rotation"
};

/// The groups of bodies with unrestrained rigid-body modes (empty when every body is held).
/// Bodies sharing a node are one group; `coupled` adds pairs of body indices that the caller
/// couples otherwise (e.g. a contact pair). Also reports free DOFs of nodes that belong to no
/// element (as the pseudo-body "unattached nodes").
std::vector<UnrestrainedBody> find_unrestrained_bodies(
    const Model& model, const DofMap& dofs, const std::vector<std::pair<int, int>>& coupled = {});

/// One line: "body 'indenter' is not restrained against translation in z; ...".
std::string describe(const std::vector<UnrestrainedBody>& unrestrained);

}  // namespace cs::solver
