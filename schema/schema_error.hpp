#pragma once
// The error of the schema layer: an unknown name, or a results or baseline file that is not
// what the schema says. Always input (exit code 2), never a bug.

#include <stdexcept>
#include <string>

namespace cs::schema {

class SchemaError : public std::runtime_error {
 public:
  explicit SchemaError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace cs::schema
