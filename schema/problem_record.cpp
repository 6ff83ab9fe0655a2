#include "schema/problem_record.hpp"

namespace cs::schema {

const QuantityDefinition* ProblemRecord::definition(Quantity q) const {
  for (const auto& d : quantities) {
    if (d.quantity == q)
      return &d;
  }
  return nullptr;
}

}  // namespace cs::schema
