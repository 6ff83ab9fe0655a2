#pragma once
// The typed error of the mesh layer: thrown for bad generator input and failed set lookups.

#include <stdexcept>
#include <string>

namespace cs::solver {

/// Bad input to a mesh generator or mesh utility (non-positive size, unknown set, ...).
/// The message is one line naming the cause, e.g. "make_block: nx = 0 (must be >= 1)".
class MeshError : public std::invalid_argument {
 public:
  explicit MeshError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace cs::solver
