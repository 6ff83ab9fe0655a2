#pragma once
// The typed errors of the CalculiX adapter. Messages are one line and name the cause, e.g.
// "CalculiX: 'ccx' not found in PATH (install the Debian package calculix-ccx)" or
// "job.frd: line 57: block 'STRESS' declares 13 nodes but holds 12 (truncated file?)".
//
// They derive from std::invalid_argument so that the command line maps them to a usage error
// (exit 2), like every input error of the suite.

#include <stdexcept>
#include <string>

namespace cs::adapters::calculix {

/// Anything the adapter cannot do as asked: ccx missing, an option out of range, a model
/// feature CalculiX cannot take (see UnsupportedByCalculix), an output it cannot parse.
class CalculixError : public std::invalid_argument {
 public:
  explicit CalculixError(const std::string& what) : std::invalid_argument(what) {}
};

/// A combination of model and options that CalculiX (or this adapter) does not support, e.g. a
/// rigid analytic target or mortar contact on 2D elements.
class UnsupportedByCalculix : public CalculixError {
 public:
  explicit UnsupportedByCalculix(const std::string& what) : CalculixError(what) {}
};

/// A CalculiX output file (.frd, .12d) that cannot be parsed: malformed, truncated, binary.
class CalculixOutputError : public CalculixError {
 public:
  explicit CalculixOutputError(const std::string& what) : CalculixError(what) {}
};

}  // namespace cs::adapters::calculix
