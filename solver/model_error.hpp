#pragma once
// The typed error of the solver for bad input: thrown when a model cannot be solved as given
// (bad material, inverted element, unknown or empty set, bad load or constraint).

#include <stdexcept>
#include <string>

namespace cs::solver {

/// Bad input to the FE solver. The message is one line that names the cause and the offending
/// entity (element index and body, set name, body name), e.g.
/// "element 12 of body 'block': det J = -0.25 <= 0 at a Gauss point (inverted or degenerate)".
class ModelError : public std::invalid_argument {
 public:
  explicit ModelError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace cs::solver
