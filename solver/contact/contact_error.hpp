#pragma once
// The typed error of the contact module for bad input: an unknown contact surface or target,
// a target that never comes within the pinball, non-positive FKN / FTOLN / pinball, an
// unsupported combination of options.

#include <stdexcept>
#include <string>

namespace cs::solver {

/// Bad contact input. The message is one line naming the cause, e.g.
/// "contact: unknown contact surface 'block.tpo'" or
/// "contact: FKN = -1 (the penalty factor must be positive and finite)".
/// A contact analysis that runs but does not converge is not an error: it returns a status
/// (see solver/contact/contact_result.hpp).
class ContactError : public std::invalid_argument {
 public:
  explicit ContactError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace cs::solver
